// corbel: the editor. GLFW window + Dear ImGui shell around the shared renderer.
#include "editor/app.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

namespace {

constexpr const char* kUsage = R"(corbel — interactive building modeler

usage: corbel [options] [PROJECT.corbel]

options:
  --size WxH              window size (default 1440x900)
  --screenshot OUT.png    save the window to a PNG after --quit-after-frames frames
  --quit-after-frames N   quit after N frames (for tests and scripted runs)
  --actions ID,ID,...     run these actions one per frame at start (see Help > Keyboard Shortcuts)
  --script FILE           run an edit script (JSON lines, one edit per frame; see docs/user-guide.md)
  --script-shots DIR      with --script: save a screenshot to DIR after each stage of the script
  --autosave-seconds S    autosave interval while there are unsaved changes (default 60)
  --recover ask|yes|no    what to do with unsaved work found from a crash (default ask)
  --state-dir DIR         where recovery and recent files live (default $XDG_STATE_HOME/corbel)
  --select NAME           select the object called NAME (its panel opens)
  --test-log FILE         write a JSON line per settled frame (selection, camera, last action)
  --frame-delay MS        sleep MS milliseconds in every frame, as a slow machine would (tests)
  --help
)";

void glfwError(int code, const char* text) { std::fprintf(stderr, "corbel: GLFW error %d: %s\n", code, text); }

}  // namespace

int main(int argc, char** argv) {
  corbel::editor::EditorOptions options;
  int width = 1440, height = 900;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "corbel: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--size") {
      if (std::sscanf(value().c_str(), "%dx%d", &width, &height) != 2 || width < 200 || height < 200 || width > 8192 ||
          height > 8192) {
        std::fprintf(stderr, "corbel: --size expects WxH between 200 and 8192\n");
        return 2;
      }
    } else if (a == "--screenshot") {
      options.screenshot = value();
    } else if (a == "--quit-after-frames") {
      options.quitAfterFrames = std::atoi(value().c_str());
      if (options.quitAfterFrames < 1) {
        std::fprintf(stderr, "corbel: --quit-after-frames expects a positive number\n");
        return 2;
      }
    } else if (a == "--actions") {
      std::stringstream ss(value());
      std::string id;
      while (std::getline(ss, id, ','))
        if (!id.empty()) options.actions.push_back(id);
    } else if (a == "--script") {
      options.script = value();
    } else if (a == "--script-shots") {
      options.scriptShots = value();
    } else if (a == "--autosave-seconds") {
      options.autosaveSeconds = std::atof(value().c_str());
    } else if (a == "--recover") {
      const std::string v = value();
      if (v == "yes")
        options.recover = corbel::editor::EditorOptions::Recover::Yes;
      else if (v == "no")
        options.recover = corbel::editor::EditorOptions::Recover::No;
      else if (v == "ask")
        options.recover = corbel::editor::EditorOptions::Recover::Ask;
      else {
        std::fprintf(stderr, "corbel: --recover expects ask, yes or no\n");
        return 2;
      }
    } else if (a == "--state-dir") {
      options.stateDir = value();
    } else if (a == "--select") {
      options.select = value();
    } else if (a == "--test-log") {
      options.testLog = value();
    } else if (a == "--frame-delay") {
      options.frameDelayMs = std::atoi(value().c_str());
      if (options.frameDelayMs < 0 || options.frameDelayMs > 10000) {
        std::fprintf(stderr, "corbel: --frame-delay expects milliseconds from 0 to 10000\n");
        return 2;
      }
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "corbel: unknown option %s (try --help)\n", a.c_str());
      return 2;
    } else if (options.project.empty()) {
      options.project = a;
    } else {
      std::fprintf(stderr, "corbel: one project at a time\n");
      return 2;
    }
  }
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
