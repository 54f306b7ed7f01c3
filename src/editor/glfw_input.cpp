#include "editor/glfw_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cfloat>

namespace corbel::editor {

namespace {

const char* clipboardText(void* window) { return glfwGetClipboardString(static_cast<GLFWwindow*>(window)); }
void setClipboardText(void* window, const char* text) { glfwSetClipboardString(static_cast<GLFWwindow*>(window), text); }

}  // namespace

GlfwInput* GlfwInput::of(GLFWwindow* window) { return static_cast<GlfwInput*>(glfwGetWindowUserPointer(window)); }

void GlfwInput::push(InputEvent e) {
  e.time = glfwGetTime();
  queue_.push(e);
}

GlfwInput::GlfwInput(GLFWwindow* window) : window_(window) {
  glfwSetWindowUserPointer(window, this);
  using T = InputEvent::Type;
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (key == GLFW_KEY_UNKNOWN || action == GLFW_REPEAT) return;  // ImGui makes its own repeats
    of(w)->push({T::Key, key, action == GLFW_PRESS});
  });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned c) {
    InputEvent e{T::Char};
    e.codepoint = c;
    of(w)->push(e);
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    of(w)->push({T::Button, button, action == GLFW_PRESS});
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    InputEvent e{T::Move};
    e.x = x, e.y = y;
    of(w)->push(e);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double dx, double dy) {
    InputEvent e{T::Scroll};
    e.x = dx, e.y = dy;
    of(w)->push(e);
  });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) {
    if (!entered) of(w)->push({T::Leave});
  });
  glfwSetWindowFocusCallback(window, [](GLFWwindow*, int focused) { ImGui::GetIO().AddFocusEvent(focused != 0); });

  ImGuiIO& io = ImGui::GetIO();
  io.BackendPlatformName = "corbel_glfw_queue";
  io.BackendFlags |= ImGuiBackendFlags_HasMouseCursors;
  const int keys[][2] = {{ImGuiKey_Tab, GLFW_KEY_TAB},         {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
                         {ImGuiKey_RightArrow, GLFW_KEY_RIGHT}, {ImGuiKey_UpArrow, GLFW_KEY_UP},
                         {ImGuiKey_DownArrow, GLFW_KEY_DOWN},   {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
                         {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN}, {ImGuiKey_Home, GLFW_KEY_HOME},
                         {ImGuiKey_End, GLFW_KEY_END},         {ImGuiKey_Insert, GLFW_KEY_INSERT},
                         {ImGuiKey_Delete, GLFW_KEY_DELETE},   {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
                         {ImGuiKey_Space, GLFW_KEY_SPACE},     {ImGuiKey_Enter, GLFW_KEY_ENTER},
                         {ImGuiKey_Escape, GLFW_KEY_ESCAPE},   {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
                         {ImGuiKey_A, GLFW_KEY_A},             {ImGuiKey_C, GLFW_KEY_C},
                         {ImGuiKey_V, GLFW_KEY_V},             {ImGuiKey_X, GLFW_KEY_X},
                         {ImGuiKey_Y, GLFW_KEY_Y},             {ImGuiKey_Z, GLFW_KEY_Z}};
  for (const auto& [imgui, glfw] : keys) io.KeyMap[imgui] = glfw;
  io.GetClipboardTextFn = clipboardText;
  io.SetClipboardTextFn = setClipboardText;
  io.ClipboardUserData = window;
  const int shapes[] = {GLFW_ARROW_CURSOR,   GLFW_IBEAM_CURSOR,     GLFW_ARROW_CURSOR,
                        GLFW_VRESIZE_CURSOR, GLFW_HRESIZE_CURSOR,   GLFW_ARROW_CURSOR,
                        GLFW_ARROW_CURSOR,   GLFW_HAND_CURSOR,      GLFW_ARROW_CURSOR};
  static_assert(sizeof shapes / sizeof shapes[0] == ImGuiMouseCursor_COUNT);
  for (int i = 0; i < ImGuiMouseCursor_COUNT; ++i) cursors_[i] = glfwCreateStandardCursor(shapes[i]);
  lastTime_ = glfwGetTime();
}

GlfwInput::~GlfwInput() {
  glfwSetKeyCallback(window_, nullptr);
  glfwSetCharCallback(window_, nullptr);
  glfwSetMouseButtonCallback(window_, nullptr);
  glfwSetCursorPosCallback(window_, nullptr);
  glfwSetScrollCallback(window_, nullptr);
  glfwSetCursorEnterCallback(window_, nullptr);
  glfwSetWindowFocusCallback(window_, nullptr);
  glfwSetWindowUserPointer(window_, nullptr);
  for (GLFWcursor* c : cursors_)
    if (c) glfwDestroyCursor(c);
}

void GlfwInput::newFrame(const InputBatch& batch) {
  ImGuiIO& io = ImGui::GetIO();
  int w = 0, h = 0, fw = 0, fh = 0;
  glfwGetWindowSize(window_, &w, &h);
  glfwGetFramebufferSize(window_, &fw, &fh);
  io.DisplaySize = ImVec2(float(w), float(h));
  if (w > 0 && h > 0) io.DisplayFramebufferScale = ImVec2(float(fw) / float(w), float(fh) / float(h));
  const double now = glfwGetTime();
  io.DeltaTime = now > lastTime_ ? float(now - lastTime_) : 1.0f / 60.0f;
  lastTime_ = now;

  using T = InputEvent::Type;
  for (const InputEvent& e : batch.events) {
    switch (e.type) {
      case T::Key:
        if (e.code >= 0 && e.code < int(sizeof io.KeysDown / sizeof io.KeysDown[0])) io.KeysDown[e.code] = e.down;
        break;
      case T::Char:
        io.AddInputCharacter(e.codepoint);
        break;
      case T::Button:
        if (e.code >= 0 && e.code < int(sizeof io.MouseDown / sizeof io.MouseDown[0])) io.MouseDown[e.code] = e.down;
        break;
      case T::Move:
        io.MousePos = ImVec2(float(e.x), float(e.y));
        break;
      case T::Leave:
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        break;
      case T::Scroll:
        io.MouseWheelH += float(e.x);
        io.MouseWheel += float(e.y);
        break;
    }
  }
  io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = io.KeysDown[GLFW_KEY_LEFT_SUPER] || io.KeysDown[GLFW_KEY_RIGHT_SUPER];

  const ImGuiMouseCursor cursor = ImGui::GetMouseCursor();
  if (io.MouseDrawCursor || cursor == ImGuiMouseCursor_None) {
    glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);
  } else {
    glfwSetCursor(window_, cursors_[cursor] ? cursors_[cursor] : cursors_[ImGuiMouseCursor_Arrow]);
    glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
  }
}

}  // namespace corbel::editor
