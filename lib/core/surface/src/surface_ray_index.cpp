// A uniform grid of triangles, walked cell by cell along a ray (Amanatides and Woo's traversal).
#include "isurface/surface/surface_ray_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isurface {

namespace {

constexpr int kMaxCellsPerAxis = 4096;
constexpr std::size_t kMaxCells = std::size_t{1} << 26;

// Möller and Trumbore: the ray parameter where origin + t * direction meets the triangle, if it
// does; edges count as inside so that a ray between two triangles does not fall through.
std::optional<double> meetTriangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b,
                                   const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 p = direction.cross(ac);
  const double det = ab.dot(p);
  if (std::fabs(det) < 1e-300) return std::nullopt;  // the ray runs in the triangle's plane, or a degenerate triangle
  const double inverse = 1.0 / det;
  const Vec3 s = origin - a;
  const double u = s.dot(p) * inverse;
  constexpr double kEdge = 1e-9;
  if (u < -kEdge || u > 1 + kEdge) return std::nullopt;
  const Vec3 q = s.cross(ab);
  const double v = direction.dot(q) * inverse;
  if (v < -kEdge || u + v > 1 + kEdge) return std::nullopt;
  const double t = ac.dot(q) * inverse;
  if (t < 0) return std::nullopt;
  return t;
}

}  // namespace

SurfaceRayIndex::SurfaceRayIndex(const std::vector<Vec3>& positions, std::shared_ptr<const SurfaceMesh> meshShared)
    : mesh_(std::move(meshShared)) {
  if (!mesh_ || mesh_->triangles.empty() || positions.empty()) return;
  const SurfaceMesh& mesh = *mesh_;
  positions_.reserve(positions.size());
  for (const Vec3& p : positions) positions_.push_back(p.cast<float>());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Point& p : positions_) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  if (!(lo.array() <= hi.array()).all()) return;  // no finite position
  // A flat surface has no extent in Z: give every axis a little, so that cells stay boxes.
  Vec3 extent = hi - lo;
  const double floor = std::max(extent.maxCoeff() * 1e-3, 1e-6);
  for (int a = 0; a < 3; ++a)
    if (extent[a] < floor) {
      lo[a] -= 0.5 * (floor - extent[a]);
      extent[a] = floor;
    }
  // About two triangles a cell.
  const double cells = std::max(1.0, static_cast<double>(mesh.triangles.size()) / 2.0);
  const double side = std::cbrt(extent.prod() / cells);
  std::size_t total = 1;
  for (int a = 0; a < 3; ++a) {
    dims_[a] = static_cast<int>(std::clamp(std::ceil(extent[a] / side), 1.0, static_cast<double>(kMaxCellsPerAxis)));
    total *= static_cast<std::size_t>(dims_[a]);
  }
  while (total > kMaxCells) {  // only with extreme aspect ratios: halve the finest axis
    const int a = static_cast<int>(std::max_element(dims_.begin(), dims_.end()) - dims_.begin());
    total = total / static_cast<std::size_t>(dims_[a]) * static_cast<std::size_t>((dims_[a] + 1) / 2);
    dims_[a] = (dims_[a] + 1) / 2;
  }
  lower_ = lo;
  for (int a = 0; a < 3; ++a) cellSize_[a] = extent[a] / dims_[a];

  // Counting sort of (cell, triangle) pairs: counts, then each cell's start, then the ids.
  std::vector<std::uint64_t> start(total + 1, 0);
  std::array<int, 3> from{}, to{};
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!triangleBounds(t, from, to)) continue;
    for (int k = from[2]; k <= to[2]; ++k)
      for (int j = from[1]; j <= to[1]; ++j)
        for (int i = from[0]; i <= to[0]; ++i) ++start[cellOf(i, j, k) + 1];
  }
  for (std::size_t c = 0; c < total; ++c) start[c + 1] += start[c];
  if (start[total] > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("surface too large to index for picking (over 4 G cell entries)");
  entries_.resize(start[total]);
  std::vector<std::uint64_t> next(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!triangleBounds(t, from, to)) continue;
    for (int k = from[2]; k <= to[2]; ++k)
      for (int j = from[1]; j <= to[1]; ++j)
        for (int i = from[0]; i <= to[0]; ++i) entries_[next[cellOf(i, j, k)]++] = t;
  }
  cellStart_.assign(start.begin(), start.end());
}

int SurfaceRayIndex::clampedCell(int axis, double coordinate) const {
  const double cell = std::floor((coordinate - lower_[axis]) / cellSize_[axis]);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(dims_[axis] - 1)));
}

