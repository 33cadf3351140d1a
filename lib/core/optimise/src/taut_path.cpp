#include "isurface/optimise/taut_path.h"

#include <algorithm>

namespace isurface {

std::vector<Vec3> drawnTaut(const std::vector<Vec3>& points, double radius) {
  // A few Jacobi rounds of half a step toward the neighbours' chord, each point held in its
  // ball: a zig-zag (the shortest wavelength) is flattened in the first round, the next let
  // neighbouring points held by their balls settle, and a longer wave (the relief's own shape)
  // moves by a fraction of a micrometre a round, so it is kept.
  constexpr int kRounds = 3;
  std::vector<Vec3> taut = points;
  if (points.size() < 3 || !(radius > 0)) return taut;
  std::vector<Vec3> next = taut;
  for (int round = 0; round < kRounds; ++round) {
    for (std::size_t k = 1; k + 1 < taut.size(); ++k) {
      // Toward the point of the chord between its neighbours at the same share of their
      // distance: the middle of the chord would also slide a point of unevenly spaced ones
      // along the path, spending its tube on a move that straightens nothing.
      const double before = (taut[k] - taut[k - 1]).norm(), after = (taut[k + 1] - taut[k]).norm();
      const double share = before + after > 0 ? before / (before + after) : 0.5;
      const Vec3 onChord = taut[k - 1] + share * (taut[k + 1] - taut[k - 1]);
      Vec3 p = taut[k] + 0.5 * (onChord - taut[k]);
      const Vec3 away = p - points[k];
      const double distance = away.norm();
      if (distance > radius) p = points[k] + away * (radius / distance);
      next[k] = p;
    }
    std::swap(taut, next);
  }
  return taut;
}

}  // namespace isurface
