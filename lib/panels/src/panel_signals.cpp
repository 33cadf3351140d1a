// Signal curves under the 3D view: speed, acceleration and jerk against time (and any other
// channel), decimated per pixel column, with a cursor at the selected sample. Clicking a curve
// selects the sample there; the wheel zooms in time around the mouse.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "inspector_state.h"

namespace isurface::panels {

namespace {

void drawCurve(Inspector::State& s, const Curve& curve, const Trajectory& t, ImVec2 origin, ImVec2 size) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + size.x, origin.y + size.y);
  draw->AddRectFilled(origin, end, IM_COL32(24, 26, 30, 255));
  const int columns = std::max(1, static_cast<int>(size.x));
  const std::size_t first = s.curveFirst, last = std::max(s.curveLast, s.curveFirst + 1);
  const ui::Envelope envelope = curve.values.envelope(first, last, columns);
  const auto [lo, hi] = curve.values.range(first, last);
  const float span = (std::isfinite(lo) && std::isfinite(hi) && hi > lo) ? hi - lo : 1.0f;
  auto toY = [&](float v) { return end.y - 2 - (v - (std::isfinite(lo) ? lo : 0)) / span * (size.y - 4); };
  for (int c = 0; c < columns; ++c) {
    const float a = envelope.low[c], b = envelope.high[c];
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    const float px = origin.x + c + 0.5f;
    draw->AddLine(ImVec2(px, toY(b)), ImVec2(px, toY(a) + 1), IM_COL32(110, 200, 255, 255));
  }
  char label[160];
  std::snprintf(label, sizeof label, "%s [%s]  %.5g .. %.5g", curve.label.c_str(), curve.unit.c_str(), lo, hi);
  draw->AddText(ImVec2(origin.x + 4, origin.y + 2), IM_COL32(230, 230, 230, 255), label);
  const ui::Selection& sel = s.selection.current();
  if (sel.sample && *sel.sample >= first && *sel.sample < last) {
    const float px = origin.x + static_cast<float>(*sel.sample - first) / (last - first) * size.x;
    draw->AddLine(ImVec2(px, origin.y), ImVec2(px, end.y), IM_COL32(255, 210, 40, 255), 1.5f);
    std::snprintf(label, sizeof label, "%.5g at %.4f s", curve.values.value(*sel.sample), t.time[*sel.sample]);
    draw->AddText(ImVec2(std::min(px + 4, end.x - 150), end.y - 16), IM_COL32(255, 210, 40, 255), label);
  }
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton(curve.label.c_str(), size);
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered()) {
    const double column = io.MousePos.x - origin.x;
    if (ImGui::IsMouseClicked(0)) s.selection.selectSample(ui::sampleAtColumn(first, last, columns, column));
    if (io.MouseWheel != 0) {
      // Zoom in time around the mouse, within the samples.
      const double centre = first + column / columns * (last - first);
      const double factor = io.MouseWheel > 0 ? 0.8 : 1.25;
      double a = centre - (centre - first) * factor, b = centre + (last - centre) * factor;
      a = std::max(0.0, a);
      b = std::min(static_cast<double>(t.size()), b);
      if (b - a >= 16) s.curveFirst = static_cast<std::size_t>(a), s.curveLast = static_cast<std::size_t>(b);
    }
  }
}

}  // namespace

void drawSignalCurves(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("Signal curves", x, y, w, h);
  Document* doc = s.activeDocument();
  if (!doc || !doc->samples || doc->curves.empty()) {
    ImGui::TextDisabled("no samples");
    ImGui::End();
    return;
  }
  if (ImGui::Button("Whole time")) s.curveFirst = 0, s.curveLast = doc->samples->size();
  ImGui::SameLine();
  const ui::Selection& sel = s.selection.current();
  if (ImGui::Button("Around selection") && sel.sample) {
    const std::size_t half = 2000;
    s.curveFirst = *sel.sample > half ? *sel.sample - half : 0;
    s.curveLast = std::min(doc->samples->size(), *sel.sample + half);
  }
  ImGui::SameLine();
  ImGui::Text("samples %zu .. %zu", s.curveFirst, s.curveLast);
  if (doc->curves.size() > 3) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(160);
    std::vector<const char*> names;
    for (std::size_t k = 3; k < doc->curves.size(); ++k) names.push_back(doc->curves[k].label.c_str());
    s.extraCurve = std::clamp(s.extraCurve, 0, static_cast<int>(names.size()) - 1);
    ImGui::Combo("channel", &s.extraCurve, names.data(), static_cast<int>(names.size()));
  }
  const ImVec2 area = ImGui::GetContentRegionAvail();
  const int shown = doc->curves.size() > 3 ? 4 : 3;
  const float each = (area.y - 4 * (shown - 1)) / shown;
  ImVec2 origin = ImGui::GetCursorScreenPos();
  for (int k = 0; k < shown; ++k) {
    const Curve& curve = doc->curves[k < 3 ? k : 3 + s.extraCurve];
    drawCurve(s, curve, *doc->samples, origin, ImVec2(area.x, each));
    origin.y += each + 4;
  }
  ImGui::End();
}

}  // namespace isurface::panels
