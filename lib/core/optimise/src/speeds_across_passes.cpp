#include "isurface/optimise/speeds_across_passes.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace isurface {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// A pass's moves by the cubes of side `reach` they pass through, to find those near a point
// without looking at all of them (a move within `reach` of a point passes through its cube or
// one of the 26 around it).
class MoveGrid {
 public:
  MoveGrid(const std::vector<Vec3>& points, double reach) : reach_(reach) {
    for (std::size_t j = 0; j + 1 < points.size(); ++j) add(points[j], points[j + 1], j);
  }

  // The moves in the cube holding p and the 26 around it: every move within `reach` of p.
  template <typename Visit>
  void near(const Vec3& p, Visit visit) const {
    const Cell c = cellOf(p);
    for (long x = c[0] - 1; x <= c[0] + 1; ++x)
      for (long y = c[1] - 1; y <= c[1] + 1; ++y)
        for (long z = c[2] - 1; z <= c[2] + 1; ++z) {
          const auto it = cells_.find(key({x, y, z}));
          if (it != cells_.end())
            for (const std::size_t j : it->second) visit(j);
        }
  }

 private:
  using Cell = std::array<long, 3>;

  // The cubes from a's to b's, one face crossed at a time (Amanatides and Woo's walk).
  void add(const Vec3& a, const Vec3& b, std::size_t j) {
    Cell cell = cellOf(a);
    const Cell last = cellOf(b);
    const Vec3 d = b - a;
    std::array<long, 3> step{};
    std::array<double, 3> nextFace{}, perCube{};  // along the move, 0..1
    for (int k = 0; k < 3; ++k) {
      step[k] = d[k] > 0 ? 1 : d[k] < 0 ? -1 : 0;
      nextFace[k] = perCube[k] = std::numeric_limits<double>::infinity();
      if (step[k] == 0) continue;
      nextFace[k] = ((double(cell[k]) + (step[k] > 0 ? 1 : 0)) * reach_ - a[k]) / d[k];
      perCube[k] = reach_ / std::fabs(d[k]);
    }
    cells_[key(cell)].push_back(j);
    for (long left = std::labs(last[0] - cell[0]) + std::labs(last[1] - cell[1]) + std::labs(last[2] - cell[2]); left > 0; --left) {
      const int k = nextFace[0] < nextFace[1] ? (nextFace[0] < nextFace[2] ? 0 : 2) : (nextFace[1] < nextFace[2] ? 1 : 2);
      cell[k] += step[k];
      nextFace[k] += perCube[k];
      cells_[key(cell)].push_back(j);
    }
    if (cell != last) cells_[key(last)].push_back(j);  // rounding at a face
  }

  Cell cellOf(const Vec3& p) const {
    return {long(std::floor(p.x() / reach_)), long(std::floor(p.y() / reach_)), long(std::floor(p.z() / reach_))};
  }
  static std::uint64_t key(const Cell& c) {
    auto part = [](long v) { return std::uint64_t(v + (1L << 20)) & ((1ULL << 21) - 1); };
    return part(c[0]) << 42 | part(c[1]) << 21 | part(c[2]);
  }
  double reach_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// The speed (mm/min) pass `q` runs at where it passes nearest `p`, interpolated along its move;
// kNone when none of its moves comes within `reach` (mm).
double speedNear(const Vec3& p, const FeedPerMove& q, const MoveGrid& grid, const std::vector<double>& speedAt, double reach) {
  double best = reach, speed = kNone;
  grid.near(p, [&](std::size_t j) {
    const Vec3 d = q.points[j + 1] - q.points[j];
    const double t = d.squaredNorm() > 0 ? std::clamp((p - q.points[j]).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const double distance = (q.points[j] + t * d - p).norm();
    if (distance < best) best = distance, speed = speedAt[j] + t * (speedAt[j + 1] - speedAt[j]);
  });
  return speed;
}

// mm/min at each point: the slower of the moves it joins.
std::vector<double> pointSpeeds(const FeedPerMove& pass) {
  std::vector<double> speed(pass.points.size(), kNone);
  for (std::size_t k = 0; k < pass.feeds.size(); ++k) {
    speed[k] = std::min(speed[k], pass.feeds[k]);
    speed[k + 1] = std::min(speed[k + 1], pass.feeds[k]);
  }
  return speed;
}

}  // namespace

std::vector<std::vector<double>> speedCapsAcrossPasses(const std::vector<FeedPerMove>& passes, const std::vector<double>& programmedFeeds,
                                                       const SpeedsAcrossPasses& rule) {
  // Each pass's speeds as held so far (its own to begin with): what its neighbours are held to.
  std::vector<std::vector<double>> held;
  std::vector<MoveGrid> grids;
  for (const FeedPerMove& pass : passes) held.push_back(pointSpeeds(pass)), grids.emplace_back(pass.points, rule.reach);
  std::vector<std::vector<double>> caps;
  for (const FeedPerMove& pass : passes) caps.emplace_back(pass.points.size(), kNone);
  auto feedOf = [&](std::size_t p) { return p < programmedFeeds.size() ? programmedFeeds[p] : 0.0; };
  // Forward, each pass held to the one before (already held to its own); then backward to the
  // one after: the cap of a point is then the least, over the passes, of their speed near it
  // plus a step for each pass between.
  auto holdTo = [&](std::size_t p, std::size_t q) {
    if (!(feedOf(p) > 0) || feedOf(p) != feedOf(q) || passes[q].feeds.empty()) return;
    const double step = rule.stepShare * feedOf(p);
    for (std::size_t i = 0; i < passes[p].points.size(); ++i) {
      // A point beside a neighbour is held to its own speed too (the slower of its two moves): the
      // pass re-ramped from its points then changes its feed a piece later on a ramp, as the
      // neighbours it is held to do, and the passes agree better (on the programs this was
      // developed on, the kept programs' inconsistency p99 fell by 70-93 % instead of 41-93 %,
      // for up to 0.3 % of the machining time).
      const double near = speedNear(passes[p].points[i], passes[q], grids[q], held[q], rule.reach);
      if (std::isfinite(near)) held[p][i] = caps[p][i] = std::min(held[p][i], near + step);
    }
  };
  for (std::size_t p = 1; p < passes.size(); ++p) holdTo(p, p - 1);
  for (std::size_t p = passes.size(); p-- > 1;) holdTo(p - 1, p);
  return caps;
}

}  // namespace isurface