bool SurfaceRayIndex::triangleBounds(std::uint32_t t, std::array<int, 3>& lo, std::array<int, 3>& hi) const {
  const auto& tri = mesh_->triangles[t];
  for (std::uint32_t v : tri)
    if (v >= positions_.size()) return false;
  const Vec3 a = positions_[tri[0]].cast<double>(), b = positions_[tri[1]].cast<double>(),
             c = positions_[tri[2]].cast<double>();
  if (!a.allFinite() || !b.allFinite() || !c.allFinite()) return false;
  const Vec3 low = a.cwiseMin(b).cwiseMin(c), high = a.cwiseMax(b).cwiseMax(c);
  for (int axis = 0; axis < 3; ++axis) {
    lo[axis] = clampedCell(axis, low[axis]);
    hi[axis] = clampedCell(axis, high[axis]);
  }
  return true;
}

std::optional<SurfaceHit> SurfaceRayIndex::firstHit(const Vec3& origin, const Vec3& through) const {
  if (entries_.empty()) return std::nullopt;
  const Vec3 direction = through - origin;
  if (!direction.allFinite() || direction.squaredNorm() == 0) return std::nullopt;
  // Where the ray is inside the grid's box (slabs).
  double enter = 0, leave = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double upper = lower_[a] + cellSize_[a] * dims_[a];
    if (direction[a] == 0) {
      if (origin[a] < lower_[a] || origin[a] > upper) return std::nullopt;
      continue;
    }
    double t0 = (lower_[a] - origin[a]) / direction[a], t1 = (upper - origin[a]) / direction[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  if (enter > leave) return std::nullopt;

  const Vec3 start = origin + enter * direction;
  std::array<int, 3> cell{}, step{};
  Vec3 nextBoundary, delta;  // ray parameter of the next cell boundary on each axis, and between boundaries
  for (int a = 0; a < 3; ++a) {
    cell[a] = clampedCell(a, start[a]);
    if (direction[a] > 0) {
      step[a] = 1;
      nextBoundary[a] = (lower_[a] + (cell[a] + 1) * cellSize_[a] - origin[a]) / direction[a];
      delta[a] = cellSize_[a] / direction[a];
    } else if (direction[a] < 0) {
      step[a] = -1;
      nextBoundary[a] = (lower_[a] + cell[a] * cellSize_[a] - origin[a]) / direction[a];
      delta[a] = -cellSize_[a] / direction[a];
    } else {
      step[a] = 0;
      nextBoundary[a] = delta[a] = std::numeric_limits<double>::infinity();
    }
  }

  double best = std::numeric_limits<double>::infinity();
  std::uint32_t bestTriangle = 0;
  for (;;) {
    const std::size_t c = cellOf(cell[0], cell[1], cell[2]);
    for (std::uint32_t e = cellStart_[c]; e < cellStart_[c + 1]; ++e) {
      const auto& tri = mesh_->triangles[entries_[e]];
      const auto t = meetTriangle(origin, direction, positions_[tri[0]].cast<double>(),
                                  positions_[tri[1]].cast<double>(), positions_[tri[2]].cast<double>());
      if (t && *t < best) {
        best = *t;
        bestTriangle = entries_[e];
      }
    }
    int axis = 0;
    if (nextBoundary[1] < nextBoundary[axis]) axis = 1;
    if (nextBoundary[2] < nextBoundary[axis]) axis = 2;
    // A triangle met before this cell's far side cannot be hidden by one in a later cell.
    if (best <= nextBoundary[axis] || nextBoundary[axis] > leave) break;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= dims_[axis]) break;
    nextBoundary[axis] += delta[axis];
  }
  if (!std::isfinite(best)) return std::nullopt;
  return SurfaceHit{origin + best * direction, bestTriangle};
}

std::size_t sampleAtHit(const Trajectory& samples, const SurfaceMesh& mesh, const SurfaceHit& hit) {
  const auto& tri = mesh.triangles.at(hit.triangle);
  std::size_t best = mesh.vertexSample.at(tri[0]);
  double bestDistance = std::numeric_limits<double>::infinity();
  const std::size_t vertices = mesh.vertexSample.size();
  for (std::uint32_t v : tri) {
    const bool before = v > 0 && mesh.vertexPass[v - 1] == mesh.vertexPass[v];
    const bool after = v + 1 < vertices && mesh.vertexPass[v + 1] == mesh.vertexPass[v];
    std::size_t lo = mesh.vertexSample[before ? v - 1 : v], hi = mesh.vertexSample[after ? v + 1 : v];
    if (lo > hi) std::swap(lo, hi);
    hi = std::min(hi, samples.size() - 1);
    for (std::size_t s = lo; s <= hi; ++s) {
      const double d = (hit.point - Vec3(samples.x[s], samples.y[s], samples.z[s])).squaredNorm();
      if (d < bestDistance) {
        bestDistance = d;
        best = s;
      }
    }
  }
  return best;
}

}  // namespace isurface
