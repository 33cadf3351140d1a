// Signal curves under the 3D view: speed, acceleration and jerk against time (and any other
// channel), decimated per pixel column, with a cursor at the selected sample. Clicking a curve
// selects the sample there; the wheel zooms in time around the mouse.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <tuple>
#include <limits>

#include "inspector_state.h"

namespace isurface::panels {

namespace {

// The span a curve is drawn over: the 0.5-99.5 % percentiles of an even subsample of the shown
// samples, so that a few rapids at 20 m/min do not flatten the cutting speed into a line.
std::pair<float, float> displayRange(const app_model::SignalPyramid& values, std::size_t first, std::size_t last) {
  std::vector<float> picked;
  const std::size_t step = std::max<std::size_t>(1, (last - first) / 4096);
  for (std::size_t i = first; i < last; i += step)
    if (std::isfinite(values.value(i))) picked.push_back(values.value(i));
  if (picked.size() < 8) return values.range(first, last);
  auto rank = [&](double fraction) {
    const std::size_t k = static_cast<std::size_t>(fraction * (picked.size() - 1));
    std::nth_element(picked.begin(), picked.begin() + k, picked.end());
    return picked[k];
  };
  const float lo = rank(0.005), hi = rank(0.995);
  return hi > lo ? std::make_pair(lo, hi) : values.range(first, last);
}

// Round values 1, 2 or 5 times a power of ten apart, about `count` of them over [lo, hi].
std::vector<double> niceTicks(double lo, double hi, int count) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || count < 1) return ticks;
  const double raw = (hi - lo) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = power * (raw / power < 1.5 ? 1 : raw / power < 3.5 ? 2 : raw / power < 7.5 ? 5 : 10);
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9 && ticks.size() < 50; v += step)
    ticks.push_back(std::fabs(v) < step * 1e-9 ? 0.0 : v);
  return ticks;
}

// Seconds under the last curve, ticked at round times across the shown samples.
void drawTimeAxis(const Trajectory& t, std::size_t first, std::size_t last, ImVec2 origin, float width) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (last <= first + 1 || last > t.size()) return;
  const double t0 = t.timeAt(first), t1 = t.timeAt(last - 1);
  for (double tick : niceTicks(t0, t1, std::max(2, static_cast<int>(width / 90)))) {
    const float px = origin.x + static_cast<float>((tick - t0) / (t1 - t0)) * width;
    draw->AddLine(ImVec2(px, origin.y), ImVec2(px, origin.y + 4), IM_COL32(200, 200, 200, 255));
    char label[32];
    std::snprintf(label, sizeof label, "%g s", tick);
    const float w = ImGui::CalcTextSize(label).x;
    draw->AddText(ImVec2(std::clamp(px - w / 2, origin.x, origin.x + width - w), origin.y + 4), IM_COL32(200, 200, 200, 255),
                  label);
  }
}

const Curve::Shown& shownPart(Curve& curve, std::size_t first, std::size_t last, int columns) {
  if (!curve.shown || curve.shown->first != first || curve.shown->last != last || curve.shown->columns != columns)
    curve.shown = Curve::Shown{first, last, columns, curve.values.envelope(first, last, columns),
                               displayRange(curve.values, first, last)};
  return *curve.shown;
}

// Text over the curve on a patch of the plot's own background, so that the trace does not run
// through it.
void textOnBacking(ImDrawList* draw, ImVec2 at, ImU32 colour, const char* text) {
  const ImVec2 extent = ImGui::CalcTextSize(text);
  draw->AddRectFilled(ImVec2(at.x - 2, at.y), ImVec2(at.x + extent.x + 2, at.y + extent.y), IM_COL32(24, 26, 30, 210));
  draw->AddText(at, colour, text);
}

