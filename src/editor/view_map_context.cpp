#include "editor/view_map_context.h"

#include <GLFW/glfw3.h>

#include <cstdio>

namespace corbel::editor {

namespace {

// A hidden window's context, made current on whichever thread renders; what that thread had
// current before (none on a worker, the window's on the main thread) is put back after.
class HiddenWindowLease : public render::GlContextLease {
 public:
  explicit HiddenWindowLease(GLFWwindow* window) : window_(window) {}
  ~HiddenWindowLease() override { glfwDestroyWindow(window_); }
  HiddenWindowLease(const HiddenWindowLease&) = delete;
  HiddenWindowLease& operator=(const HiddenWindowLease&) = delete;
  void enter() override {
    previous_ = glfwGetCurrentContext();
    glfwMakeContextCurrent(window_);
  }
  void leave() override { glfwMakeContextCurrent(previous_); }

 private:
  GLFWwindow* window_;
  GLFWwindow* previous_ = nullptr;  // one lease at a time (ContextViewMapper's lock)
};

}  // namespace

std::shared_ptr<render::ContextViewMapper> makeEditorGlViewMapper(double pixelSize, std::string* why) {
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);  // ids are read back: no multisampling
  GLFWwindow* current = glfwGetCurrentContext();
  GLFWwindow* hidden = glfwCreateWindow(16, 16, "corbel view maps", nullptr, nullptr);
  glfwMakeContextCurrent(current);
  glfwDefaultWindowHints();
  if (!hidden) {
    if (why) *why = "GLFW could not make a hidden OpenGL 3.3 core context";
    return nullptr;
  }
  return std::make_shared<render::ContextViewMapper>(std::make_unique<HiddenWindowLease>(hidden), pixelSize);
}

std::string glMapsName(double pixelSize) {
  char text[48];
  std::snprintf(text, sizeof text, "GL, %.2g m pixels", pixelSize);
  return text;
}

}  // namespace corbel::editor
