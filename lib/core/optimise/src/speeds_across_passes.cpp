#include "isurface/optimise/speeds_across_passes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace isurface {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// A pass's points in order along the axis (X or Y) it spans most, to find those near a point.
struct PassIndex {
  int axis = 0;
  std::vector<std::size_t> order;  // point indices, by their coordinate on `axis`
  std::vector<double> along;       // that coordinate, sorted
};

PassIndex indexOf(const std::vector<Vec3>& points) {
  PassIndex index;
  if (points.empty()) return index;
  Vec3 lower = points.front(), upper = points.front();
  for (const Vec3& p : points) lower = lower.cwiseMin(p), upper = upper.cwiseMax(p);
  index.axis = upper.y() - lower.y() > upper.x() - lower.x() ? 1 : 0;
  index.order.resize(points.size());
  std::iota(index.order.begin(), index.order.end(), std::size_t{0});
  std::sort(index.order.begin(), index.order.end(),
            [&](std::size_t a, std::size_t b) { return points[a][index.axis] < points[b][index.axis]; });
  for (const std::size_t i : index.order) index.along.push_back(points[i][index.axis]);
  return index;
}

// The speed (mm/min) pass `q` runs at where it passes nearest `p`, interpolated along its move;
// kNone when no move of it within `reach` (mm) has an end within `reach` along its axis.
double speedNear(const Vec3& p, const FeedPerMove& q, const PassIndex& index, const std::vector<double>& speedAt, double reach) {
  const auto from = std::lower_bound(index.along.begin(), index.along.end(), p[index.axis] - reach);
  const auto to = std::upper_bound(index.along.begin(), index.along.end(), p[index.axis] + reach);
  double best = reach, speed = kNone;
  for (auto it = from; it != to; ++it) {
    const std::size_t i = index.order[std::size_t(it - index.along.begin())];
    for (const std::size_t j : {i > 0 ? i - 1 : i, i}) {  // the moves ending and starting at point i
      if (j + 1 >= q.points.size()) continue;
      const Vec3 d = q.points[j + 1] - q.points[j];
      const double t = d.squaredNorm() > 0 ? std::clamp((p - q.points[j]).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      const double distance = (q.points[j] + t * d - p).norm();
      if (distance < best) best = distance, speed = speedAt[j] + t * (speedAt[j + 1] - speedAt[j]);
    }
  }
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

std::vector<std::vector<double>> speedCapsAcrossPasses(const std::vector<FeedPerMove>& passes, const SpeedsAcrossPasses& rule) {
  std::vector<std::vector<double>> caps;
  std::vector<PassIndex> indices;
  for (const FeedPerMove& pass : passes) caps.push_back(pointSpeeds(pass)), indices.push_back(indexOf(pass.points));
  // Forward, each pass held to the one before (already held to its own); then backward to the
  // one after: the cap of a point is then the least, over the passes, of their speed near it
  // plus a step for each pass between.
  auto holdTo = [&](std::size_t p, std::size_t q) {
    for (std::size_t i = 0; i < passes[p].points.size(); ++i) {
      const double near = speedNear(passes[p].points[i], passes[q], indices[q], caps[q], rule.reach);
      if (std::isfinite(near)) caps[p][i] = std::min(caps[p][i], near + rule.step);
    }
  };
  for (std::size_t p = 1; p < passes.size(); ++p) holdTo(p, p - 1);
  for (std::size_t p = passes.size(); p-- > 1;) holdTo(p - 1, p);
  return caps;
}

}  // namespace isurface
