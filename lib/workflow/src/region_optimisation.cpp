// Re-optimising a region: choose it, re-fit it, simulate the new program, measure both.
#include "isurface/workflow/region_optimisation.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "isurface/analysis/quality_figures.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface {

namespace {

constexpr double kRegionMarginMm = 0.5;

std::vector<Vec3> regionPoints(const Program& program, LineRange lines) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < program.moves.size(); ++i)
    if (program.moves[i].isMotion() && program.moves[i].line >= lines.first && program.moves[i].line <= lines.last) {
      if (points.empty()) points.push_back(program.startOf(i));
      points.push_back(program.moves[i].end);
    }
  return points;
}

std::pair<Vec3, Vec3> boundingBox(const std::vector<Vec3>& points) {
  Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity()), upper = -lower;
  for (const Vec3& p : points) lower = lower.cwiseMin(p), upper = upper.cwiseMax(p);
  if (points.empty()) lower = upper = Vec3::Zero();
  return {lower, upper};
}

}  // namespace

SurfaceRun surfaceRun(std::shared_ptr<const Trajectory> samples, const Program* program) {
  SurfaceRun run;
  PassOptions options;
  options.program = program;
  run.passes = splitPasses(*samples, options);
  run.mesh = std::make_shared<const SurfaceMesh>(buildSurfaceMesh(*samples, run.passes));
  run.samples = std::move(samples);
  return run;
}

ChosenRegion worstRegion(const SurfaceRun& run, const std::string& source) {
  const QualityReport report = findQualityRegions(*run.samples, *run.mesh);
  const QualityRegion* worst = worstRegionInsidePasses(report);
  if (!worst)
    throw InputError(Diagnostic{source, 0, 0,
                                report.regions.empty() ? "no region beyond the quality thresholds to optimise"
                                                       : "every region beyond the quality thresholds lies where passes start or end"});
  return {widenToWholePasses(*run.samples, run.passes, {worst->firstLine, worst->lastLine}), worst->lower, worst->upper,
          worst->vertices};
}

namespace {

// The lines and the extent of the surface's samples inside a box (XY, mm).
ChosenRegion surfaceInside(const SurfaceRun& run, const Vec3& lower, const Vec3& upper) {
  const Trajectory& t = *run.samples;
  ChosenRegion region;
  region.lines = {std::numeric_limits<std::uint32_t>::max(), 0};
  region.lower = Vec3::Constant(std::numeric_limits<double>::infinity());
  region.upper = -region.lower;
  for (const std::uint32_t i : run.mesh->vertexSample) {
    if (t.line[i] == 0 || t.x[i] < lower.x() || t.x[i] > upper.x() || t.y[i] < lower.y() || t.y[i] > upper.y()) continue;
    const Vec3 p(t.x[i], t.y[i], t.z[i]);
    region.lines.first = std::min(region.lines.first, t.line[i]);
    region.lines.last = std::max(region.lines.last, t.line[i]);
    region.lower = region.lower.cwiseMin(p);
    region.upper = region.upper.cwiseMax(p);
    ++region.vertices;
  }
  return region;
}

}  // namespace

ChosenRegion regionInBox(const SurfaceRun& run, const Vec3& lower, const Vec3& upper, const std::string& source) {
  ChosenRegion region = surfaceInside(run, lower.cwiseMin(upper), lower.cwiseMax(upper));
  if (region.vertices == 0)
    throw InputError(Diagnostic{source, 0, 0,
                                fmt::format("no cutting pass crosses the box X {:g}..{:g} Y {:g}..{:g} mm", lower.x(),
                                            upper.x(), lower.y(), upper.y())});
  region.lines = widenToWholePasses(*run.samples, run.passes, region.lines);
  region.lower = lower.cwiseMin(upper);
  region.upper = lower.cwiseMax(upper);
  return region;
}

