// The Colour panel: what the map is coloured by, on which surface, how its passes are found and
// joined, its colour map and range, and what of the document the view shows.
#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

#include "inspector_state.h"
#include "isurface/vis/color_map.h"

namespace isurface::panels {

namespace {

// The next radio button or checkbox labelled `label` on the same line when it fits there whole,
// else on the next: a narrow panel wraps its choices rather than cutting them off.
void sameLineIfRoomFor(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float needed = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + needed <= right) ImGui::SameLine();
}

// A map of this few passes or fewer is mostly empty, and the panel says what may fill it.
constexpr std::size_t kFewPasses = 3;

// How far apart passes may lie and still be joined by the surface, in the lengths shown; true
// when it changed (the map is then made again). A roughing program's step-over (4 mm, say) is
// more than the default, which is set for finishing programs: without this, such a program
// opened in the window had curves but no map, and nothing to be done about it.
bool drawGapControl(Inspector::State& s) {
  const DisplayUnits u = s.units();
  float shown = static_cast<float>(u.length(s.settings.gapLimit));
  ImGui::TextUnformatted("gap between passes:");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputFloat("##gap", &shown, 0, 0, u.inch ? "%.4f in" : "%.3f mm");
  noteControl(s, "surface.gap");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("passes further apart than this get no surface between them");
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  const double mm = u.inch ? double(shown) * kMmPerInch : double(shown);
  if (!(mm > 0) || !std::isfinite(mm)) {
    s.status = "the gap between passes must be more than 0";
    return false;
  }
  // The value as shown, typed again, is not a change (2 mm shows as 0.0787 in).
  if (std::fabs(mm - s.settings.gapLimit) < (u.inch ? 0.00005 * kMmPerInch : 0.0005)) return false;
  s.settings.gapLimit = mm;
  return true;
}

// How the samples split into passes: found from the path (auto), or as the user knows the
// program was written (as `compare --pattern` takes it). True when it changed.
bool drawPatternControl(Inspector::State& s) {
  ImGui::TextUnformatted("passes:");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  bool changed = false;
  if (ImGui::BeginCombo("##pattern", pathPatternName(s.settings.pattern))) {
    for (PathPattern p : {PathPattern::Auto, PathPattern::DirectionParallel, PathPattern::ContourParallel, PathPattern::NoBoundary})
    {
      const bool chosen = ImGui::Selectable(pathPatternName(p), p == s.settings.pattern);
      noteControl(s, std::string("surface.pattern:") + pathPatternName(p));
      if (chosen && p != s.settings.pattern) {
        s.settings.pattern = p;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  noteControl(s, "surface.pattern");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("how the samples split into passes: found from the path, or as the program was written");
  return changed;
}

}  // namespace

void drawColourControls(Inspector::State& s, float x, float y, float w, float h) {
  beginPanel("Colour", x, y, w, h);
  s.chrome.controls["colour"] = {x, y, x + w, y + h};
  bool recolour = false;
  const QuantityInfo& current = quantityInfo(s.settings.quantity);
  const bool byChannel = !s.settings.channel.empty();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##quantity", byChannel ? s.settings.channel.c_str() : current.label)) {
    const Document* shown = s.activeDocument();
    for (const QuantityInfo& q : quantityInfos())
      if (q.needsJoints && !(shown && shown->samples && quantityAvailable(q.quantity, *shown->samples))) continue;
      else if (ImGui::Selectable(q.label, !byChannel && q.quantity == s.settings.quantity)) {
        s.settings.quantity = q.quantity;
        s.settings.channel.clear();
        s.persistent.quantity = q.name;
        if (s.settings.rangeMode == 2) s.settings.rangeMode = 0;  // a fixed range was the other quantity's
        recolour = true;
      }
    // The dump's own channels (errors of a slow tool servo path, currents, ...).
    if (Document* doc = s.activeDocument(); doc && doc->samples)
      for (const auto& [name, values] : doc->samples->extra)
        if (ImGui::Selectable(name.c_str(), s.settings.channel == name)) {
          s.settings.channel = name;
          recolour = true;
        }
    ImGui::EndCombo();
  }
  if (!byChannel) ImGui::Text("unit: %s", s.units().unitOf(current.unit));
  // Which surface carries the colours: what the interpolator commanded, or where the encoders
  // say the tool went (a dump with feedback). The programmed path is the toolpath below.
  {
    const Document* doc = s.activeDocument();
    const bool feedback = doc && doc->feedbackAvailable();
    // The map of such a file was made on the commanded surface (see loadDocument).
    if (!feedback) s.settings.feedbackSurface = false;
    int surface = s.settings.feedbackSurface ? 1 : 0;
    ImGui::TextUnformatted("surface:");
    ImGui::SameLine();
    recolour |= ImGui::RadioButton("commanded", &surface, 0);
    sameLineIfRoomFor("feedback");
    ImGui::BeginDisabled(!feedback);
    recolour |= ImGui::RadioButton("feedback", &surface, 1);
    noteControl(s, "surface.feedback");
    ImGui::EndDisabled();
    if (!feedback && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
      ImGui::SetTooltip("the samples have no feedback positions (fb_x fb_y fb_z)");
    s.settings.feedbackSurface = surface == 1;
  }
  recolour |= drawGapControl(s);
  recolour |= drawPatternControl(s);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##cmap", s.settings.colorMap.c_str())) {
    std::vector<std::string> names = vis::colorMapNames();
    names.insert(names.begin(), vis::kAutoColorMap);  // rainbow, or diverging for signed values
    for (const std::string& name : names)
      if (ImGui::Selectable(name.c_str(), name == s.settings.colorMap)) {
        s.settings.colorMap = s.persistent.colorMap = name;
        recolour = true;
      }
    ImGui::EndCombo();
  }
  recolour |= ImGui::RadioButton("1-99 %", &s.settings.rangeMode, 0);
  noteControl(s, "range.percentile");
  ImGui::SameLine();
  recolour |= ImGui::RadioButton("full", &s.settings.rangeMode, 1);
  ImGui::SameLine();
  const int modeBefore = s.settings.rangeMode;
  recolour |= ImGui::RadioButton("fixed", &s.settings.rangeMode, 2);
  noteControl(s, "range.fixed");
  if (s.settings.rangeMode == 2 && modeBefore != 2) {
    // A fixed range starts as the range shown, in the quantity's own unit.
    if (const Document* doc = s.activeDocument(); doc && doc->scene) {
      s.settings.fixedLow = static_cast<float>(doc->map.style.range.lo);
      s.settings.fixedHigh = static_cast<float>(doc->map.style.range.hi);
    }
  }
  if (s.settings.rangeMode == 2) {
    // Enter in either field applies the range, as the button does.
    const float labelRoom = ImGui::CalcTextSize("from ").x;
    ImGui::SetNextItemWidth(-labelRoom);
    bool apply = ImGui::InputFloat("from", &s.settings.fixedLow, 0, 0, "%g", ImGuiInputTextFlags_EnterReturnsTrue);
    noteControl(s, "range.low");
    ImGui::SetNextItemWidth(-labelRoom);
    apply |= ImGui::InputFloat("to", &s.settings.fixedHigh, 0, 0, "%g", ImGuiInputTextFlags_EnterReturnsTrue);
    noteControl(s, "range.high");
    apply |= ImGui::Button("Apply range");
    noteControl(s, "range.apply");
    if (apply && !(s.settings.fixedLow < s.settings.fixedHigh))
      s.status = "a fixed range needs its start below its end";
    else recolour |= apply;
  }
  if (Document* doc = s.activeDocument(); doc && doc->scene) {
    ImGui::Separator();
    ImGui::Text("range %s .. %s", readableValue(doc->map.style.range.lo).c_str(), readableValue(doc->map.style.range.hi).c_str());
    const std::size_t passes = doc->map.passes.passes.size();
    ImGui::TextWrapped("%zu passes, %s%s", passes, pathPatternName(doc->map.passes.pattern),
                       doc->map.request.pattern == PathPattern::Auto ? " (found)" : "");
    bool visibility = ImGui::Checkbox("surface", &doc->showSurface);
    ImGui::SameLine();
    visibility |= ImGui::Checkbox("toolpath", &doc->showToolpath);
    sameLineIfRoomFor("points");
    visibility |= ImGui::Checkbox("points", &doc->showPoints);
    if (doc->scene->hasToolAxes()) {
      sameLineIfRoomFor("tool axis");
      visibility |= ImGui::Checkbox("tool axis", &doc->showToolAxes);
      noteControl(s, "view.toolAxis");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("the tool's direction along the passes (a five-axis run)");
    }
    if (visibility) {
      doc->scene->setVisibility(doc->showSurface, doc->showToolpath, doc->showPoints, doc->showToolAxes);
      s.view.invalidate();
    }
    // A surface on little of the path is mostly empty: said, with what may fill it, below the
    // controls so that none of them moves when it appears.
    if (passes <= kFewPasses || doc->surfaceShare < vis::kLittleSurfaceShare) {
      ImGui::PushTextWrapPos(0);
      ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f),
                         "%zu passes, %.0f %% of the path on the surface: if the program is a raster or "
                         "waterlines, choose its pass pattern above, or raise the gap",
                         passes, 100 * doc->surfaceShare);
      ImGui::PopTextWrapPos();
    }
  }
  if (recolour) s.startRecolour();
  ImGui::End();
}

}  // namespace isurface::panels
