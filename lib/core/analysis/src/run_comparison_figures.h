#pragma once
// Summing a run comparison's figures over samples, lines and ranges (internal to the core).
#include <cmath>
#include <vector>

#include "isurface/analysis/run_comparison.h"

namespace isurface {

// Keeps the value of larger magnitude, sign and all.
inline void keepLarger(double& kept, double candidate) {
  if (std::isfinite(candidate) && std::abs(candidate) > std::abs(kept)) kept = candidate;
}

class FigureAccumulator {
 public:
  void addTime(double a, double b) { f_.timeA += a, f_.timeB += b; }
  void setLengths(double a, double b, std::size_t samplesA, std::size_t samplesB) {
    f_.lengthA = a, f_.lengthB = b, f_.samplesA = samplesA, f_.samplesB = samplesB;
  }
  void addSample(double speedDifference, double positionDistance, double pathDistance) {
    if (std::isfinite(speedDifference)) {
      speedSum_ += speedDifference;
      ++f_.comparedSamples;
      keepLarger(f_.maxSpeedDifference, speedDifference);
    }
    keepLarger(f_.maxPositionDistance, positionDistance);
    keepLarger(f_.maxPathDistance, pathDistance);
  }
  void addFeedbackDistance(double d) { keepLarger(feedback_, d); }
  DifferenceFigures figures(bool withFeedback) const {
    DifferenceFigures f = f_;
    f.timeDifference = f.timeB - f.timeA;
    f.meanSpeedDifference = f.comparedSamples ? speedSum_ / double(f.comparedSamples) : 0.0;
    if (withFeedback) f.maxFeedbackDistance = feedback_;
    return f;
  }

 private:
  DifferenceFigures f_;
  double speedSum_ = 0;  // mm/min, sum of the finite speed differences
  double feedback_ = 0;  // mm, largest feedback distance
};

// Adds a line's (or range's) figures to those of a larger stretch.
void mergeFigures(DifferenceFigures& into, const DifferenceFigures& f);

// Fills out.ranges and out.total from out.lines.
void groupRanges(RunComparison& out, const RunComparisonOptions& options);

}  // namespace isurface
