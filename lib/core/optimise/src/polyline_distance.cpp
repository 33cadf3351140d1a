#include "isurface/optimise/polyline_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

namespace isurface {

namespace {

struct Nearest {
  double distance = INFINITY;  // mm
  std::size_t segment = 0;     // from point `segment` to `segment + 1`
};

// The nearest of the segments lo..hi-1 of the polyline.
Nearest nearestAmong(const Vec3& p, const std::vector<Vec3>& to, std::size_t lo, std::size_t hi) {
  Nearest best;
  for (std::size_t k = lo; k + 1 < hi; ++k) {
    const double d = distanceToSegment(p, to[k], to[k + 1]);
    if (d < best.distance) best = {d, k};
  }
  return best;
}

// A polyline's segments in a grid of cubes, each segment entered in every cell that a piece of
// it no longer than a cell reaches: a segment nearer to p than r lies in a cell that the cube
// p +- r reaches. Built only for paths that stray from each other (most points of a re-fitted
// path are found near the last one's match without it).
class SegmentGrid {
 public:
  explicit SegmentGrid(const std::vector<Vec3>& to) : to_(to) {
    std::vector<double> lengths;
    double total = 0;  // mm
    for (std::size_t k = 0; k + 1 < to.size(); ++k) {
      const double length = (to[k + 1] - to[k]).norm();
      if (!std::isfinite(length)) continue;
      lengths.push_back(length);
      total += length;
    }
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    // A cell as long as a typical segment, but never so small that a long move among short
    // ones is cut into more pieces than the path has points a few times over.
    cell_ = std::max({lengths.empty() ? 1.0 : lengths[lengths.size() / 2], kSmallestCell,
                      total / double(kPiecesPerPoint * to.size())});
    for (std::size_t k = 0; k + 1 < to.size(); ++k) enter(k);
    std::sort(entries_.begin(), entries_.end());
    entries_.erase(std::unique(entries_.begin(), entries_.end()), entries_.end());
  }

  // The nearest segment nearer than `within`, nullopt when the cube p +- within reaches too
  // many cells to be worth it (the caller then looks at every segment).
  std::optional<Nearest> nearestWithin(const Vec3& p, double within) const {
    Nearest best{within, 0};
    long long lo[3], hi[3];
    double cells = 1;
    for (int ax = 0; ax < 3; ++ax) {
      lo[ax] = index(p[ax] - within);
      hi[ax] = index(p[ax] + within);
      cells *= double(hi[ax] - lo[ax] + 1);
    }
    if (!(cells <= kMostCellsLookedAt)) return std::nullopt;
    for (long long x = lo[0]; x <= hi[0]; ++x)
      for (long long y = lo[1]; y <= hi[1]; ++y)
        for (long long z = lo[2]; z <= hi[2]; ++z) {
          const std::uint64_t k = key(x, y, z);
          auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(k, std::uint32_t{0}));
          for (; it != entries_.end() && it->first == k; ++it) {
            const double d = distanceToSegment(p, to_[it->second], to_[it->second + 1]);
            if (d < best.distance) best = {d, it->second};
          }
        }
    return best;
  }

 private:
  static constexpr double kSmallestCell = 1e-3;        // mm
  static constexpr double kMostCellsLookedAt = 4096;
  static constexpr std::size_t kPiecesPerPoint = 4;

  // Clamped so that no coordinate, however far out, overflows the conversion.
  long long index(double v) const { return static_cast<long long>(std::clamp(std::floor(v / cell_), -1e18, 1e18)); }
  static std::uint64_t key(long long x, long long y, long long z) {
    // 21 bits an axis (wrapping: two cells far apart may share a key, which costs a distance
    // computed for nothing, never a segment missed).
    const auto bits = [](long long v) { return static_cast<std::uint64_t>(v) & 0x1FFFFF; };
    return bits(x) << 42 | bits(y) << 21 | bits(z);
  }
  void enter(std::size_t k) {
    const Vec3 a = to_[k], d = to_[k + 1] - to_[k];
    if (!a.allFinite() || !d.allFinite()) return;
    const std::size_t pieces = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(d.norm() / cell_)));
    for (std::size_t j = 0; j < pieces; ++j) {
      const Vec3 from = a + d * (double(j) / double(pieces)), to = a + d * (double(j + 1) / double(pieces));
      for (long long x = index(std::min(from.x(), to.x())); x <= index(std::max(from.x(), to.x())); ++x)
        for (long long y = index(std::min(from.y(), to.y())); y <= index(std::max(from.y(), to.y())); ++y)
          for (long long z = index(std::min(from.z(), to.z())); z <= index(std::max(from.z(), to.z())); ++z)
            entries_.emplace_back(key(x, y, z), static_cast<std::uint32_t>(k));
    }
  }

  const std::vector<Vec3>& to_;
  double cell_ = 1;                                          // mm
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries_;  // (cell, segment), sorted
};

// Largest distance from a point of `from` to the polyline `to`.
double oneWay(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  if (to.size() == 1) {
    double worst = 0;
    for (const Vec3& p : from) worst = std::max(worst, (to[0] - p).norm());
    return worst;
  }
  // Paths that run the same way: a point's nearest segment is mostly near the last one's.
  constexpr std::size_t kBehind = 50, kAhead = 500;
  constexpr double kSurelyNearest = 1e-3;  // mm: nearer than this, the window's answer stands
  std::optional<SegmentGrid> grid;
  double worst = 0;
  std::size_t near = 0;
  for (const Vec3& p : from) {
    Nearest best = nearestAmong(p, to, near > kBehind ? near - kBehind : 0, std::min(to.size(), near + kAhead));
    if (!(best.distance <= kSurelyNearest)) {
      if (!grid) grid.emplace(to);
      const std::optional<Nearest> found =
          std::isfinite(best.distance) ? grid->nearestWithin(p, best.distance) : std::nullopt;
      if (found) {
        if (found->distance < best.distance) best = *found;
      } else {
        best = nearestAmong(p, to, 0, to.size());
      }
    }
    near = best.segment;
    worst = std::max(worst, best.distance);
  }
  return worst;
}

}  // namespace

double polylineDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.empty() || b.empty()) return 0;
  return std::max(oneWay(a, b), oneWay(b, a));
}

}  // namespace isurface
