// isurface: the interactive application. A GLFW window whose OpenGL context Dear ImGui and VTK
// share; the inspector draws every panel. Files named on the command line or dropped on the
// window are opened; settings and recent files are kept between runs.
#define GL_GLEXT_PROTOTYPES 1
#define GLFW_INCLUDE_GLEXT
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <stb/stb_image.h>

#include "isurface/panels/inspector.h"
#include "isurface/panels/ui_look.h"
#include "isurface/app_model/settings.h"

namespace {

std::vector<std::string> dropped;

void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i) dropped.emplace_back(paths[i]);
}

void setWindowIcon(GLFWwindow* window, const std::string& path) {
  if (path.empty()) return;
  GLFWimage icon;
  int channels = 0;
  icon.pixels = stbi_load(path.c_str(), &icon.width, &icon.height, &channels, 4);
  if (!icon.pixels) return;
  glfwSetWindowIcon(window, 1, &icon);
  stbi_image_free(icon.pixels);
}

int run(int argc, char** argv) {
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) {
    std::fprintf(stderr, "isurface: cannot open a window (no display?); isurface-cli does the headless work\n");
    return 1;
  }
  isurface::app_model::Settings settings = isurface::app_model::loadSettings();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GL_TRUE);
  GLFWwindow* window = glfwCreateWindow(settings.windowWidth, settings.windowHeight, "iSurface", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "isurface: cannot create an OpenGL 3.2 window\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  glfwSetDropCallback(window, onDrop);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  const isurface::panels::UiLook look = isurface::panels::uiLook();
  isurface::panels::applyUiLook(look);
  setWindowIcon(window, look.iconFile);
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; settings.json keeps the rest
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 150");
  {
    isurface::panels::GlHooks hooks{[window] { glfwMakeContextCurrent(window); },
                                    [window] { return glfwGetCurrentContext() == window; }};
    isurface::panels::Inspector inspector(hooks, settings);
    // --exit-after-frames N: quit by itself N frames after everything named has loaded (for
    // smoke tests of the real window).
    long exitAfter = -1;
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]) == "--exit-after-frames" && i + 1 < argc) exitAfter = std::atol(argv[++i]);
      else dropped.emplace_back(argv[i]);
    }
    while (!glfwWindowShouldClose(window) && !inspector.quitRequested()) {
      if (exitAfter >= 0 && dropped.empty() && !inspector.busy() && exitAfter-- == 0) break;
      // Idle frames wait for input; work in the background wakes the loop often enough.
      if (inspector.busy()) glfwWaitEventsTimeout(0.05);
      else glfwWaitEventsTimeout(0.25);
      if (!dropped.empty()) {
        inspector.open(dropped);  // together: a dump after its program joins it
        dropped.clear();
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      inspector.frame();
      ImGui::Render();
      glfwMakeContextCurrent(window);
      int width, height;
      glfwGetFramebufferSize(window, &width, &height);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, width, height);
      glClearColor(0.08f, 0.08f, 0.1f, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glfwSwapBuffers(window);
    }
    glfwGetWindowSize(window, &settings.windowWidth, &settings.windowHeight);
    settings.recentFiles = inspector.settings().recentFiles;
    settings.quantity = inspector.settings().quantity;
    settings.colorMap = inspector.settings().colorMap;
    isurface::app_model::saveSettings(settings);
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isurface: %s\n", e.what());
    return 1;
  }
}
