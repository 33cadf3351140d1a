#include "candidate_choice.h"

#include <algorithm>
#include <cmath>

namespace isurface {

namespace {

// Candidates whose scores (balanced, quality) or times differ by no more than this share are as
// good: the one with the shorter program is chosen.
constexpr double kSameScoreWithin = 0.02;
constexpr double kSameTimeWithin = 0.001;

// The region's figures after over before, averaged (smaller is better): how Objective::Quality
// ranks the candidates it keeps.
double qualityScore(const RegionOptimisation& r) {
  const QualityFigures &a = r.regionBefore, &b = r.regionAfter;
  auto ratio = [](double before, double after, double floor) { return std::max(after, floor) / std::max(before, floor); };
  const double sum = ratio(a.speedFluctuation, b.speedFluctuation, 0.1) + ratio(a.inconsistencyP99, b.inconsistencyP99, 0.1) +
                     ratio(a.inconsistencyMean, b.inconsistencyMean, 0.1) + ratio(a.jerkP99, b.jerkP99, 1.0) +
                     (a.hasDeviation ? ratio(a.deviationP99, b.deviationP99, 0.001) : 0.0);
  return sum / (a.hasDeviation ? 5.0 : 4.0);
}

// The region's time after over before added to the quality score, so that the time weighs as
// much as the figures together: how Objective::Balanced ranks the candidates it keeps, none of
// them slower.
double balancedScore(const RegionOptimisation& r) {
  return qualityScore(r) + (r.regionTimeBefore > 0 ? r.regionTimeAfter / r.regionTimeBefore : 1.0);
}

}  // namespace

// Scores within kSameScoreWithin of each other (times within kSameTimeWithin) are as good: the
// shorter program is then the better.
bool betterFor(Objective objective, const RegionOptimisation& r, const RegionOptimisation& best) {
  const double a = objective == Objective::Time ? r.timeAfter : objective == Objective::Balanced ? balancedScore(r) : qualityScore(r);
  const double b = objective == Objective::Time ? best.timeAfter
                   : objective == Objective::Balanced ? balancedScore(best)
                                                      : qualityScore(best);
  const double within = objective == Objective::Time ? kSameTimeWithin : kSameScoreWithin;
  if (std::fabs(a - b) <= within * std::fabs(b)) return r.linesAfter < best.linesAfter;
  return a < b;
}

}  // namespace isurface
