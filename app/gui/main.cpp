// isurface: the interactive application. A GLFW window whose OpenGL context Dear ImGui and VTK
// share; the inspector draws every panel. Files named on the command line or dropped on the
// window are opened; settings and recent files are kept between runs.
#define GL_GLEXT_PROTOTYPES 1
#define GLFW_INCLUDE_GLEXT
#include <algorithm>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <set>
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

// Dear ImGui 1.86 sees a key as held or not at each frame: a press and its release that arrive
// in one batch of events (a quick tap, or a synthetic one) would never be seen. A release that
// comes after any press not yet seen by a frame is handed on only after that frame, and so
// are the releases after it (a quick Ctrl+L may let go of Ctrl before L, or in the batch after
// the one that held Ctrl down).
std::set<int> pressedSinceFrame;
std::vector<std::array<int, 4>> heldReleases;

// Dear ImGui 1.86 inserts a frame's typed characters before it acts on the frame's key presses:
// "out/exp.json" typed right after Ctrl+A, in one batch of events, had "ou" inserted and then
// selected and replaced by the next character. Characters that come after a shortcut (a key with
// Ctrl) not yet seen by a frame wait for the frame after it, and so do those after them.
bool shortcutSinceFrame = false;
std::vector<unsigned int> heldCharacters;

// When the last key, character, button or pointer move came: the loop draws on for a second
// after it (a tooltip shows once the pointer has rested a few frames).
double inputSeenAt = 0;

// Dear ImGui 1.86's GLFW backend reads the pointer each frame and installs no callback for it.
void onCursorMove(GLFWwindow*, double, double) { inputSeenAt = glfwGetTime(); }

void onChar(GLFWwindow* window, unsigned int character) {
  inputSeenAt = glfwGetTime();
  if (shortcutSinceFrame || !heldCharacters.empty()) {
    heldCharacters.push_back(character);
    return;
  }
  ImGui_ImplGlfw_CharCallback(window, character);
}

void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  inputSeenAt = glfwGetTime();
  if (action == GLFW_PRESS && (mods & GLFW_MOD_CONTROL) != 0) shortcutSinceFrame = true;
  if (action == GLFW_RELEASE && (!pressedSinceFrame.empty() || !heldReleases.empty())) {
    heldReleases.push_back({key, scancode, action, mods});
    return;
  }
  if (action == GLFW_PRESS) pressedSinceFrame.insert(key);
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  // Dear ImGui 1.86 takes the modifiers from the modifier keys it saw go down; a modifier that
  // reached the window under another key code (xdotool maps one to a spare code when the
  // keymap lacks it) still stands in the key's own modifier bits.
  if (action != GLFW_RELEASE) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = io.KeyCtrl || (mods & GLFW_MOD_CONTROL) != 0;
    io.KeyShift = io.KeyShift || (mods & GLFW_MOD_SHIFT) != 0;
    io.KeyAlt = io.KeyAlt || (mods & GLFW_MOD_ALT) != 0;
  }
}

// Dear ImGui 1.86 sees a mouse button as down or not at each frame, so the two clicks of a
// double click that arrive in one batch of events (a quick one while a frame took long) would
// be one click. A press after another not yet seen by a frame, or while the last frame saw the
// button down (its release came in this batch), waits: a frame sees the button up first, the
// next one the press, both where the pointer was at the press. GLFW's events carry no time:
// those two frames are given the time step of a quick frame, so that clicks that came in one
// batch count as a double click (within Dear ImGui's 6 px), as they would have on quick frames.
struct HeldPress {
  int button, mods;
  double x, y;  // the pointer, window pixels
};
std::array<int, 3> pressesSinceFrame{};
std::vector<HeldPress> heldPresses;
bool upFrame = false;                // the next frame shows the first held press's button up
std::optional<HeldPress> handedOn;   // the press the next frame shows
constexpr float kReplayFrameSeconds = 1.0f / 60;

void onMouseButton(GLFWwindow* window, int button, int action, int mods) {
  inputSeenAt = glfwGetTime();
  if (action == GLFW_PRESS && button >= 0 && button < 3 &&
      (pressesSinceFrame[button]++ > 0 || ImGui::GetIO().MouseDown[button] || !heldPresses.empty())) {
    HeldPress press{button, mods, 0, 0};
    glfwGetCursorPos(window, &press.x, &press.y);
    heldPresses.push_back(press);
    return;
  }
  ImGui_ImplGlfw_MouseButtonCallback(window, button, action, mods);
}

