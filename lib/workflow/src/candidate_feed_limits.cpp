#include "candidate_feed_limits.h"

#include <algorithm>
#include <cmath>

#include "isurface/analysis/quantities.h"

namespace isurface {

namespace {

// Of a faster run's samples, the shares whose speed caps the feed of the next candidates.
constexpr double kSpeedPeakShares[] = {0.01, 0.1, 0.3, 0.5};
constexpr double kSlowestCap = 1.0;  // mm/min: a feed floored below it would be F0

}  // namespace

std::vector<double> deviationCeilings(const RegionOptimisation& r, double targetUm, std::vector<double> previous) {
  constexpr double kMargin = 0.97;
  const Trajectory& t = *r.after.samples;
  const std::vector<float> deviation = vertexQuantity(Quantity::Deviation, t, *r.after.mesh);
  std::vector<double> worst;  // um per new line
  RunChannel<std::uint32_t>::Cursor lineOf = t.line.cursor();
  for (std::size_t v = 0; v < deviation.size(); ++v) {
    const std::uint32_t line = lineOf[r.after.mesh->vertexSample[v]];
    if (line == 0 || !std::isfinite(deviation[v])) continue;
    if (line >= worst.size()) worst.resize(line + 1, 0.0);
    worst[line] = std::max(worst[line], double(std::fabs(deviation[v])));
  }
  std::vector<double> feedOfLine;  // mm/min per new line
  for (const Move& m : r.program->moves) {
    if (m.line >= feedOfLine.size()) feedOfLine.resize(m.line + 1, 0.0);
    feedOfLine[m.line] = m.feed;
  }
  for (const OptimizedPass& pass : r.result.passes)
    for (std::size_t k = 0; k < pass.sourceLines.size(); ++k) {
      const std::size_t line = pass.newFirstLine + 1 + k;  // after the pass's comment line
      const std::uint32_t source = pass.sourceLines[k];
      if (line >= worst.size() || line >= feedOfLine.size() || worst[line] <= targetUm || source == 0) continue;
      const double ceiling = kMargin * feedOfLine[line] * std::sqrt(targetUm / worst[line]);
      if (source >= previous.size()) previous.resize(source + 1, 0.0);
      if (previous[source] == 0 || ceiling < previous[source]) previous[source] = ceiling;
    }
  return previous;
}

std::vector<double> speedPeakCaps(const RegionOptimisation& r) {
  const Trajectory& t = *r.after.samples;
  const std::vector<float> speed = vertexQuantity(Quantity::Speed, t, *r.after.mesh);
  const LineRange& lines = r.result.newRange;
  RunChannel<std::uint32_t>::Cursor lineOf = t.line.cursor();
  std::vector<float> inRegion;
  for (std::size_t v = 0; v < speed.size(); ++v) {
    const std::uint32_t line = lineOf[r.after.mesh->vertexSample[v]];
    if (line >= lines.first && line <= lines.last && std::isfinite(speed[v])) inRegion.push_back(speed[v]);
  }
  double highestFeed = 0;  // mm/min, programmed in the region
  for (const Move& m : r.program->moves)
    if (m.kind == MoveKind::Linear && m.line >= lines.first && m.line <= lines.last) highestFeed = std::max(highestFeed, double(m.feed));
  std::vector<double> caps;
  for (const double share : kSpeedPeakShares) {
    if (inRegion.empty()) break;
    const auto at = inRegion.begin() + static_cast<std::ptrdiff_t>((1.0 - share) * double(inRegion.size() - 1));
    std::nth_element(inRegion.begin(), at, inRegion.end());
    if (*at < 0.99 * highestFeed && *at >= kSlowestCap) caps.push_back(*at);
  }
  return caps;
}

}  // namespace isurface
