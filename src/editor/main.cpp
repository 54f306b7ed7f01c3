// corbel: the editor. GLFW window + Dear ImGui shell around the shared renderer.
#include "core/command_line.h"
#include "editor/app.h"
#include "editor/options.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>

namespace {

void glfwError(int code, const char* text) { std::fprintf(stderr, "corbel: GLFW error %d: %s\n", code, text); }

}  // namespace

int main(int argc, char** argv) {
  corbel::editor::EditorOptions options;
  CLI::App cli;
  corbel::editor::declareEditorOptions(cli, options);
  if (const int code = corbel::parseCommandLine(cli, argc, argv); code >= 0) return code;
  const int width = options.window.width, height = options.window.height;
  if (!options.screenshot.empty() && options.quitAfterFrames < 1) options.quitAfterFrames = 10;

  glfwSetErrorCallback(glfwError);
  if (!glfwInit()) {
    std::fprintf(stderr,
                 "corbel: cannot open a window (no display?). For headless pictures use: corbel-cli render PROJECT "
                 "--out PNG\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window = glfwCreateWindow(width, height, "corbel", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "corbel: cannot create an OpenGL 3.3 core window\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; no imgui.ini next to projects
  ImGui::StyleColorsDark();
  {
    // DejaVu Sans (fonts-dejavu-core) has the glyphs the panels use: Latin-1 (degree, ², ×),
    // Greek (α, θ, μ), dashes and ellipsis, super- and subscripts (f_n⁻), arrows and the math
    // operators (≤, ≥, √, ∞); ImGui's built-in font is ASCII only, and a glyph outside these
    // ranges shows as "?".
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2027, 0x2070,
                                     0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
    const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if (FILE* f = std::fopen(font, "rb")) {
      std::fclose(f);
      ImGui::GetIO().Fonts->AddFontFromFileTTF(font, 15.0f, nullptr, ranges);
    }
  }
  ImGui::GetStyle().WindowRounding = 0.0f;
  // The platform side of ImGui (input, display size, cursors) is the editor's own input queue
  // (editor/glfw_input.h), made by the App; the renderer side is ImGui's OpenGL 3 backend.
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int code = 0;
  try {
    corbel::editor::App app(window, options);
    code = app.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "corbel: %s\n", e.what());
    code = 1;
  }

  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return code;
}