ChosenRegion wholeProgramRegion(const SurfaceRun& run, const std::string& source) {
  const Vec3 everywhere = Vec3::Constant(std::numeric_limits<double>::infinity());
  const ChosenRegion region = surfaceInside(run, -everywhere, everywhere);
  if (region.vertices == 0) throw InputError(Diagnostic{source, 0, 0, "no cutting passes to optimise"});
  return region;
}

std::optional<LineRange> passOfLine(const SurfaceRun& run, std::uint32_t line) {
  const Trajectory& t = *run.samples;
  for (const Pass& pass : run.passes.passes) {
    const auto begin = t.line.begin() + static_cast<std::ptrdiff_t>(pass.begin);
    const auto end = t.line.begin() + static_cast<std::ptrdiff_t>(pass.end);
    if (std::find(begin, end, line) == end) continue;
    LineRange lines{~std::uint32_t(0), 0};
    for (auto it = begin; it != end; ++it)
      if (*it != 0) lines.first = std::min(lines.first, *it), lines.last = std::max(lines.last, *it);
    return lines;
  }
  return std::nullopt;
}

namespace {

bool slower(const RegionOptimisation& r) {
  // Half a cycle of slack: the two runs are whole numbers of cycles.
  const double cycle = r.after.samples ? r.after.samples->cycle : 0.0;
  return r.timeAfter > r.timeBefore + 0.5 * cycle;
}

// One candidate: re-fitted, simulated on the machine, measured and judged. `wholeBefore`: the
// program's own figures, the same for every candidate.
RegionOptimisation evaluateCandidate(const std::string& text, const Program& program, const SurfaceRun& before,
                                     const QualityFigures& wholeBefore, const Machine& machine,
                                     const RegionRequest& request, const ProgressCallback& progress) {
  RegionOptimisation r;
  r.lines = request.lines;
  r.result = optimizeRegion(text, program, request.lines, machine, request.options);
  if (progress) progress(0.2);
  InterpretResult reread = interpretGcode(r.result.text, program.source);
  if (!reread.ok()) throw std::runtime_error("the new program does not interpret: " + reread.errors.front().str());
  r.program = std::make_shared<const Program>(std::move(reread.program));
  r.after = surfaceRun(std::make_shared<const Trajectory>(simulateRun(*r.program, machine, progressStage(progress, 0.2, 0.9))),
                       r.program.get());
  // The figures look where the defect was found (a box), else where the path was re-fitted; a
  // re-fitted part that holds no surface sample (one pass, a flat box) gives way to the region.
  std::tie(r.lower, r.upper) = request.box ? *request.box : std::make_pair(r.result.fittedLower, r.result.fittedUpper);
  const auto window = [&](LineRange lines) { return FigureWindow{lines, r.lower, r.upper}; };
  r.regionBefore = measureQualityFigures(*before.samples, *before.mesh, window(request.lines));
  if (!request.box && r.regionBefore.samples == 0) {
    std::tie(r.lower, r.upper) = boundingBox(regionPoints(program, request.lines));
    // Only the region's lines are measured: the margin takes in no other line, and gives the
    // box of a single straight pass the height its samples need.
    r.lower -= Vec3::Constant(kRegionMarginMm);
    r.upper += Vec3::Constant(kRegionMarginMm);
    r.regionBefore = measureQualityFigures(*before.samples, *before.mesh, window(request.lines));
  }
  r.regionAfter = measureQualityFigures(*r.after.samples, *r.after.mesh, window(r.result.newRange));
  r.wholeBefore = wholeBefore;
  r.wholeAfter = measureQualityFigures(*r.after.samples, *r.after.mesh);
  r.maxPathDistance =
      polylineDistance(regionPoints(program, request.lines), regionPoints(*r.program, r.result.newRange));
  r.timeBefore = machiningTime(*before.samples);
  r.timeAfter = machiningTime(*r.after.samples);
  if (const auto why = worsening(r)) {
    r.kept = false;
    r.reason = *why;
  }
  if (progress) progress(1.0);
  return r;
}

}  // namespace

