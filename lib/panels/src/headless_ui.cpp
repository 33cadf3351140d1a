#include "isurface/panels/headless_ui.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "isurface/panels/ui_look.h"
#include "isurface/vis/osmesa_context.h"

namespace isurface::panels {

namespace {

constexpr int kNamedKeys = 300;  // io.KeysDown index of ImGuiKey_ 0

}  // namespace

HeadlessUi::HeadlessUi(int width, int height, app_model::Settings settings)
    : width_(width), height_(height), context_(std::make_unique<vis::OsMesaContext>(width, height)) {
  ImGui::CreateContext();
  panels::applyUiLook(panels::uiLook());
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 30.0f;
  // Named keys above the letters' ASCII codes, which shortcuts read directly.
  for (int k = 0; k < ImGuiKey_COUNT; ++k) io.KeyMap[k] = kNamedKeys + k;
  ImGui_ImplOpenGL3_Init("#version 150");
  vis::OsMesaContext* context = context_.get();
  panels::GlHooks hooks{[context] { context->makeCurrent(); }, [context] { return context->isCurrent(); }};
  inspector_ = std::make_unique<panels::Inspector>(hooks, std::move(settings));
}

HeadlessUi::~HeadlessUi() {
  inspector_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void HeadlessUi::mouse(float x, float y, bool leftDown) {
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(x, y);
  io.MouseDown[0] = leftDown;
}

void HeadlessUi::wheel(float steps) { ImGui::GetIO().MouseWheel += steps; }

void HeadlessUi::key(int imguiKey, bool down) { ImGui::GetIO().KeysDown[kNamedKeys + imguiKey] = down; }

void HeadlessUi::letter(char upperCase, bool down) { ImGui::GetIO().KeysDown[static_cast<unsigned char>(upperCase)] = down; }
void HeadlessUi::ctrl(bool down) { ImGui::GetIO().KeyCtrl = down; }
void HeadlessUi::shift(bool down) { ImGui::GetIO().KeyShift = down; }
void HeadlessUi::type(const std::string& text) { ImGui::GetIO().AddInputCharactersUTF8(text.c_str()); }

void HeadlessUi::frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  inspector_->frame();
  ImGui::Render();
  context_->clearFrame(0.08f, 0.08f, 0.1f);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  context_->finish();
}

std::vector<unsigned char> HeadlessUi::pixels() { return context_->readPixels(); }

}  // namespace isurface::panels