// The second run's curve over the first's, on the first's time axis (each from its own start):
// per pixel column, the second run's samples in the column's time, their lowest to highest. Kept
// in the overlay's `shown` for the first run's span and width: reading a derived quantity at
// every column's ends costs milliseconds, too much for every frame of a camera drag.
const app_model::Envelope& overlayEnvelope(Curve& overlay, const Trajectory& b, const Trajectory& a, std::size_t first,
                                           std::size_t last, int columns) {
  if (overlay.shown && overlay.shown->first == first && overlay.shown->last == last && overlay.shown->columns == columns)
    return overlay.shown->envelope;
  app_model::Envelope envelope;
  envelope.low.assign(static_cast<std::size_t>(columns), std::numeric_limits<float>::quiet_NaN());
  envelope.high = envelope.low;
  const double a0 = a.timeAt(0), bEnd = b.timeAt(b.size() - 1) - b.timeAt(0);
  const auto timeOfColumn = [&](int c) {
    const std::size_t i = first + static_cast<std::size_t>(double(c) / columns * double(last - first));
    return a.timeAt(std::min(i, a.size() - 1)) - a0;
  };
  for (int c = 0; c < columns; ++c) {
    const double from = timeOfColumn(c), to = timeOfColumn(c + 1);
    if (from > bEnd) break;
    const std::size_t i = app_model::sampleAtTime(b, from), j = app_model::sampleAtTime(b, to) + 1;
    std::tie(envelope.low[std::size_t(c)], envelope.high[std::size_t(c)]) = overlay.values.range(i, std::min(j, b.size()));
  }
  overlay.shown = Curve::Shown{first, last, columns, std::move(envelope), {}};
  return overlay.shown->envelope;
}

void drawOverlay(Curve& overlay, const Trajectory& b, const Trajectory& a, std::size_t first, std::size_t last,
                 double scale, const std::function<float(float)>& toY, ImVec2 origin, ImVec2 end) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const int columns = std::max(1, static_cast<int>(end.x - origin.x));
  const app_model::Envelope& envelope = overlayEnvelope(overlay, b, a, first, last, columns);
  for (int c = 0; c < columns; ++c) {
    const float low = envelope.low[std::size_t(c)], high = envelope.high[std::size_t(c)];
    if (!std::isfinite(low) || !std::isfinite(high)) continue;
    const float px = origin.x + c + 0.5f;
    draw->AddLine(ImVec2(px, std::max(toY(float(high * scale)), origin.y)),
                  ImVec2(px, std::min(toY(float(low * scale)) + 1, end.y)), IM_COL32(255, 140, 60, 170));
  }
}

