#include "isurface/surface/coarse_mesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace isurface {

namespace {

constexpr std::size_t kLengthProbes = 64;  // points a pass's length is measured through

// A pass's length along its path (mm), from a few of its samples.
double passLength(const Trajectory& t, const Pass& pass) {
  if (pass.size() < 2) return 0.0;
  double length = 0;
  std::size_t previous = pass.begin;
  for (std::size_t k = 1; k <= kLengthProbes; ++k) {
    const std::size_t i = pass.begin + (pass.size() - 1) * k / kLengthProbes;
    const double step = (t.commanded(i) - t.commanded(previous)).norm();
    if (std::isfinite(step)) length += step;
    previous = i;
  }
  return length;
}

// The typical distance between neighbouring passes (mm): from the middle of each pass to the
// middle of the next, the median.
double passSpacing(const Trajectory& t, const std::vector<Pass>& passes) {
  std::vector<double> gaps;
  for (std::size_t k = 1; k < passes.size(); ++k) {
    if (passes[k - 1].size() == 0 || passes[k].size() == 0) continue;
    const Vec3 a = t.commanded(passes[k - 1].begin + passes[k - 1].size() / 2);
    const Vec3 b = t.commanded(passes[k].begin + passes[k].size() / 2);
    const double gap = (b - a).norm();
    if (std::isfinite(gap)) gaps.push_back(gap);
  }
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

}  // namespace

SurfaceMesh buildCoarseSurfaceMesh(const Trajectory& samples, const PassSet& passes, MeshOptions options,
                                   std::size_t vertexBudget) {
  const std::vector<Pass>& all = passes.passes;
  double along = 0;
  for (const Pass& p : all) along += passLength(samples, p);
  vertexBudget = std::max<std::size_t>(vertexBudget, 1);
  std::size_t passStep = 1;
  if (!all.empty() && along > 0) {
    along /= double(all.size());
    const double across = passSpacing(samples, all) * double(all.size());
    // Rows (passes kept) and columns (vertices a pass) in the proportion of the surface's sides.
    const double rows = std::sqrt(double(vertexBudget) * across / along);
    if (rows > 0 && std::isfinite(rows))
      passStep = std::clamp<std::size_t>(static_cast<std::size_t>(std::floor(double(all.size()) / rows)), 1,
                                         std::max<std::size_t>(1, all.size() / 4));
  }
  PassSet kept;
  kept.pattern = passes.pattern;
  std::size_t keptSamples = 0;
  for (std::size_t k = 0; k < all.size(); k += passStep) kept.passes.push_back(all[k]), keptSamples += all[k].size();
  if (!all.empty() && (all.size() - 1) % passStep != 0) kept.passes.push_back(all.back()), keptSamples += all.back().size();  // the far edge
  options.gapLimit *= double(passStep);
  options.stride = std::max<std::size_t>(1, (keptSamples + vertexBudget - 1) / vertexBudget);
  return buildSurfaceMesh(samples, kept, options);
}

}  // namespace isurface