// After a frame: the next held press, after a frame that saw its button up. Returns whether
// there are any (another frame is due).
bool handOnHeldPress(GLFWwindow* window) {
  pressesSinceFrame.fill(0);
  handedOn.reset();
  if (heldPresses.empty()) return upFrame = false;
  if (!upFrame) return upFrame = true;
  upFrame = false;
  handedOn = heldPresses.front();
  heldPresses.erase(heldPresses.begin());
  pressesSinceFrame[handedOn->button] = 1;
  ImGui_ImplGlfw_MouseButtonCallback(window, handedOn->button, GLFW_PRESS, handedOn->mods);
  return true;
}

// Between the backend's new frame and Dear ImGui's: a frame replaying a held press sees what
// the press came after (the button up) or the press itself, at the press's place.
void replayHeldPress() {
  const HeldPress* press = upFrame && !heldPresses.empty() ? &heldPresses.front() : handedOn ? &*handedOn : nullptr;
  if (!press) return;
  ImGuiIO& io = ImGui::GetIO();
  if (upFrame) io.MouseDown[press->button] = false;
  io.MousePos = ImVec2(static_cast<float>(press->x), static_cast<float>(press->y));
  io.DeltaTime = std::min(io.DeltaTime, kReplayFrameSeconds);
}

// Whether Dear ImGui last saw a mouse button other than it now is: a press and its release in
// one batch of events (a quick click while a frame took long) are seen as a press in one
// frame, and the release needs a frame of its own, with no further input to wake the loop.
bool mouseFrameDue(GLFWwindow* window) {
  const ImGuiIO& io = ImGui::GetIO();
  for (int button = 0; button < 3; ++button)
    if (io.MouseDown[button] != (glfwGetMouseButton(window, button) == GLFW_PRESS)) return true;
  return false;
}

// After a frame: the releases and characters it waited for. Returns whether there were any (another
// frame is due).
bool releaseHeldKeys(GLFWwindow* window) {
  pressedSinceFrame.clear();
  shortcutSinceFrame = false;
  const bool any = !heldReleases.empty() || !heldCharacters.empty();
  for (const auto& r : heldReleases) ImGui_ImplGlfw_KeyCallback(window, r[0], r[1], r[2], r[3]);
  heldReleases.clear();
  for (const unsigned int c : heldCharacters) ImGui_ImplGlfw_CharCallback(window, c);
  heldCharacters.clear();
  return any;
}

// Waits for input. Nothing changes on screen without it (or work in the background), so an idle
// window sleeps; for a second after input it still draws ten frames a second, for what Dear
// ImGui shows after a pause (tooltips) and settles over a few frames.
void waitForInput(bool busy, bool frameDue, bool neverBlock, double& lastInput) {
  const double now = glfwGetTime();
  if (frameDue) glfwPollEvents();
  else if (busy) glfwWaitEventsTimeout(0.05), lastInput = now;  // its result settles after it
  else if (neverBlock || now - lastInput < 1.0) glfwWaitEventsTimeout(0.1);
  else {
    glfwWaitEvents();
    lastInput = glfwGetTime();
  }
}

// ISURFACE_STATE_FILE: the window's state (Inspector::describe) written there whenever it
// changes, replaced whole, for a script that drives the window to read.
void tellState(const isurface::panels::Inspector& inspector, std::string& told) {
  static const char* const path = std::getenv("ISURFACE_STATE_FILE");
  if (!path || !*path) return;
  std::string state = inspector.describe();
  if (state == told) return;
  const std::string temporary = std::string(path) + ".writing";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << state;
    if (!out) return;
  }
  if (std::rename(temporary.c_str(), path) == 0) told = std::move(state);
}

void setWindowIcon(GLFWwindow* window, const std::string& png) {
  if (png.empty()) return;
  GLFWimage icon;
  int channels = 0;
  icon.pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), static_cast<int>(png.size()),
                                      &icon.width, &icon.height, &channels, 4);
  if (!icon.pixels) return;
  glfwSetWindowIcon(window, 1, &icon);
  stbi_image_free(icon.pixels);
}

constexpr const char* kUsage = R"(Usage: isurface [FILE...]

iSurface: NC interpolation quality maps in a window. Opens the G-code programs, Biip dumps
(Biip.dat) and machine traces (LinuxCNC halsampler text, CSV) named, a dump or trace after its
program joining it; a program without a dump is simulated with the machine last applied to it
in the window's Machine window (the built-in 3-axis machining centre otherwise). Files may also be dropped on the window or
opened with File > Open (Ctrl+O).

In the window: click the surface to pick a sample (every panel follows: the G-code line, the
data bar, the inspector); click a G-code line to find it on the surface; drag to rotate, scroll
to zoom; P re-optimises a region, M edits the machine, H lists every key. Settings (window size,
theme, units, recent files) are kept in $XDG_CONFIG_HOME/isurface/settings.json.

