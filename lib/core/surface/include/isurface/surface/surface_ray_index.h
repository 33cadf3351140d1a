#pragma once
// Where a ray first meets the cutter-location surface: a uniform grid of the mesh's triangles,
// built once, so that a pick costs the few cells the ray crosses, not the whole surface.
// About 10 bytes a triangle (32-bit triangle ids sorted by cell, and each cell's first entry)
// and 12 a vertex (its position in single precision: picking needs no finer than 0.01 um).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/surface/surface_mesh.h"

namespace isurface {

struct SurfaceHit {
  Vec3 point;              // mm
  std::uint32_t triangle;  // index into the mesh's triangles
};

class SurfaceRayIndex {
 public:
  // `positions`: mm, one per mesh vertex.
  SurfaceRayIndex(const std::vector<Vec3>& positions, std::shared_ptr<const SurfaceMesh> mesh);

  // The first triangle along the ray from `origin` towards `through` (both mm; the ray goes on
  // beyond `through`), or none.
  std::optional<SurfaceHit> firstHit(const Vec3& origin, const Vec3& through) const;

  const SurfaceMesh& mesh() const { return *mesh_; }
  std::size_t bytes() const {
    return (cellStart_.capacity() + entries_.capacity()) * sizeof(std::uint32_t) + positions_.capacity() * sizeof(Point);
  }

 private:
  std::size_t cellOf(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims_[1] + static_cast<std::size_t>(j)) * dims_[0] + static_cast<std::size_t>(i);
  }
  int clampedCell(int axis, double coordinate) const;
  bool triangleBounds(std::uint32_t t, std::array<int, 3>& lo, std::array<int, 3>& hi) const;

  using Point = Eigen::Vector3f;
  std::vector<Point> positions_;
  std::shared_ptr<const SurfaceMesh> mesh_;
  Vec3 lower_ = Vec3::Zero(), cellSize_ = Vec3::Ones();  // mm
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::uint32_t> cellStart_;  // entries of cell c: [cellStart_[c], cellStart_[c + 1])
  std::vector<std::uint32_t> entries_;    // triangle ids
};

// The sample a hit on the surface stands for: the nearest (commanded position) among the
// samples the hit triangle's vertices stand for (a thinned mesh's vertex stands for the samples
// up to its neighbours on its pass).
std::size_t sampleAtHit(const Trajectory& samples, const SurfaceMesh& mesh, const SurfaceHit& hit);

}  // namespace isurface
