#include "isurface/analysis/quality_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>
#include <stdexcept>
#include <vector>

#include "isurface/analysis/quantities.h"
#include "isurface/base/geometry.h"

namespace isurface {

namespace {

constexpr double kFluctuationWindow = 0.1;  // s, the moving average's span

// The mean of the finite values within `half` samples of each sample, from running sums.
class MovingMean {
 public:
  MovingMean(const std::vector<double>& values, std::size_t half) : half_(half), sum_(values.size() + 1), count_(values.size() + 1) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      const bool finite = std::isfinite(values[i]);
      sum_[i + 1] = sum_[i] + (finite ? values[i] : 0.0);
      count_[i + 1] = count_[i] + (finite ? 1 : 0);
    }
  }
  double at(std::size_t i) const {
    const std::size_t a = i > half_ ? i - half_ : 0, b = std::min(sum_.size() - 1, i + half_ + 1);
    const std::size_t n = count_[b] - count_[a];
    return n ? (sum_[b] - sum_[a]) / static_cast<double>(n) : 0.0;
  }

 private:
  std::size_t half_;
  std::vector<double> sum_;
  std::vector<std::size_t> count_;
};

bool inside(const Trajectory& s, std::size_t i, std::uint32_t line, const FigureWindow& w) {
  return w.lines.contains(line) && insideBoxInPlan(s.x[i], s.y[i], w.lower, w.upper);
}

}  // namespace

double percentileOf(std::vector<double>& values, double percent) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }), values.end());
  if (values.empty()) return 0.0;
  const double rank = std::ceil(percent / 100.0 * static_cast<double>(values.size()));
  const std::size_t k = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size()))) - 1;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

FigureValues figureValues(const Trajectory& samples, const SurfaceMesh& mesh) {
  FigureValues values;
  if (samples.size() == 0 || mesh.vertexSample.empty()) return values;
  // The surface's values on a second core while this one derives the motion of every sample.
  std::future<std::vector<float>> inconsistency = std::async(std::launch::async, [&] {
    return vertexQuantity(Quantity::SpeedInconsistency, samples, mesh);
  });
  {
    const std::vector<std::vector<double>> speedAndJerk = sampleQuantities({Quantity::Speed, Quantity::Jerk}, samples);
    const std::vector<double>& speed = speedAndJerk[0];
    const std::vector<double>& jerk = speedAndJerk[1];
    const double cycle = samples.cycle > 0 ? samples.cycle : 0.001;
    const MovingMean mean(speed, static_cast<std::size_t>(std::lround(0.5 * kFluctuationWindow / cycle)));
    const std::size_t vertices = mesh.vertexSample.size();
    values.speedOffMean.resize(vertices);
    values.jerk.resize(vertices);
    for (std::size_t v = 0; v < vertices; ++v) {
      const std::size_t i = mesh.vertexSample[v];
      values.speedOffMean[v] = std::isfinite(speed[i]) ? speed[i] - mean.at(i) : std::numeric_limits<double>::quiet_NaN();
      values.jerk[v] = jerk[i];
    }
  }
  if (samples.hasFeedback()) values.deviation = vertexQuantity(Quantity::Deviation, samples, mesh);
  values.inconsistency = inconsistency.get();
  return values;
}

