// The 3D view panel: VTK's frame as an image, mouse input to the camera, click to pick,
// rectangle zoom.
#include <GL/gl.h>
#include <imgui.h>

#include <cmath>

#include "inspector_state.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

void drawSceneView(Inspector::State& s, float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("3D view", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const unsigned int texture = s.view.render(static_cast<int>(size.x), static_cast<int>(size.y));
  if (texture) {
    // VTK's frame is bottom-up: flip it. It is drawn without blending: where VTK blended
    // translucent glow its alpha is below one, and the panel behind must not show through.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture)), size, ImVec2(0, 1), ImVec2(1, 0));
    draw->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
  } else {
    ImGui::Dummy(size);
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 20, origin.y + 20));
    ImGui::TextDisabled("%s", s.job.running() ? "working..." : "no quality map yet: open a program or a dump");
  }
  const ImGuiIO& io = ImGui::GetIO();
  const double mx = io.MousePos.x - origin.x, my = io.MousePos.y - origin.y;
  const ImVec2 pressedAt(s.pressX, s.pressY);
  if (ImGui::IsWindowHovered() && texture) {
    for (int button = 0; button < 3; ++button) {
      if (ImGui::IsMouseClicked(button)) {
        s.pressX = io.MousePos.x;
        s.pressY = io.MousePos.y;
        s.pressedInView = true;
        if (!(s.rectangleZoom && button == 0)) s.view.mouseButton(button, true, mx, my);
      }
    }
    if (io.MouseWheel != 0) s.view.mouseWheel(io.MouseWheel, mx, my);
  }
  if (s.pressedInView && texture) {
    s.view.mouseMove(mx, my);
    if (s.rectangleZoom && ImGui::IsMouseDown(0))
      ImGui::GetWindowDrawList()->AddRect(pressedAt, io.MousePos, IM_COL32(255, 255, 255, 220), 0, 0, 1.5f);
    for (int button = 0; button < 3; ++button) {
      if (!ImGui::IsMouseReleased(button)) continue;
      const double moved = std::hypot(io.MousePos.x - pressedAt.x, io.MousePos.y - pressedAt.y);
      if (s.rectangleZoom && button == 0) {
        s.view.zoomToRectangle(pressedAt.x - origin.x, pressedAt.y - origin.y, mx, my);
        s.rectangleZoom = false;
      } else {
        s.view.mouseButton(button, false, mx, my);
      }
      // A click that did not drag picks the surface: the nearest sample becomes the selection.
      if (button == 0 && moved < 3 && !s.rectangleZoom) {
        if (const auto point = s.view.pick(mx, my)) s.selection.selectNearest(*point);
      }
      s.pressedInView = false;
    }
  } else if (ImGui::IsWindowHovered() && texture) {
    s.view.mouseMove(mx, my);
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace isurface::panels
