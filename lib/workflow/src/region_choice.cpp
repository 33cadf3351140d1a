// Choosing the region to re-optimise: the worst one, the one in a box, the whole program, the
// pass of a line; and the simulated run they are chosen on.
#include "isurface/workflow/region_optimisation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/analysis/quality_regions.h"
#include "surface_required.h"

namespace isurface {

SurfaceRun surfaceRun(std::shared_ptr<const Trajectory> samples, const Program* program, double gapLimit) {
  SurfaceRun run;
  PassOptions options;
  options.program = program;
  run.passes = splitPasses(*samples, options);
  MeshOptions mesh;
  mesh.gapLimit = gapLimit;
  run.mesh = std::make_shared<const SurfaceMesh>(buildSurfaceMesh(*samples, run.passes, mesh));
  run.gapLimit = gapLimit;
  run.samples = std::move(samples);
  return run;
}

void requireSurface(const SurfaceRun& run, const std::string& source) {
  if (!run.mesh->triangles.empty()) return;
  throw InputError(Diagnostic{source, 0, 0, whyNoTriangles(run.passes, run.gapLimit)});
}

namespace {

// Whether some sample of pass `k` has its neighbour on pass k - 1 within the gap limit (where the
// surface joins them).
bool joinedToPrevious(const SurfaceRun& run, std::size_t k) {
  const SurfaceMesh& mesh = *run.mesh;
  const Trajectory& t = *run.samples;
  for (std::size_t v = mesh.passFirstVertex[k]; v < mesh.passFirstVertex[k + 1]; ++v) {
    const std::uint32_t w = mesh.previousPassNeighbour[v];
    if (w == kNoVertex) continue;
    const std::size_t i = mesh.vertexSample[v], j = mesh.vertexSample[w];
    if (std::hypot(t.x[i] - t.x[j], t.y[i] - t.y[j], t.z[i] - t.z[j]) <= run.gapLimit) return true;
  }
  return false;
}

// The region's lines widened to every pass of a raster joined to its passes on the surface, one
// beside the next: a pass left as it was beside one re-planned runs at its old speeds beside the new ones,
// and that seam can make the whole program's passes disagree more than the region gains (on a
// raster whose fillet crosses every pass, the worst stretch of 9 of its 60 passes re-planned
// was turned down for that, all 60 were kept).
LineRange widenToJoinedPasses(const SurfaceRun& run, LineRange lines) {
  const std::vector<Pass>& passes = run.passes.passes;
  std::size_t first = passes.size(), last = 0;
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const LineRange r = linesOfPass(*run.samples, passes[k]);
    if (r.last < lines.first || r.first > lines.last) continue;
    first = std::min(first, k), last = std::max(last, k);
  }
  if (first > last || run.mesh->passFirstVertex.size() != passes.size() + 1) return lines;
  while (first > 0 && joinedToPrevious(run, first)) --first;
  while (last + 1 < passes.size() && joinedToPrevious(run, last + 1)) ++last;
  for (std::size_t k = first; k <= last; ++k) {
    const LineRange r = linesOfPass(*run.samples, passes[k]);
    if (r.first > r.last) continue;
    lines.first = std::min(lines.first, r.first), lines.last = std::max(lines.last, r.last);
  }
  return lines;
}

}  // namespace

ChosenRegion worstRegion(const SurfaceRun& run, const std::string& source) {
  requireSurface(run, source);
  const QualityReport report = findQualityRegions(*run.samples, *run.mesh);
  const QualityRegion* worst = worstRegionInsidePasses(report);
  if (!worst)
    throw InputError(Diagnostic{source, 0, 0,
                                report.regions.empty() ? "no region beyond the quality thresholds to optimise"
                                                       : "every region beyond the quality thresholds lies where passes start or end"});
  const LineRange lines{worst->firstLine, worst->lastLine};
  // A raster's passes cross the same features one after the other; loops around a part do not,
  // and re-planned all alike, those of samples/wuzhishan.nc deviated 6 % more in its worst
  // region than with its own passes re-planned.
  const LineRange own = widenToWholePasses(*run.samples, run.passes, lines);
  return {run.passes.pattern == PathPattern::DirectionParallel ? widenToJoinedPasses(run, lines) : own, worst->lower,
          worst->upper, worst->vertices, own};
}

namespace {

// The lines and the extent of the surface's samples inside a box (XY, mm).
ChosenRegion surfaceInside(const SurfaceRun& run, const Vec3& lower, const Vec3& upper) {
  const Trajectory& t = *run.samples;
  ChosenRegion region;
  region.lines = {std::numeric_limits<std::uint32_t>::max(), 0};
  region.lower = Vec3::Constant(std::numeric_limits<double>::infinity());
  region.upper = -region.lower;
  RunChannel<std::uint32_t>::Cursor lineOf = t.line.cursor();
  for (const std::uint32_t i : run.mesh->vertexSample) {
    const std::uint32_t line = lineOf[i];
    if (line == 0 || !insideBoxInPlan(t.x[i], t.y[i], lower, upper)) continue;
    const Vec3 p(t.x[i], t.y[i], t.z[i]);
    region.lines.first = std::min(region.lines.first, line);
    region.lines.last = std::max(region.lines.last, line);
    region.lower = region.lower.cwiseMin(p);
    region.upper = region.upper.cwiseMax(p);
    ++region.vertices;
  }
  return region;
}

}  // namespace

ChosenRegion regionInBox(const SurfaceRun& run, const Vec3& lower, const Vec3& upper, const std::string& source) {
  requireSurface(run, source);
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
  requireSurface(run, source);
  const Vec3 everywhere = Vec3::Constant(std::numeric_limits<double>::infinity());
  const ChosenRegion region = surfaceInside(run, -everywhere, everywhere);
  if (region.vertices == 0) throw InputError(Diagnostic{source, 0, 0, "no cutting passes to optimise"});
  return region;
}

std::optional<LineRange> passOfLine(const SurfaceRun& run, std::uint32_t line) {
  const Trajectory& t = *run.samples;
  for (const Pass& pass : run.passes.passes) {
    bool found = false;
    LineRange lines{~std::uint32_t(0), 0};
    t.line.forEachRun(pass.begin, pass.end, [&](std::uint32_t l, std::size_t, std::size_t) {
      found = found || l == line;
      if (l != 0) lines.first = std::min(lines.first, l), lines.last = std::max(lines.last, l);
    });
    if (found) return lines;
  }
  return std::nullopt;
}

}  // namespace isurface
