// The worst regions window: the report's ranking of the map's regions beyond the quality
// thresholds (pits and bulges to be expected), each a click away from its worst sample, and from
// the Optimise dialog holding its lines and box.
#include <imgui.h>

#include <fmt/format.h>

#include "inspector_state.h"
#include "isurface/map/quality_map.h"

namespace isurface::panels {

namespace {

// The most the window lists, as the report shows at most.
constexpr std::size_t kMostListed = 50;

// The region's lines and box held by the Optimise dialog, which opens.
void optimiseRegion(Inspector::State& s, const Document& doc, const QualityRegion& r) {
  s.dialogs.optimise.forgetTheRegionOfAnotherProgram(doc.programPath);
  const LineRange lines{r.firstLine, r.lastLine};
  s.dialogs.optimise.hold(lines, app_model::BoxSelection{lines, r.lower, r.upper, r.vertices});
  s.dialogs.optimise.boxOnView = {};
  s.dialogs.optimise.opening = true;
}

void drawRegionRows(Inspector::State& s, Document& doc, const QualityReport& report) {
  const DisplayUnits u = s.units();
  ImGui::TextWrapped("%zu regions beyond the thresholds (speed inconsistency 150 mm/min, acceleration inconsistency "
                     "600 mm/s^2, jerk 40000 mm/s^3), most severe first, as the report ranks them. A click goes to "
                     "the worst sample of one.",
                     report.regions.size());
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersV |
                                ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("regions", 7, flags)) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name : {"#", "lines", "severity", "speed inc. [mm/min]", "accel inc. [mm/s^2]", "jerk [mm/s^3]", ""})
    ImGui::TableSetupColumn(name);
  ImGui::TableHeadersRow();
  const std::size_t listed = std::min(report.regions.size(), kMostListed);
  for (std::size_t k = 0; k < listed; ++k) {
    const QualityRegion& r = report.regions[k];
    ImGui::PushID(static_cast<int>(k));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = std::to_string(k + 1);
    if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap)) {
      s.selection.selectSample(r.worstSample);
      s.status = fmt::format("region {}: lines {}-{}, box X {:.4g} to {:.4g}, Y {:.4g} to {:.4g} {}; worst at sample {}",
                             k + 1, r.firstLine, r.lastLine, u.length(r.lower.x()), u.length(r.upper.x()),
                             u.length(r.lower.y()), u.length(r.upper.y()), u.lengthUnit(), r.worstSample);
    }
    noteControl(s, "regions.item:" + label);
    ImGui::TableNextColumn();
    ImGui::Text("%u-%u%s", r.firstLine, r.lastLine, r.atPassEnds ? " (pass ends)" : "");
    ImGui::TableNextColumn();
    ImGui::Text("%.1f", r.severity);
    ImGui::TableNextColumn();
    ImGui::Text("%.0f", r.maxSpeedInconsistency);
    ImGui::TableNextColumn();
    ImGui::Text("%.0f", r.maxAccelInconsistency);
    ImGui::TableNextColumn();
    ImGui::Text("%.0f", r.maxJerk);
    ImGui::TableNextColumn();
    if (ImGui::SmallButton("Optimise")) optimiseRegion(s, doc, r);
    noteControl(s, "regions.optimise:" + label);
    ImGui::PopID();
  }
  ImGui::EndTable();
}

}  // namespace

void Inspector::State::startFindingRegions() {
  Document* doc = activeDocument();
  if (!doc || !doc->samples || !doc->map.mesh || (doc->regions && doc->regionsOfMap == doc->map.mesh)) return;
  if (job.running() || pending) return;  // asked again once the job has ended (the window stays open)
  auto result = std::make_shared<JobResult>(FoundRegions{doc->samples, doc->map.mesh, nullptr});
  pending = result;
  job.start("finding the worst regions of " + doc->name, [result, map = doc->map](app_model::JobControl& control) {
    FoundRegions& found = std::get<FoundRegions>(*result);
    control.progress(0.1);
    // On the figures' mesh (every pass sample), as the report finds them, whatever the view thinned.
    const std::shared_ptr<const SurfaceMesh> mesh = vis::figuresMesh(*found.madeFor, map);
    control.progress(0.5);
    found.report = std::make_shared<const QualityReport>(findQualityRegions(*found.madeFor, *mesh));
    control.progress(1.0);
  });
}

void Inspector::State::take(FoundRegions& result, const std::string&) {
  const std::size_t k = documentOf(result.madeFor);
  if (k == documents.size() || documents[k]->map.mesh != result.ofMap) return;  // closed, or mapped again
  documents[k]->regions = result.report;
  documents[k]->regionsOfMap = result.ofMap;
  status = fmt::format("{}: {} regions beyond the thresholds", documents[k]->name, result.report->regions.size());
}

void drawRegionsWindow(Inspector::State& s) {
  if (!s.dialogs.regionsOpen) return;
  if (beginListWindow("Worst regions", &s.dialogs.regionsOpen, 0.45f)) {
    Document* doc = s.activeDocument();
    if (!doc || !doc->samples) ImGui::TextDisabled("no samples: open a program or a dump");
    else if (!doc->map.mesh) ImGui::TextDisabled("%s has no surface: no regions to rank", doc->name.c_str());
    else if (!doc->regions || doc->regionsOfMap != doc->map.mesh) {
      s.startFindingRegions();
      ImGui::TextDisabled("finding the worst regions of %s ...", doc->name.c_str());
    } else {
      drawRegionRows(s, *doc, *doc->regions);
    }
    if (ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) && s.takeEscape()) s.dialogs.regionsOpen = false;
  }
  ImGui::End();
}

}  // namespace isurface::panels