QualityFigures measureQualityFigures(const FigureValues& values, const Trajectory& samples, const SurfaceMesh& mesh,
                                     const FigureWindow& window) {
  QualityFigures f;
  if (samples.size() == 0 || mesh.vertexSample.empty()) return f;
  const std::size_t vertices = mesh.vertexSample.size();
  if (values.speedOffMean.size() != vertices || values.jerk.size() != vertices || values.inconsistency.size() != vertices ||
      (!values.deviation.empty() && values.deviation.size() != vertices))
    throw std::invalid_argument("figure values of another surface");
  f.hasDeviation = !values.deviation.empty();
  std::vector<double> jerks, inconsistencies, deviations;
  double sumSquares = 0, inconsistencySum = 0;
  std::size_t inconsistencyCount = 0;
  RunChannel<std::uint32_t>::Cursor lineOf = samples.line.cursor();
  for (std::size_t v = 0; v < mesh.vertexSample.size(); ++v) {
    const std::size_t i = mesh.vertexSample[v];
    const double d = values.speedOffMean[v];
    if (!inside(samples, i, lineOf[i], window) || std::isnan(d)) continue;
    ++f.samples;
    sumSquares += d * d;
    jerks.push_back(values.jerk[v]);
    if (mesh.previousPassNeighbour[v] != kNoVertex || mesh.nextPassNeighbour[v] != kNoVertex) ++f.betweenPasses;
    if (std::isfinite(values.inconsistency[v])) {
      inconsistencies.push_back(values.inconsistency[v]);
      inconsistencySum += values.inconsistency[v];
      ++inconsistencyCount;
    }
    if (f.hasDeviation) deviations.push_back(std::fabs(values.deviation[v]));
  }
  f.speedFluctuation = f.samples ? std::sqrt(sumSquares / static_cast<double>(f.samples)) : 0.0;
  f.inconsistencyMean = inconsistencyCount ? inconsistencySum / static_cast<double>(inconsistencyCount) : 0.0;
  f.inconsistencyP99 = percentileOf(inconsistencies, 99);
  f.jerkP99 = percentileOf(jerks, 99);
  f.deviationP99 = percentileOf(deviations, 99);
  return f;
}

QualityFigures measureQualityFigures(const Trajectory& samples, const SurfaceMesh& mesh, const FigureWindow& window) {
  return measureQualityFigures(figureValues(samples, mesh), samples, mesh, window);
}

namespace {

struct NamedFigure {
  const char* name;
  double before, after;
  const char* unit;
  double floor;  // below it a change is no change
};

// Below its floor a change is no change (a speed a tenth of a mm/min, a jerk of 1 mm/s^3, a
// nanometre): a figure that was 0 does not make every candidate worse.
std::array<NamedFigure, 5> namedFigures(const QualityFigures& before, const QualityFigures& after) {
  return {{
      {"speed fluctuation", before.speedFluctuation, after.speedFluctuation, "mm/min", 0.1},
      {"inconsistency between passes (p99)", before.inconsistencyP99, after.inconsistencyP99, "mm/min", 0.1},
      {"inconsistency between passes (mean)", before.inconsistencyMean, after.inconsistencyMean, "mm/min", 0.1},
      {"jerk (p99)", before.jerkP99, after.jerkP99, "mm/s^3", 1.0},
      {"predicted deviation (p99)", before.deviationP99, after.deviationP99, "\u00b5m", 0.001},
  }};
}

// With the digits that show a change of 2 % (3.21 -> 3.29 um would both read 3.2) and the change itself.
std::string describeChange(const NamedFigure& f) {
  const double size = std::max(std::fabs(f.before), std::fabs(f.after));
  const int decimals = size < 10 ? 2 : size < 1000 ? 1 : 0;
  const std::string change = f.before != 0 ? fmt::format(" ({:+.1f} %)", 100 * (f.after / f.before - 1)) : "";
  return fmt::format("{} {:.{}f} -> {:.{}f} {}{}", f.name, f.before, decimals, f.after, decimals, f.unit, change);
}

}  // namespace

std::string worseFigure(const QualityFigures& before, const QualityFigures& after, double allowed) {
  for (const NamedFigure& f : namedFigures(before, after))
    if (f.after > f.before * (1 + allowed) + f.floor) return describeChange(f);
  return {};
}

std::string betterFigure(const QualityFigures& before, const QualityFigures& after, double required) {
  for (const NamedFigure& f : namedFigures(before, after))
    if (f.after < f.before * (1 - required) - f.floor) return describeChange(f);
  return {};
}

}  // namespace isurface