RegionOptimisation optimiseRegion(const std::string& text, const Program& program, const SurfaceRun& before,
                                  const Machine& machine, const RegionRequest& request, const ProgressCallback& progress) {
  // The closed loop. The paper's plan first (each pass its own interval feeds); when the
  // simulation finds it worse, the feeds planned across passes (the median of the passes
  // around, then their slowest), then a little below the plan (servo lag grows with speed).
  // Each candidate is simulated and judged; the first no worse than the program is kept. When
  // none is, the first one's figures and reason are reported.
  const struct {
    CrossPassRule rule;
    double share;
  } candidates[] = {{CrossPassRule::None, 1.0},
                    {CrossPassRule::Median, 1.0},
                    {CrossPassRule::Envelope, 1.0},
                    {CrossPassRule::None, 0.95},
                    {CrossPassRule::Median, 0.95}};
  constexpr std::size_t kCandidates = std::size(candidates);
  const QualityFigures wholeBefore = measureQualityFigures(*before.samples, *before.mesh);
  std::optional<RegionOptimisation> first;
  std::vector<CrossPassRule> tooSlow;  // rules whose full feeds already took longer
  for (std::size_t k = 0; k < kCandidates; ++k) {
    const auto& c = candidates[k];
    // Lower feeds can only take longer still.
    if (std::find(tooSlow.begin(), tooSlow.end(), c.rule) != tooSlow.end()) continue;
    RegionRequest candidate = request;
    candidate.options.feedScale = request.options.feedScale * c.share;
    candidate.options.crossPass = c.rule;
    RegionOptimisation r = evaluateCandidate(
        text, program, before, wholeBefore, machine, candidate,
        progressStage(progress, double(k) / kCandidates, double(k + 1) / kCandidates));
    r.plan = fmt::format("{}{}", c.rule == CrossPassRule::None     ? "each pass its own interval feeds"
                                 : c.rule == CrossPassRule::Median ? "interval feeds planned across passes (median)"
                                                                   : "interval feeds planned across passes (slowest)",
                         c.share < 1 ? fmt::format(", at {:.0f} %", 100 * c.share) : "");
    if (r.kept) {
      if (progress) progress(1.0);
      return r;
    }
    if (slower(r)) tooSlow.push_back(c.rule);
    if (!first) first = std::move(r);
  }
  if (progress) progress(1.0);
  return std::move(*first);
}

std::optional<std::string> worsening(const RegionOptimisation& r) {
  if (slower(r)) return fmt::format("the program would take longer ({:.3f} -> {:.3f} s)", r.timeBefore, r.timeAfter);
  // A region that cannot be measured after cannot be said to be no worse.
  if (r.regionBefore.samples > 0 && r.regionAfter.samples == 0) return std::string("the region has no surface after");
  if (const std::string worse = worseFigure(r.regionBefore, r.regionAfter, kWorseningAllowed); !worse.empty())
    return "in the region, " + worse;
  if (const std::string worse = worseFigure(r.wholeBefore, r.wholeAfter, kWorseningAllowed); !worse.empty())
    return "over the whole program, " + worse;
  return std::nullopt;
}

std::string regionSummary(const RegionOptimisation& r) {
  const QualityFigures &a = r.regionBefore, &b = r.regionAfter;
  return fmt::format(
      "lines {}-{}: {} passes re-fitted. Machining time {:.3f} -> {:.3f} s. In the region: speed fluctuation "
      "{:.1f} -> {:.1f} mm/min, inconsistency between passes p99 {:.1f} -> {:.1f} mm/min (mean {:.1f} -> {:.1f}), "
      "jerk p99 {:.0f} -> {:.0f} mm/s^3; path moved {:.4f} mm at most ({})",
      r.lines.first, r.lines.last, r.result.passes.size(), r.timeBefore, r.timeAfter, a.speedFluctuation,
      b.speedFluctuation, a.inconsistencyP99, b.inconsistencyP99, a.inconsistencyMean, b.inconsistencyMean, a.jerkP99,
      b.jerkP99, r.maxPathDistance, r.plan) +
         (r.kept ? "" : ". Not kept: " + r.reason + "; the program is left as it was");
}

}  // namespace isurface
