// Re-optimising a region from the application: choose the lines (typed, dragged as a box over
// the surface, or the worst region the quality prediction finds), optimise in the background,
// and see the new map beside the old one, the same colour range and camera, or the speed
// difference on the old surface, with the region's figures; save the new program.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "inspector_state.h"
#include "isurface/io/atomic_file.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/optimise/optimized_run_comparison.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/optimise/region_optimizer.h"
#include "isurface/nc/simulator.h"
#include "isurface/vis/difference_map.h"
#include "isurface/vis/quality_scene.h"
#include "isurface/nc/sample_trajectory.h"

namespace isurface::panels {

namespace {

// How far the re-fitted passes moved and how their speed changed (after - before).
std::string passDifferenceText(const RunComparison& difference, const OptimizeResult& optimized) {
  double apart = 0, speedChange = 0;  // mm; mm/min, the signed change of largest magnitude
  for (const LineDifference& d : difference.lines) {
    const bool refitted = std::any_of(optimized.passes.begin(), optimized.passes.end(),
                                      [&](const OptimizedPass& p) { return p.firstLine == d.line; });
    if (!refitted) continue;
    apart = std::max(apart, d.figures.maxPathDistance);
    if (std::abs(d.figures.maxSpeedDifference) > std::abs(speedChange)) speedChange = d.figures.maxSpeedDifference;
  }
  return fmt::format(". The new passes lie within {:.4f} mm of the old; speed after - before up to {:+.0f} mm/min",
                     apart, speedChange);
}

}  // namespace

void Inspector::State::startOptimise(std::uint32_t first, std::uint32_t last,
                                     std::optional<std::pair<Vec3, Vec3>> measuredBox) {
  Document* doc = activeDocument();
  if (!doc || !doc->program || doc->programPath.empty() || !doc->samples) return;
  vis::QualityMapRequest request = mapRequest();
  request.fixedRange = doc->map.style.range;  // the same colours on both sides
  auto result = std::make_shared<JobResult>();
  pending = result;
  const std::string path = doc->programPath;
  std::shared_ptr<const Program> program = doc->program;
  std::shared_ptr<const Trajectory> before = doc->samples;
  const PassSet beforePasses = doc->map.passes;
  job.start(fmt::format("optimising lines {}-{}", first, last),
            [result, path, program, before, beforePasses, request, first, last, measuredBox](app_model::JobControl& control) {
              std::ifstream in(path, std::ios::binary);
              std::stringstream text;
              text << in.rdbuf();
              const Machine machine = defaultMachine();
              const OptimizeResult optimized = optimizeRegion(text.str(), *program, LineRange{first, last}, machine);
              control.progress(0.2);
              InterpretResult reread = interpretGcode(optimized.text, path);
              if (!reread.ok()) throw InputError(reread.errors.front());
              auto c = std::make_shared<Comparison>();
              c->text = optimized.text;
              c->first = first;
              c->last = last;
              c->program = std::make_shared<const Program>(std::move(reread.program));
              SampleBuffer buffer;
              simulate(*c->program, machine, buffer, [&](double f) { control.progress(0.2 + 0.5 * f); });
              c->samples = std::make_shared<const Trajectory>(trajectoryFromSamples(buffer.data, machine.cycle, path));
              c->map = vis::buildQualityMap(*c->samples, c->program.get(), request);
              c->scene = std::make_shared<vis::QualityScene>(c->map.data, c->map.style);
              control.progress(0.8);
              c->difference = compareOptimizedRuns(*before, *c->samples, optimized);
              buildDifferenceView(vis::regionDifferenceMapRequest(c->difference, *before, LineRange{first, last}), request,
                                  *before, program.get(), c->differenceMap, c->differenceScene);
              control.progress(0.9);
              const SurfaceMesh beforeMesh = buildSurfaceMesh(*before, beforePasses);
              const Vec3 lower = measuredBox ? measuredBox->first : optimized.fittedLower;
              const Vec3 upper = measuredBox ? measuredBox->second : optimized.fittedUpper;
              const RegionMetrics old = measureRegion(*before, beforeMesh, LineRange{first, last}, lower, upper);
              const RegionMetrics now = measureRegion(*c->samples, *c->map.mesh, optimized.newRange, lower, upper);
              c->timeBefore = before->size() * machine.cycle;
              c->timeAfter = c->samples->size() * machine.cycle;
              c->summary = fmt::format(
                  "lines {}-{}: {} passes re-fitted. Machining time {:.1f} -> {:.1f} s. In the region: speed fluctuation "
                  "{:.0f} -> {:.0f} mm/min, largest inconsistency between passes {:.0f} -> {:.0f} mm/min, jerk peak "
                  "{:.0f} -> {:.0f} mm/s^3",
                  first, last, optimized.passes.size(), c->timeBefore, c->timeAfter, old.speedFluctuation,
                  now.speedFluctuation, old.maxSpeedInconsistency, now.maxSpeedInconsistency, old.maxJerk, now.maxJerk);
              c->summary += passDifferenceText(c->difference, optimized);
              result->comparison = c;
            });
}

void Inspector::State::showOptimisedDifference(bool difference) {
  if (!comparison) return;
  comparison->showDifference = difference;
  afterView.setScene(difference ? comparison->differenceScene : comparison->scene);
}

void drawOptimiseDialog(Inspector::State& s) {
  if (s.optimiseDialog) ImGui::OpenPopup("Optimise region");
  s.optimiseDialog = false;
  s.optimiseDialogOpen = ImGui::BeginPopupModal("Optimise region", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (!s.optimiseDialogOpen) {
    s.optimiseBox.reset();  // a box chosen for a dialog that was closed
    return;
  }
  Document* doc = s.activeDocument();
  ImGui::TextWrapped("Constant speed intervals, Akima fitting and one feed per interval, for the G1 moves of the lines:");
  ImGui::InputInt("first line", &s.optimiseFirst);
  ImGui::InputInt("last line", &s.optimiseLast);
  // The box only stands for the region while the lines are still its own.
  const bool boxed = s.optimiseBox && s.optimiseBox->lines.first == static_cast<std::uint32_t>(s.optimiseFirst) &&
                     s.optimiseBox->lines.last == static_cast<std::uint32_t>(s.optimiseLast);
  if (boxed) {
    const app_model::BoxSelection& b = *s.optimiseBox;
    ImGui::Text("Box: X %.2f .. %.2f  Y %.2f .. %.2f mm, %zu surface samples; the figures are taken inside it",
                b.lower.x(), b.upper.x(), b.lower.y(), b.upper.y(), b.samples);
  }
  if (ImGui::Button("Worst predicted region") && doc && doc->samples && doc->map.mesh) {
    const QualityReport report = findQualityRegions(*doc->samples, *doc->map.mesh);
    if (const QualityRegion* worst = worstRegionInsidePasses(report)) {
      // As `optimize --auto`: whole passes around the region, its figures taken inside its box.
      const LineRange lines = widenToWholePasses(*doc->samples, doc->map.passes, {worst->firstLine, worst->lastLine});
      s.optimiseFirst = static_cast<int>(lines.first);
      s.optimiseLast = static_cast<int>(lines.last);
      s.optimiseBox = app_model::BoxSelection{lines, worst->lower, worst->upper, worst->vertices};
      s.optimiseBoxOnView = {};  // not drawn: the region was not dragged on this view
    } else {
      s.status = "no region beyond the quality thresholds away from the pass ends";
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Selected line's pass") && s.selection.current().line) {
    s.optimiseFirst = static_cast<int>(*s.selection.current().line);
    s.optimiseLast = s.optimiseFirst + 100;
  }
  if (ImGui::Button("Optimise") && s.optimiseFirst >= 1 && s.optimiseLast >= s.optimiseFirst) {
    std::optional<std::pair<Vec3, Vec3>> measured;
    if (boxed) measured = std::make_pair(s.optimiseBox->lower, s.optimiseBox->upper);
    s.startOptimise(static_cast<std::uint32_t>(s.optimiseFirst), static_cast<std::uint32_t>(s.optimiseLast), measured);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Close")) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

void beginBesidePanel(const char* name, const std::string& summary, float x, float y, float w, float h) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  beginPanel(name, x, y, w, h, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + w - 10);
  ImGui::TextUnformatted(summary.c_str());
  ImGui::PopTextWrapPos();
}

bool endBesidePanel(Inspector::State& s, bool close) {
  // Seen from where the map beside it is seen.
  if (s.view.scene() && s.afterView.scene()) s.afterView.copyCameraFrom(s.view);
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const unsigned int texture = s.afterView.render(static_cast<int>(size.x), static_cast<int>(size.y));
  if (texture) drawViewFrame(texture, size);
  ImGui::End();
  ImGui::PopStyleVar();
  if (close) s.afterView.setScene(nullptr);
  return close;
}

void drawComparisonView(Inspector::State& s, float x, float y, float w, float h) {
  Comparison& c = *s.comparison;
  beginBesidePanel("After re-optimisation", c.summary, x, y, w, h);
  if (const auto difference = drawDifferenceToggle(c.showDifference, "Difference (speed after - before)"))
    s.showOptimisedDifference(*difference);
  ImGui::SetNextItemWidth(w * 0.5f);
  ImGui::InputText("##save", s.savePath, sizeof s.savePath);
  ImGui::SameLine();
  if (ImGui::Button("Save program") && s.savePath[0]) {
    try {
      writeFileAtomically(s.savePath, c.text);
      s.status = std::string("saved ") + s.savePath;
    } catch (const std::exception& e) {
      s.status = std::string("error: ") + e.what();
    }
  }
  ImGui::SameLine();
  const bool close = ImGui::Button("Close");
  if (endBesidePanel(s, close)) s.comparison.reset();
}

}  // namespace isurface::panels
