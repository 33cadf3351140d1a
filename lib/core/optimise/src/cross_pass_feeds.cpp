#include "isurface/optimise/cross_pass_feeds.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace isurface {

namespace {

constexpr double kCellsPerSpacing = 1.5;
constexpr double kSmallestCell = 0.05;  // mm: passes closer than this are one pass

// The typical distance between neighbouring passes (mm): for each pass, from its middle point
// to the nearest point of the pass before; the median of those.
double passSpacing(const std::vector<PassFeeds>& passes) {
  std::vector<double> gaps;
  for (std::size_t k = 1; k < passes.size(); ++k) {
    const std::vector<Vec3>& here = passes[k].points;
    const std::vector<Vec3>& before = passes[k - 1].points;
    if (here.empty() || before.empty()) continue;
    const Vec3& middle = here[here.size() / 2];
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec3& p : before) nearest = std::min(nearest, (p - middle).head<2>().norm());
    gaps.push_back(nearest);
  }
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

class FeedGrid {
 public:
  explicit FeedGrid(double cell) : cell_(cell) {}

  // The cells the polyline crosses, each once, in order (sampled at half a cell).
  std::vector<std::int64_t> cellsOf(const std::vector<Vec3>& points, std::size_t from, std::size_t to) const {
    std::vector<std::int64_t> cells;
    const auto add = [&](const Vec3& p) {
      const std::int64_t key = keyOf(p);
      if (std::find(cells.begin(), cells.end(), key) == cells.end()) cells.push_back(key);
    };
    add(points[from]);
    for (std::size_t i = from; i < to; ++i) {
      const Vec3 d = points[i + 1] - points[i];
      const int steps = static_cast<int>(std::ceil(d.head<2>().norm() / (0.5 * cell_)));
      for (int s = 1; s <= steps; ++s) add(points[i] + d * (double(s) / steps));
    }
    return cells;
  }

  void add(std::int64_t key, double feed) { cells_[key].push_back(feed); }

  // The feeds of a cell and the eight around it.
  std::vector<double> feedsAround(std::int64_t key) const {
    const auto bits = static_cast<std::uint64_t>(key);
    const std::int64_t ix = static_cast<std::int32_t>(bits >> 32), iy = static_cast<std::int32_t>(bits & 0xffffffffu);
    std::vector<double> feeds;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(keyOf(ix + dx, iy + dy));
        if (it != cells_.end()) feeds.insert(feeds.end(), it->second.begin(), it->second.end());
      }
    return feeds;
  }

 private:
  // Cell indices packed as two 32-bit halves (a part is far smaller than 2^31 cells).
  static std::int64_t keyOf(std::int64_t ix, std::int64_t iy) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(ix) << 32) | (static_cast<std::uint64_t>(iy) & 0xffffffffu));
  }
  std::int64_t keyOf(const Vec3& p) const {
    return keyOf(static_cast<std::int64_t>(std::floor(p.x() / cell_)), static_cast<std::int64_t>(std::floor(p.y() / cell_)));
  }

  double cell_;
  std::unordered_map<std::int64_t, std::vector<double>> cells_;
};

double ruleValue(std::vector<double>& feeds, CrossPassRule rule) {
  if (rule == CrossPassRule::Envelope) return *std::min_element(feeds.begin(), feeds.end());
  std::nth_element(feeds.begin(), feeds.begin() + static_cast<std::ptrdiff_t>(feeds.size() / 2), feeds.end());
  return feeds[feeds.size() / 2];
}

}  // namespace

void harmonizeFeedsAcrossPasses(std::vector<PassFeeds>& passes, CrossPassRule rule) {
  if (rule == CrossPassRule::None || passes.size() < 2) return;
  const double spacing = passSpacing(passes);
  if (!(spacing > 0) || !std::isfinite(spacing)) return;
  FeedGrid grid(std::max(kSmallestCell, kCellsPerSpacing * spacing));
  // The cells of every interval, kept for the second walk.
  std::vector<std::vector<std::vector<std::int64_t>>> cellsOf(passes.size());
  for (std::size_t p = 0; p < passes.size(); ++p) {
    const PassFeeds& pass = passes[p];
    for (std::size_t i = 0; i < pass.feeds.size() && i < pass.intervalEnd.size(); ++i) {
      const std::size_t from = i == 0 ? 0 : pass.intervalEnd[i - 1];
      cellsOf[p].push_back(grid.cellsOf(pass.points, from, pass.intervalEnd[i]));
      for (const std::int64_t key : cellsOf[p].back()) grid.add(key, pass.feeds[i]);
    }
  }
  std::unordered_map<std::int64_t, double> value;
  for (std::size_t p = 0; p < passes.size(); ++p)
    for (std::size_t i = 0; i < cellsOf[p].size(); ++i) {
      double feed = passes[p].feeds[i];
      for (const std::int64_t key : cellsOf[p][i]) {
        auto it = value.find(key);
        if (it == value.end()) {
          std::vector<double> around = grid.feedsAround(key);
          it = value.emplace(key, ruleValue(around, rule)).first;
        }
        feed = std::min(feed, it->second);
      }
      passes[p].feeds[i] = feed;
    }
}

}  // namespace isurface
