#include "isurface/optimise/taut_path.h"

#include <algorithm>

namespace isurface {

std::vector<Vec3> drawnTaut(const std::vector<Vec3>& points, double radius) {
  // Jacobi rounds of half a step toward the neighbours' middle, each point held in its ball: a
  // zig-zag (the shortest wavelength) is flattened in one round, longer waves more slowly, and
  // the balls stop it long before the relief itself is smoothed away.
  constexpr int kMostRounds = 100;
  constexpr double kSettled = 0.01;  // of the radius: a round that moves no point further ends
  std::vector<Vec3> taut = points;
  if (points.size() < 3 || !(radius > 0)) return taut;
  std::vector<Vec3> next = taut;
  for (int round = 0; round < kMostRounds; ++round) {
    double largestStep = 0;
    for (std::size_t k = 1; k + 1 < taut.size(); ++k) {
      Vec3 p = taut[k] + 0.5 * (0.5 * (taut[k - 1] + taut[k + 1]) - taut[k]);
      const Vec3 away = p - points[k];
      const double distance = away.norm();
      if (distance > radius) p = points[k] + away * (radius / distance);
      largestStep = std::max(largestStep, (p - taut[k]).norm());
      next[k] = p;
    }
    std::swap(taut, next);
    if (largestStep < kSettled * radius) break;
  }
  return taut;
}

}  // namespace isurface
