#pragma once
// The window's side of the input queue (editor/input_queue.h): GLFW callbacks push events
// into it, and each frame's batch is handed to Dear ImGui. This takes the place of the input
// half of ImGui 1.86's GLFW backend, which writes key states straight into ImGui and so loses
// a tap that starts and ends between two frames.
#include "editor/input_queue.h"

struct GLFWwindow;
struct GLFWcursor;

namespace corbel::editor {

class GlfwInput {
 public:
  // Installs the window's input callbacks and ImGui's key map, clipboard and cursor support.
  // ImGui's context must exist; one GlfwInput per window.
  explicit GlfwInput(GLFWwindow* window);
  ~GlfwInput();
  GlfwInput(const GlfwInput&) = delete;
  GlfwInput& operator=(const GlfwInput&) = delete;

  InputQueue& queue() { return queue_; }
  // Starts ImGui's frame on the platform side (display size, time step, the cursor's shape)
  // and applies one batch of events to ImGui's input state.
  void newFrame(const InputBatch& batch);

 private:
  static GlfwInput* of(GLFWwindow* window);
  void push(InputEvent e);
  GLFWwindow* window_;
  InputQueue queue_;
  double lastTime_ = 0;
  GLFWcursor* cursors_[9] = {};
};

}  // namespace corbel::editor
