// Choosing the region to re-optimise: the worst one, the one in a box, the whole program, the
// pass of a line; and the simulated run they are chosen on.
#include "isurface/workflow/region_optimisation.h"

#include <fmt/format.h>

#include <algorithm>
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

ChosenRegion worstRegion(const SurfaceRun& run, const std::string& source) {
  requireSurface(run, source);
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