void drawCurve(Inspector::State& s, Curve& curve, double scale, const char* unit, const Trajectory& t,
               ImVec2 origin, ImVec2 size, RunComparisonView* second = nullptr) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + size.x, origin.y + size.y);
  draw->AddRectFilled(origin, end, IM_COL32(24, 26, 30, 255));
  const int columns = std::max(1, static_cast<int>(size.x));
  const std::size_t first = s.follow.curveFirst, last = std::max(s.follow.curveLast, s.follow.curveFirst + 1);
  const Curve::Shown& part = shownPart(curve, first, last, columns);
  const app_model::Envelope& envelope = part.envelope;
  const auto [storedLo, storedHi] = part.range;
  const float lo = static_cast<float>(storedLo * scale), hi = static_cast<float>(storedHi * scale);
  const float span = (std::isfinite(lo) && std::isfinite(hi) && hi > lo) ? hi - lo : 1.0f;
  auto toY = [&](float v) { return end.y - 2 - (v - (std::isfinite(lo) ? lo : 0)) / span * (size.y - 4); };
  draw->PushClipRect(origin, end, true);
  // Round values across, faint, with their numbers at the right edge (drawn over the curve).
  const std::vector<double> ticks = niceTicks(lo, hi, std::max(2, static_cast<int>(size.y / 22)));
  for (double tick : ticks) {
    const float py = toY(static_cast<float>(tick));
    draw->AddLine(ImVec2(origin.x, py), ImVec2(end.x, py), IM_COL32(70, 74, 82, 255));
  }
  for (int c = 0; c < columns; ++c) {
    const float a = static_cast<float>(envelope.low[c] * scale), b = static_cast<float>(envelope.high[c] * scale);
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    const float px = origin.x + c + 0.5f;
    draw->AddLine(ImVec2(px, std::max(toY(b), origin.y)), ImVec2(px, std::min(toY(a) + 1, end.y)),
                  IM_COL32(110, 200, 255, 255));
  }
  if (second && second->speed && second->samples && second->samples->size() > 0)
    drawOverlay(*second->speed, *second->samples, t, first, last, scale, toY, origin, end);
  char label[160];
  const float lineHeight = ImGui::GetTextLineHeight();
  std::vector<float> labelTops;  // of the tick labels drawn: one that would cover another is left out
  for (double tick : ticks) {
    const float py = toY(static_cast<float>(tick));
    // Above its line, or below it where that would leave the plot.
    const float top = py - lineHeight < origin.y ? py + 1 : py - lineHeight;
    if (std::any_of(labelTops.begin(), labelTops.end(), [&](float other) { return std::fabs(other - top) < lineHeight; }))
      continue;
    labelTops.push_back(top);
    std::snprintf(label, sizeof label, "%g", tick);
    textOnBacking(draw, ImVec2(end.x - ImGui::CalcTextSize(label).x - 3, top), IM_COL32(150, 155, 165, 255), label);
  }
  draw->PopClipRect();
  // Read to a millionth of what the plot spans: finer is the rounding of differencing.
  const double largest = std::max(std::fabs(double(lo)), std::fabs(double(hi)));
  const double resolution = std::isfinite(largest) ? 1e-6 * largest : 0.0;
  // The axis spans most of the shown stretch; the run's extremes beside it, so that neither is
  // taken for the other.
  if (!curve.wholeRun) curve.wholeRun = curve.values.range(0, curve.values.size());
  const float runLo = static_cast<float>(curve.wholeRun->first * scale), runHi = static_cast<float>(curve.wholeRun->second * scale);
  const std::string unitText = unit[0] != '\0' ? std::string(" [") + unit + "]" : std::string();
  std::snprintf(label, sizeof label, "%s%s  axis %s .. %s; run %s .. %s", curve.label.c_str(), unitText.c_str(),
                readableValue(lo, resolution).c_str(), readableValue(hi, resolution).c_str(),
                readableValue(runLo, resolution).c_str(), readableValue(runHi, resolution).c_str());
  textOnBacking(draw, ImVec2(origin.x + 4, origin.y + 2), IM_COL32(230, 230, 230, 255), label);
  if (second && second->speed) {
    const std::string name = "and " + std::filesystem::path(second->path).filename().string() + " (orange)";
    textOnBacking(draw, ImVec2(origin.x + 8 + ImGui::CalcTextSize(label).x, origin.y + 2), IM_COL32(255, 140, 60, 255),
                  name.c_str());
  }
  const app_model::Selection& sel = s.selection.current();
  if (sel.sample && *sel.sample >= first && *sel.sample < last) {
    const float px = origin.x + static_cast<float>(*sel.sample - first) / (last - first) * size.x;
    draw->AddLine(ImVec2(px, origin.y), ImVec2(px, end.y), IM_COL32(255, 210, 40, 255), 1.5f);
    std::snprintf(label, sizeof label, "%s at %.4f s", readableValue(curve.values.value(*sel.sample) * scale, resolution).c_str(),
                  t.timeAt(*sel.sample));
    textOnBacking(draw, ImVec2(std::min(px + 4, end.x - 150), end.y - 16), IM_COL32(255, 210, 40, 255), label);
  }
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton(curve.label.c_str(), size);
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered()) {
    const double column = io.MousePos.x - origin.x;
    if (ImGui::IsMouseClicked(0)) s.selection.selectSample(app_model::sampleAtColumn(first, last, columns, column));
    if (io.MouseWheel != 0) {
      // Zoom in time around the mouse, within the samples.
      const double centre = first + column / columns * (last - first);
      const double factor = io.MouseWheel > 0 ? 0.8 : 1.25;
      double a = centre - (centre - first) * factor, b = centre + (last - centre) * factor;
      a = std::max(0.0, a);
      b = std::min(static_cast<double>(t.size()), b);
      if (b - a >= 16) s.follow.curveFirst = static_cast<std::size_t>(a), s.follow.curveLast = static_cast<std::size_t>(b);
    }
  }
}

