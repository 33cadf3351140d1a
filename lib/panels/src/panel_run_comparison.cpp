// Comparing the active document with a second run of its program (another simulation, a
// machine's recording): the second run's map beside the document's, the same colour range and
// camera, or the difference map on the document's surface; the figures over the view.
#include <imgui.h>

#include <filesystem>

#include <fmt/format.h>

#include "inspector_state.h"
#include "text_input.h"
#include "isurface/io/biip.h"
#include "isurface/vis/difference_map.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/io/trajectory_loading.h"

namespace isurface::panels {

namespace {

std::string summaryOf(const RunComparison& c, const std::string& nameB) {
  const DifferenceFigures& t = c.total;
  std::string text = fmt::format(
      "{} against this run (B - A): {} common lines, time {:.3f} -> {:.3f} s ({:+.3f} s, {:+.1f}%), speed mean {:+.0f}, "
      "largest {:+.0f} mm/min, paths up to {:.3f} mm apart",
      nameB, c.lines.size(), t.timeA, t.timeB, t.timeDifference, t.timeA > 0 ? 100.0 * t.timeDifference / t.timeA : 0.0,
      t.meanSpeedDifference, t.maxSpeedDifference, t.maxPathDistance);
  if (!c.ranges.empty()) {
    const RangeDifference& worst = c.ranges[c.worstRanges(ComparisonQuantity::Time, 1).front()];
    text += fmt::format("; most time at lines {}-{} ({:+.3f} s)", worst.firstLine, worst.lastLine,
                        worst.figures.timeDifference);
  }
  if (!c.onlyInA.empty() || !c.onlyInB.empty())
    text += fmt::format("; {} lines only here, {} only in B (each compared with the common line before it)", c.onlyInA.size(), c.onlyInB.size());
  return text;
}

}  // namespace

void buildDifferenceView(vis::QualityMapRequest request, const vis::QualityMapRequest& like, const Trajectory& a,
                         const Program* program, vis::QualityMap& map, std::shared_ptr<vis::QualityScene>& scene) {
  request.view = like.view;
  request.coarseVertices = like.coarseVertices;
  request.gapLimit = like.gapLimit;  // the passes joined as on the map it is the difference of
  if (request.caption.empty()) request.caption = like.caption;  // the machine both runs were made with
  map = vis::buildQualityMap(a, program, request);
  scene = std::make_shared<vis::QualityScene>(map.data, map.style);
}

std::optional<bool> drawDifferenceToggle(bool showingDifference, const char* differenceLabel) {
  std::optional<bool> choice;
  if (ImGui::RadioButton("Side by side", !showingDifference)) choice = false;
  ImGui::SameLine();
  if (ImGui::RadioButton(differenceLabel, showingDifference)) choice = true;
  if (choice == showingDifference) choice.reset();
  return choice;
}

void Inspector::State::startRunComparison(const std::string& dumpPath) {
  Document* doc = activeDocument();
  if (!doc || !doc->samples) {
    status = "open a program or a dump first, then compare it with another run";
    return;
  }
  if (doc->samples->thinning > 1) {
    status = "comparing needs every sample: " + doc->name + " is shown thinned (1 sample in " +
             std::to_string(doc->samples->thinning) + ")";
    return;
  }
  if (refusedDuringReport("compare")) return;
  // The two runs' feedback are compared too, when both have it.
  if (loadFeedbackFirst([this, dumpPath] { startRunComparison(dumpPath); })) return;
  vis::QualityMapRequest request = mapRequest();
  request.fixedRange = doc->map.style.range;  // the same colours on both sides
  auto result = std::make_shared<JobResult>(ComparedRun{doc->samples, nullptr});
  pending = result;
  std::shared_ptr<const Trajectory> a = doc->samples;
  std::shared_ptr<const Program> program = doc->program;
  const bool difference = runComparison && runComparison->showDifference;
  job.start("comparing with " + dumpPath, [result, a, program, request, dumpPath, difference](app_model::JobControl& control) {
    auto view = std::make_shared<RunComparisonView>();
    view->path = dumpPath;
    view->showDifference = difference;
    const BiipReader reader(dumpPath);
    view->samples = std::make_shared<const Trajectory>(loadTrajectory(reader));
    view->speed = curveOf(Quantity::Speed, view->samples);
    control.progress(0.3);
    view->result = compareRuns(*a, *view->samples);
    control.progress(0.5);
    view->map = vis::buildQualityMap(*view->samples, program.get(), request);
    view->scene = std::make_shared<vis::QualityScene>(view->map.data, view->map.style);
    control.progress(0.75);
    buildDifferenceView(vis::differenceMapRequest(view->result, ComparisonQuantity::Speed), request, *a, program.get(),
                        view->differenceMap, view->differenceScene);
    view->summary = summaryOf(view->result, std::filesystem::path(dumpPath).filename().string());
    std::get<ComparedRun>(*result).view = view;
  });
  status = "comparing with " + dumpPath;
}

void Inspector::State::showRunDifference(bool difference) {
  if (!runComparison) return;
  runComparison->showDifference = difference;
  afterView.setScene(difference ? runComparison->differenceScene : runComparison->scene);
}

void drawCompareDialog(Inspector::State& s) {
  if (s.dialogs.compare.opening) ImGui::OpenPopup("Compare with another run");
  s.dialogs.compare.opening = false;
  if (!beginDialog("Compare with another run")) return;
  ImGui::TextWrapped("A Biip dump of the same program (another simulation, or a machine's trace imported with its "
                     "lines), aligned to this run by G-code line and arc length:");
  ImGui::SetNextItemWidth(560);
  const bool enter = inputText("##run", s.dialogs.compare.path, ImGuiInputTextFlags_EnterReturnsTrue);
  if ((ImGui::Button("Compare") || enter) && !s.dialogs.compare.path.empty()) {
    s.startRunComparison(s.dialogs.compare.path);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Close") || escapeCloses(s)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

void drawRunComparisonView(Inspector::State& s, float x, float y, float w, float h) {
  RunComparisonView& c = *s.runComparison;
  beginBesidePanel("Second run", c.summary, x, y, w, h);
  if (const auto difference = drawDifferenceToggle(c.showDifference, "Difference (speed B - A)"))
    s.showRunDifference(*difference);
  ImGui::SameLine();
  const bool close = ImGui::Button("Close");
  if (endBesidePanel(s, close)) s.runComparison.reset();
}

}  // namespace isurface::panels
