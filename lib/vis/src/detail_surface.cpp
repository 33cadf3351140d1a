#include "isurface/vis/detail_surface.h"

#include <algorithm>

namespace isurface::vis {

PassSet passesInBox(const Trajectory& samples, const PassSet& passes, const Vec3& lower, const Vec3& upper,
                    bool feedback) {
  const auto inside = [&](std::size_t i) {
    const Vec3 p = feedback ? samples.feedback(i) : samples.commanded(i);
    return p.x() >= lower.x() && p.x() <= upper.x() && p.y() >= lower.y() && p.y() <= upper.y();
  };
  PassSet out;
  out.pattern = passes.pattern;
  for (const Pass& pass : passes.passes) {
    std::size_t first = pass.end, last = pass.begin;
    for (std::size_t i = pass.begin; i < pass.end; ++i) {
      if (!inside(i)) continue;
      first = std::min(first, i);
      last = i;
    }
    // Two samples at least: a pass of one point makes no triangle.
    if (first < pass.end && last > first) out.passes.push_back(Pass{first, last + 1});
  }
  return out;
}

std::optional<DetailSurface> buildDetailSurface(const Trajectory& samples, const PassSet& passes,
                                                const QualityMapRequest& request, const Vec3& lower, const Vec3& upper) {
  const PassSet inBox = passesInBox(samples, passes, lower, upper, request.feedbackSurface);
  if (inBox.passes.empty()) return std::nullopt;
  DetailSurface detail;
  detail.lower = lower;
  detail.upper = upper;
  detail.stride = strideWithin(inBox, request.maxVertices);
  MeshOptions options;
  options.feedback = request.feedbackSurface;
  options.gapLimit = request.gapLimit;
  options.stride = detail.stride;
  auto mesh = std::make_shared<SurfaceMesh>(buildSurfaceMesh(samples, inBox, options));
  if (mesh->triangles.empty()) return std::nullopt;
  detail.positions = meshPositions(samples, *mesh, request.feedbackSurface);
  detail.scalars = vertexValuesShown(request, samples, *mesh);
  detail.mesh = std::move(mesh);
  return detail;
}

}  // namespace isurface::vis