// Play / pause, the speed, and a slider over the run's time: the selection follows (the view's
// marker, the G-code line, the row, the curves' cursor), as a preview plays the tool along its path.
void drawPlayback(Inspector::State& s, const Trajectory& t) {
  app_model::Playback& play = s.follow.playback;
  // As wide playing as paused: the speed and the slider beside it stay put.
  const float playWidth = ImGui::CalcTextSize("Pause").x + 2 * ImGui::GetStyle().FramePadding.x;
  const bool toggled = ImGui::Button(play.playing ? "Pause###play" : "Play###play", ImVec2(playWidth, 0));
  noteControl(s, "curves.play");
  if (toggled) play.toggle(s.selection);
  ImGui::SameLine();
  static const double kSpeeds[] = {0.1, 1, 10, 100};
  static const char* const kSpeedNames[] = {"x0.1", "x1", "x10", "x100"};
  int speed = 1;
  for (int k = 0; k < 4; ++k)
    if (play.speed == kSpeeds[k]) speed = k;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.5f);
  if (ImGui::Combo("##speed", &speed, kSpeedNames, 4)) play.speed = kSpeeds[speed];
  ImGui::SameLine();
  const double total = t.timeAt(t.size() - 1) - t.timeAt(0);
  const auto& sel = s.selection.current();
  double at = sel.sample && *sel.sample < t.size() ? t.timeAt(*sel.sample) - t.timeAt(0) : 0.0;
  const double lowest = 0;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &at, &lowest, &total, "%.3f s")) {
    play.playing = false;
    s.selection.selectSample(app_model::sampleAtTime(t, at));
  }
  noteControl(s, "curves.time");
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
  if (ImGui::Button("Whole time")) s.follow.curveFirst = 0, s.follow.curveLast = doc->samples->size();
  ImGui::SameLine();
  const app_model::Selection& sel = s.selection.current();
  const bool around = ImGui::Button("Around selection");
  noteControl(s, "curves.around");
  if (around && sel.sample) {
    const std::size_t half = 2000;
    s.follow.curveFirst = *sel.sample > half ? *sel.sample - half : 0;
    s.follow.curveLast = std::min(doc->samples->size(), *sel.sample + half);
  }
  // Playing, the curves turn the page when the tool leaves the stretch shown, as a chart
  // recorder does: the same width, the tool near its left.
  if (s.follow.playback.playing && sel.sample && s.follow.curveLast > s.follow.curveFirst &&
      (*sel.sample < s.follow.curveFirst || *sel.sample >= s.follow.curveLast)) {
    const std::size_t width = s.follow.curveLast - s.follow.curveFirst, size = doc->samples->size();
    s.follow.curveFirst = std::min(*sel.sample > width / 10 ? *sel.sample - width / 10 : 0, size > width ? size - width : 0);
    s.follow.curveLast = std::min(size, s.follow.curveFirst + width);
  }
  ImGui::SameLine();
  ImGui::Text("samples %zu .. %zu", s.follow.curveFirst, s.follow.curveLast);
  if (doc->curves.size() > 3) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(160);
    std::vector<const char*> names;
    for (std::size_t k = 3; k < doc->curves.size(); ++k) names.push_back(doc->curves[k].label.c_str());
    s.follow.extraCurve = std::clamp(s.follow.extraCurve, 0, static_cast<int>(names.size()) - 1);
    ImGui::Combo("channel", &s.follow.extraCurve, names.data(), static_cast<int>(names.size()));
  }
  drawPlayback(s, *doc->samples);
  const ImVec2 area = ImGui::GetContentRegionAvail();
  const int shown = doc->curves.size() > 3 ? 4 : 3;
  const float axis = ImGui::GetTextLineHeight() + 6;  // the time axis under the curves
  const float each = (area.y - axis - 4 * (shown - 1)) / shown;
  ImVec2 origin = ImGui::GetCursorScreenPos();
  const DisplayUnits units = s.units();
  const char* unitOf[3] = {units.feedUnit(), units.accelerationUnit(), units.jerkUnit()};
  for (int k = 0; k < shown; ++k) {
    Curve& curve = doc->curves[k < 3 ? k : 3 + s.follow.extraCurve];
    // Speed, acceleration and jerk are lengths per time: shown in the display units.
    const double scale = k < 3 ? units.length(1.0) : 1.0;
    // The path speed of a second run compared (a machine's recording, another simulation) over
    // this one's.
    RunComparisonView* second = k == 0 && s.runComparison ? s.runComparison.get() : nullptr;
    drawCurve(s, curve, scale, k < 3 ? unitOf[k] : curve.unit.c_str(), *doc->samples, origin, ImVec2(area.x, each), second);
    if (k == 0) s.chrome.controls["curves.speed"] = {origin.x, origin.y, origin.x + area.x, origin.y + each};
    origin.y += each + 4;
  }
  drawTimeAxis(*doc->samples, s.follow.curveFirst, std::max(s.follow.curveLast, s.follow.curveFirst + 1), ImVec2(origin.x, origin.y - 4), area.x);
  ImGui::SetCursorScreenPos(ImVec2(origin.x, origin.y + axis - 4));
  ImGui::Dummy(ImVec2(1, 1));
  ImGui::End();
}

}  // namespace isurface::panels