Options:
  -h, --help               print this help and exit
  --version                print the version and exit
  --exit-after-frames N    quit by itself N frames after everything named has loaded

The headless jobs (render, simulate, analyze, optimize, ...) are isurface-cli's: see
isurface-cli(1).
)";

int run(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") return std::fputs(kUsage, stdout) >= 0 && std::fflush(stdout) == 0 ? 0 : 1;
    if (arg == "--version") return std::printf("isurface %s\n", ISURFACE_VERSION) > 0 && std::fflush(stdout) == 0 ? 0 : 1;
  }
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
  // No larger than the screen's work area (a size remembered from a larger screen, or the
  // default on a laptop's): a window beyond the screen hides its right and lower panels.
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int x = 0, y = 0, width = 0, height = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &width, &height);
    if (width > 0 && height > 0) {
      settings.windowWidth = std::min(settings.windowWidth, width);
      settings.windowHeight = std::min(settings.windowHeight, height);
    }
  }
  GLFWwindow* window = glfwCreateWindow(settings.windowWidth, settings.windowHeight, "iSurface", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "isurface: cannot create an OpenGL 3.2 window\n");
    glfwTerminate();
    return 1;
  }
  // Text as large on a dense screen as on a usual one, unless the user chose its size.
  if (!settings.uiScaleChosen) {
    float contentScale = 1, ignored = 1;
    glfwGetWindowContentScale(window, &contentScale, &ignored);
    int millimetres = 0, unusedHeight = 0;
    int pixels = 0;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
      glfwGetMonitorPhysicalSize(monitor, &millimetres, &unusedHeight);
      if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) pixels = mode->width;
    }
    settings.uiScale = isurface::app_model::uiScaleForScreen(pixels, millimetres, contentScale);
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  glfwSetDropCallback(window, onDrop);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  const isurface::panels::UiLook look = isurface::panels::uiLook();
  isurface::panels::applyUiLook(look);
  setWindowIcon(window, look.iconPng);
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; settings.json keeps the rest
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  glfwSetKeyCallback(window, onKey);  // in front of Dear ImGui's, which it calls
  glfwSetCharCallback(window, onChar);  // so too
  glfwSetMouseButtonCallback(window, onMouseButton);  // so too
  glfwSetCursorPosCallback(window, onCursorMove);
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
    // Settings are written as soon as they change (a window ended by a signal keeps its recent
    // files); the window's size, which changes every frame of a drag, when it closes.
    std::string savedSettings = isurface::app_model::settingsText(settings);
    auto keepSettings = [&](bool closing) {
      if (closing) glfwGetWindowSize(window, &settings.windowWidth, &settings.windowHeight);
      settings.recentFiles = inspector.settings().recentFiles;
      settings.quantity = inspector.settings().quantity;
      settings.colorMap = inspector.settings().colorMap;
      settings.theme = inspector.settings().theme;
      settings.uiScale = inspector.settings().uiScale;
      settings.units = inspector.settings().units;
      const std::string text = isurface::app_model::settingsText(settings);
      if (text == savedSettings) return;
      savedSettings = text;  // a folder that cannot be written is not tried again every frame
      isurface::app_model::saveSettings(settings);
    };
    double lastInput = glfwGetTime();
    bool frameDue = true;
    bool laidOut = false;  // a frame has been drawn
    std::string toldState;
    while (!glfwWindowShouldClose(window) && !inspector.quitRequested()) {
      if (exitAfter >= 0 && dropped.empty() && !inspector.busy() && exitAfter-- == 0) break;
      // Every input counts, not only the one that woke the loop: a click's result is drawn a
      // frame after it, and one that came late in the second after the last wake was left undrawn
      // until the pointer moved.
      lastInput = std::max(lastInput, inputSeenAt);
      waitForInput(inspector.busy() || inspector.refining(), frameDue || !dropped.empty(), exitAfter >= 0, lastInput);
      const double frameStart = glfwGetTime();
      // After a first frame: a map is made for the view's size, known once it has been laid out.
      if (!dropped.empty() && laidOut) {
        inspector.open(dropped);  // together: a dump after its program joins it
        dropped.clear();
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      replayHeldPress();
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
      const bool keysHeld = releaseHeldKeys(window), pressesHeld = handOnHeldPress(window);
      frameDue = keysHeld || pressesHeld || mouseFrameDue(window);
      tellState(inspector, toldState);
      keepSettings(false);
      laidOut = true;
      // A long frame (a picture exported, a file written) is followed by frames that show its
      // result, as input is.
      if (glfwGetTime() - frameStart > 0.2) lastInput = glfwGetTime();
    }
    keepSettings(true);
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
