#pragma once
// The figures a run is judged by (defined in docs/optimising.md, "Quality figures"): measured on the
// samples of the surface alone, whatever made the program, so that a re-optimised program is
// judged by the same rule as the one it replaces and the optimiser cannot flatter itself (it
// makes its choices with the planner's own limits, never with these).
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "isurface/base/line_range.h"
#include "isurface/base/trajectory.h"
#include "isurface/surface/surface_mesh.h"

namespace isurface {

// Where figures are taken: samples of these lines inside this XY box (mm). By default the whole run.
struct FigureWindow {
  LineRange lines{0, std::numeric_limits<std::uint32_t>::max()};
  Vec3 lower = Vec3::Constant(-std::numeric_limits<double>::infinity());
  Vec3 upper = Vec3::Constant(std::numeric_limits<double>::infinity());
};

struct QualityFigures {
  std::size_t samples = 0;         // surface samples measured
  std::size_t betweenPasses = 0;   // of them, those with a neighbouring pass (inconsistency measured)
  double speedFluctuation = 0;     // mm/min, RMS of the path speed about its 100 ms moving average
  double inconsistencyP99 = 0;     // mm/min, 99th percentile of the adjacent-pass speed inconsistency
  double inconsistencyMean = 0;    // mm/min, its mean
  double jerkP99 = 0;              // mm/s^3, 99th percentile of |j|
  double deviationP99 = 0;         // um, 99th percentile of |predicted deviation| (0 without feedback)
  bool hasDeviation = false;
};

// What the figures are taken from, per vertex of the surface: derived once for a run (most of the
// work of measuring it), then measured in any number of windows.
struct FigureValues {
  std::vector<double> speedOffMean;   // mm/min, the path speed less its moving average; NaN where the speed is not finite
  std::vector<double> jerk;           // mm/s^3, |j|
  std::vector<float> inconsistency;   // mm/min, adjacent-pass speed inconsistency
  std::vector<float> deviation;       // um, predicted deviation (signed); empty without feedback
};

FigureValues figureValues(const Trajectory& samples, const SurfaceMesh& mesh);
// `values`: figureValues(samples, mesh); std::invalid_argument when they are of another surface.
QualityFigures measureQualityFigures(const FigureValues& values, const Trajectory& samples, const SurfaceMesh& mesh,
                                     const FigureWindow& window = {});
QualityFigures measureQualityFigures(const Trajectory& samples, const SurfaceMesh& mesh, const FigureWindow& window = {});

// The nearest-rank percentile (0..100) of finite values; 0 when there are none. Reorders `values`.
double percentileOf(std::vector<double>& values, double percent);

// How `after` is worse than `before` by more than `allowed` (relative, 0.02 = 2 %) on any
// figure, naming the figure and both values; empty when it is not.
std::string worseFigure(const QualityFigures& before, const QualityFigures& after, double allowed);

// How `after` is better than `before` by at least `required` on any figure, naming the first
// such figure and both values; empty when none is.
std::string betterFigure(const QualityFigures& before, const QualityFigures& after, double required);

}  // namespace isurface
