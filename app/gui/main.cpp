// isurface: the interactive application. A GLFW window with Dear ImGui panels: open G-code
// programs, read them, simulate them in the background with progress, and inspect the program
// text. The 3D quality-map view joins these panels once the VTK layer exists.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "isurface/core/gcode_interpreter.h"
#include "isurface/core/path_segment.h"
#include "isurface/core/simulator.h"

namespace {

using namespace isurface;

// One open program and its background simulation.
struct Document {
  std::string path;
  std::vector<std::string> lines;
  Program program;
  std::vector<Diagnostic> errors;
  double pathLength = 0;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();

  std::atomic<double> progress{0};
  std::atomic<bool> running{false}, finished{false};
  std::mutex resultMutex;
  SimulationReport report;
  std::string simulationError;
  std::thread worker;

  ~Document() {
    if (worker.joinable()) worker.join();
  }
};

// Counts samples without keeping them: the window shows the simulation summary.
class CountingSink : public SampleSink {
 public:
  void consume(const SimSample*, std::size_t) override {}
};

std::unique_ptr<Document> openProgram(const std::string& path) {
  auto doc = std::make_unique<Document>();
  doc->path = path;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    doc->lines.push_back(line);
  }
  InterpretResult result = interpretGcodeFile(path);
  doc->errors = result.errors;
  doc->program = std::move(result.program);
  bool first = true;
  for (std::size_t i = 0; i < doc->program.moves.size(); ++i) {
    const Move& m = doc->program.moves[i];
    if (!m.isMotion()) continue;
    doc->pathLength += PathSegment::from(doc->program, i).length;
    doc->lower = first ? m.end : Vec3(doc->lower.cwiseMin(m.end));
    doc->upper = first ? m.end : Vec3(doc->upper.cwiseMax(m.end));
    first = false;
  }
  return doc;
}

void startSimulation(Document& doc) {
  if (doc.running) return;
  if (doc.worker.joinable()) doc.worker.join();
  doc.running = true;
  doc.finished = false;
  doc.progress = 0;
  doc.worker = std::thread([&doc] {
    CountingSink sink;
    try {
      const SimulationReport r = simulate(doc.program, defaultMachine(), sink, [&](double f) { doc.progress = f; });
      std::lock_guard<std::mutex> lock(doc.resultMutex);
      doc.report = r;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(doc.resultMutex);
      doc.simulationError = e.what();
    }
    doc.running = false;
    doc.finished = true;
  });
}

void drawDocument(Document& doc) {
  ImGui::Text("%s", doc.path.c_str());
  ImGui::Text("%zu lines, %zu moves, %.1f mm of path", doc.lines.size(), doc.program.moves.size(), doc.pathLength);
  ImGui::Text("bounds X %.3f..%.3f  Y %.3f..%.3f  Z %.3f..%.3f mm", doc.lower.x(), doc.upper.x(), doc.lower.y(),
              doc.upper.y(), doc.lower.z(), doc.upper.z());
  for (const Diagnostic& e : doc.errors) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", e.str().c_str());
  if (doc.running) {
    ImGui::ProgressBar(static_cast<float>(doc.progress.load()), ImVec2(-1, 0), "simulating");
  } else if (ImGui::Button("Simulate (S)") ||
             (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(GLFW_KEY_S))) {
    startSimulation(doc);
  }
  if (doc.finished) {
    std::lock_guard<std::mutex> lock(doc.resultMutex);
    if (doc.simulationError.empty())
      ImGui::Text("machining time %.3f s, %llu samples", doc.report.machiningTime,
                  static_cast<unsigned long long>(doc.report.samples));
    else
      ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", doc.simulationError.c_str());
  }
  ImGui::Separator();
  ImGui::BeginChild("gcode", ImVec2(0, 0), true);
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(doc.lines.size()));
  while (clipper.Step())
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i)
      ImGui::Text("%6d  %s", i + 1, doc.lines[i].c_str());
  ImGui::EndChild();
}

std::vector<std::unique_ptr<Document>>* droppedInto = nullptr;

void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count && droppedInto; ++i) droppedInto->push_back(openProgram(paths[i]));
}

}  // namespace

int main(int argc, char** argv) {
  glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
  if (!glfwInit()) {
    std::fprintf(stderr, "isurface: cannot open a window (no display?); use isurface-cli for headless work\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GL_TRUE);
  GLFWwindow* window = glfwCreateWindow(1280, 800, "iSurface", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "isurface: cannot create an OpenGL 3.2 window\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 150");

  std::vector<std::unique_ptr<Document>> documents;
  for (int i = 1; i < argc; ++i) documents.push_back(openProgram(argv[i]));
  droppedInto = &documents;
  glfwSetDropCallback(window, onDrop);
  static char pathInput[1024] = "";

  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->WorkPos);
    ImGui::SetNextWindowSize(viewport->WorkSize);
    ImGui::Begin("iSurface", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    ImGui::InputText("G-code file", pathInput, sizeof pathInput);
    ImGui::SameLine();
    if (ImGui::Button("Open (Enter)") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      if (pathInput[0]) documents.push_back(openProgram(pathInput));
    }
    if (ImGui::BeginTabBar("documents")) {
      for (auto& doc : documents) {
        if (ImGui::BeginTabItem(doc->path.c_str())) {
          drawDocument(*doc);
          ImGui::EndTabItem();
        }
      }
      ImGui::EndTabBar();
    }
    if (documents.empty()) ImGui::TextWrapped("Open a G-code file by name above, drop one onto the window, or name it on the command line.");
    ImGui::End();
    ImGui::Render();
    int width, height;
    glfwGetFramebufferSize(window, &width, &height);
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.12f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window);
  }
  droppedInto = nullptr;
  documents.clear();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return 0;
}
