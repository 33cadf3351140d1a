#include "report_beside.h"

#include <filesystem>

#include <fmt/format.h>

#include "isurface/analysis/quality_figures.h"
#include "isurface/analysis/quantities.h"
#include "isurface/analysis/run_comparison.h"
#include "isurface/io/whole_file.h"
#include "isurface/optimise/optimized_run_comparison.h"
#include "isurface/vis/difference_map.h"
#include "isurface/workflow/region_optimisation.h"
#include "report_parts.h"

namespace isurface::report {
namespace {

// Both runs' speed maps share one colour range (the first run's 1st to 99th percentile on its
// surface), so that a colour means the same speed in both.
ValueRange sharedSpeedRange(const SurfaceRun& run) {
  return percentileRange(vertexQuantity(Quantity::Speed, *run.samples, *run.mesh), 1, 99);
}

vis::QualityMapRequest speedTop(const ValueRange& range, const std::string& caption) {
  vis::QualityMapRequest request;
  request.quantity = Quantity::Speed;
  request.view = vis::ViewDirection::Top;
  request.fixedRange = range;
  request.caption = caption;
  return request;
}

std::string nameOf(const std::string& path) { return std::filesystem::path(path).filename().string(); }


}  // namespace

void comparisonSection(HtmlDocument& doc, const OpenedRun& run, const OpenedRun& other, double gapLimit,
                       const ProgressCallback& progress,
                       nlohmann::json& out) {
  const std::string thisName = nameOf(run.files.dump.empty() ? run.files.program : run.files.dump);
  const std::string otherName = nameOf(other.files.dump.empty() ? other.files.program : other.files.dump);
  if (!other.samples) throw InputError(Diagnostic{other.files.dump, 0, 0, "the run compared makes no motion"});
  const SurfaceRun a = surfaceRun(run.samples, run.program.get(), gapLimit);
  const SurfaceRun b = surfaceRun(other.samples, other.program ? other.program.get() : run.program.get(), gapLimit);
  doc.openSection("comparison");
  doc.heading(2, fmt::format("This run beside {}", otherName));
  // Runs without a surface between their passes are not compared; the rest of the report stands.
  if (a.mesh->triangles.empty() || b.mesh->triangles.empty()) {
    const std::string why = whyNoTriangles((a.mesh->triangles.empty() ? a : b).passes, gapLimit);
    doc.paragraph("Not compared: " + why + ".");
    doc.closeSection();
    out["comparison"] = {{"compared_with", other.files.dump}, {"not_done", why}};
    return;
  }
  const ValueRange range = sharedSpeedRange(a);
  doc.raw("<div class=\"maps\">\n");
  doc.image(renderMapPng(run, speedTop(range, thisName), gapLimit), fmt::format("Path speed, {} (top view)", thisName));
  if (progress) progress(0.3);
  doc.image(renderMapPng(other, speedTop(range, otherName), gapLimit),
            fmt::format("Path speed, {} (top view, the same colour range)", otherName));
  if (progress) progress(0.6);
  const RunComparison comparison = compareRuns(*run.samples, *other.samples);
  vis::QualityMapRequest difference = vis::differenceMapRequest(comparison, ComparisonQuantity::Speed);
  difference.view = vis::ViewDirection::Top;
  difference.caption = otherName + " against " + thisName;
  doc.image(renderMapPng(run, difference, gapLimit),
            fmt::format("Speed of {} minus speed of {} at the same place on the part (mm/min)", otherName, thisName));
  doc.raw("</div>\n");
  const QualityFigures figuresA = measureQualityFigures(*a.samples, *a.mesh);
  const QualityFigures figuresB = measureQualityFigures(*b.samples, *b.mesh);
  const double timeA = machiningTime(*run.samples), timeB = machiningTime(*other.samples);
  figuresTable(doc, thisName, otherName, timeA, timeB, figuresA, figuresB);
  doc.closeSection();
  out["comparison"] = {{"compared_with", other.files.dump}, {"this_run", figuresJson(timeA, figuresA)},
                       {"compared_run", figuresJson(timeB, figuresB)}};
  if (progress) progress(1.0);
}

void optimisationSection(HtmlDocument& doc, const OpenedRun& run, const ReportOptions& options,
                         const ProgressCallback& progress, nlohmann::json& out) {
  if (!run.program || run.files.program.empty())
    throw InputError(Diagnostic{run.files.dump, 0, 0, "a re-optimisation needs the program, not a dump alone"});
  const std::string& path = run.files.program;
  const SurfaceRun before = surfaceRun(run.samples, run.program.get(), options.gapLimit);
  const bool all = options.optimisation == ReportOptimisation::AllPasses;
  RegionOptimisation r;
  try {
    const ChosenRegion chosen = all ? wholeProgramRegion(before, path) : worstRegion(before, path);
    RegionRequest request;
    request.options.chordTolerance = options.chordTolerance;
    request.lines = chosen.lines;
    request.box = std::make_pair(chosen.lower, chosen.upper);
    r = optimiseRegion(readWholeFile(path), *run.program, before, run.machine, request, progressStage(progress, 0, 0.7));
  } catch (const InputError& e) {
    // Nothing to re-optimise (no surface, no region beyond the thresholds, an inch program):
    // the rest of the report stands, and this section says why.
    doc.openSection("optimisation");
    doc.heading(2, "Re-optimisation");
    doc.paragraph("Not re-optimised: " + e.diagnostic().message + ".");
    doc.closeSection();
    out["optimisation"] = {{"mode", all ? "all" : "auto"}, {"not_done", e.diagnostic().message}};
    return;
  }

  doc.openSection("optimisation");
  doc.heading(2, fmt::format("Re-optimised: {} (lines {}-{})", all ? "every pass" : "the worst region", r.lines.first,
                             r.lines.last));
  if (r.kept) doc.paragraph("The new program is no slower and no figure is worse by more than 2 %: it would be kept.");
  doc.paragraph(regionSummary(r));
  OpenedRun after = run;
  after.files.dump.clear();
  after.samples = r.after.samples;
  after.program = r.program;
  const ValueRange range = sharedSpeedRange(before);
  const std::string name = nameOf(path);
  doc.raw("<div class=\"maps\">\n");
  doc.image(renderMapPng(run, speedTop(range, name + " before"), options.gapLimit), "Path speed before (top view)");
  doc.image(renderMapPng(after, speedTop(range, name + " after"), options.gapLimit), "Path speed after (top view, the same colour range)");
  const RunComparison difference = compareOptimizedRuns(*before.samples, *r.after.samples, r.result);
  vis::QualityMapRequest differenceMap = vis::regionDifferenceMapRequest(difference, *before.samples, r.lines);
  differenceMap.view = vis::ViewDirection::Top;
  differenceMap.caption = name + " after against before";
  doc.image(renderMapPng(run, differenceMap, options.gapLimit), "Speed after minus before on the surface before (mm/min)");
  doc.raw("</div>\n");
  doc.heading(3, "In the region");
  figuresTable(doc, "before", "after", r.timeBefore, r.timeAfter, r.regionBefore, r.regionAfter);
  doc.heading(3, "The whole program");
  figuresTable(doc, "before", "after", r.timeBefore, r.timeAfter, r.wholeBefore, r.wholeAfter);
  doc.paragraph(fmt::format("The new path lies within {:.4f} mm of the old one over the region. The program has {} lines "
                            "before and {} after.",
                            r.maxPathDistance, r.linesBefore, r.linesAfter));
  doc.closeSection();
  out["optimisation"] = {{"mode", all ? "all" : "auto"},
                         {"lines", {r.lines.first, r.lines.last}},
                         {"kept", r.kept},
                         {"reason", r.reason},
                         {"max_path_distance_mm", r.maxPathDistance},
                         {"program_lines", {{"before", r.linesBefore}, {"after", r.linesAfter}}},
                         {"region", {{"before", figuresJson(r.timeBefore, r.regionBefore)},
                                     {"after", figuresJson(r.timeAfter, r.regionAfter)}}},
                         {"whole_program", {{"before", figuresJson(r.timeBefore, r.wholeBefore)},
                                            {"after", figuresJson(r.timeAfter, r.wholeAfter)}}}};
  if (progress) progress(1.0);
}

}  // namespace isurface::report
