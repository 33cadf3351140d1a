#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/base/tolerances.h"
#include "isurface/base/units.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "isurface/gcode/arc.h"
#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void badParameter(const std::string& message) { throw InputError(Diagnostic{"", 0, 0, message}); }

// Points with consecutive duplicates dropped, and for each kept point its index in `points`.
struct DistinctPoints {
  std::vector<Vec3> points;
  std::vector<std::size_t> original;
};

DistinctPoints dropDuplicates(const std::vector<Vec3>& points) {
  DistinctPoints d;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!d.points.empty() && (points[i] - d.points.back()).norm() < kLengthEpsilon) continue;
    d.points.push_back(points[i]);
    d.original.push_back(i);
  }
  return d;
}

// Curvature (mm^-1) at every point from equation 1; the ends copy their only neighbour.
std::vector<double> pointCurvatures(const std::vector<Vec3>& p) {
  const std::size_t n = p.size();
  std::vector<double> k(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double rho = threePointRadius(p[i - 1], p[i], p[i + 1]);
    k[i] = std::isfinite(rho) && rho > 0 ? 1.0 / rho : 0.0;
  }
  if (n >= 3) {
    k[0] = k[1];
    k[n - 1] = k[n - 2];
  }
  return k;
}

bool strictlyWithin(double ratio, double threshold) {
  return ratio > 1.0 / threshold && ratio < threshold;
}

}  // namespace

std::vector<std::size_t> douglasPeuckerIndices(const std::vector<Vec3>& points, double tolerance) {
  const std::size_t n = points.size();
  if (n == 0) return {};
  if (n == 1) return {0};
  std::vector<bool> keep(n, false);
  keep[0] = keep[n - 1] = true;
  // An explicit stack instead of recursion: a long raster pass would otherwise recurse deeply.
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, n - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (b <= a + 1) continue;
    double worst = -1;
    std::size_t worstIndex = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = distanceToSegment(points[i], points[a], points[b]);
      if (d > worst) {
        worst = d;
        worstIndex = i;
      }
    }
    if (worst > tolerance) {
      keep[worstIndex] = true;
      stack.push_back({a, worstIndex});
      stack.push_back({worstIndex, b});
    }
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) out.push_back(i);
  return out;
}

double curvatureRatio(double curvature, double previousCurvature) {
  const bool zero = std::abs(curvature) < kZeroCurvature;
  const bool previousZero = std::abs(previousCurvature) < kZeroCurvature;
  if (zero && previousZero) return 1.0;
  if (previousZero) return kLargeRatio;
  if (zero) return 1.0 / kLargeRatio;
  return curvature / previousCurvature;
}

IntervalPartition partitionConstantSpeedIntervals(const std::vector<Vec3>& input,
                                                  const IntervalThresholds& t) {
  if (!(t.error > 0)) badParameter("the error threshold must be > 0 mm");
  if (!(t.distanceRatio > 1)) badParameter("the distance ratio threshold must be > 1");
  if (!(t.curvatureRatio > 1)) badParameter("the curvature ratio threshold must be > 1");

  IntervalPartition out;
  const DistinctPoints d = dropDuplicates(input);
  const std::vector<Vec3>& p = d.points;
  const std::size_t n = p.size();
  if (n < 2) return out;
  const std::vector<double> k = pointCurvatures(p);

  std::vector<std::size_t> boundaries;  // into p
  for (const std::size_t i : douglasPeuckerIndices(p, t.error)) {
    CharacteristicPoint c;
    c.index = d.original[i];
    c.position = p[i];
    c.radius = k[i] > 0 ? 1.0 / k[i] : std::numeric_limits<double>::infinity();
    const bool end = i == 0 || i + 1 == n;
    c.distanceRatio = end ? kNaN : (p[i + 1] - p[i]).norm() / (p[i] - p[i - 1]).norm();
    c.curvatureRatio = i == 0 ? kNaN : curvatureRatio(k[i], k[i - 1]);
    c.inside = !end && strictlyWithin(c.distanceRatio, t.distanceRatio) &&
               strictlyWithin(c.curvatureRatio, t.curvatureRatio);
    if (!c.inside) boundaries.push_back(i);
    out.characteristic.push_back(c);
  }

  for (std::size_t b = 0; b + 1 < boundaries.size(); ++b) {
    const std::size_t first = boundaries[b], last = boundaries[b + 1];
    ConstantSpeedInterval interval;
    interval.first = d.original[first];
    interval.last = d.original[last];
    double sum = 0;
    for (std::size_t i = first; i <= last; ++i) sum += k[i];
    interval.averageCurvature = sum / static_cast<double>(last - first + 1);
    for (std::size_t i = first; i < last; ++i) interval.length += (p[i + 1] - p[i]).norm();
    out.intervals.push_back(interval);
  }
  return out;
}

// --- Sections ---

namespace {

// Appends the CL points of one feed move: its end, or for an arc samples whose chords stay within
// the chord error of the exact arc.
void appendMovePoints(const Program& program, std::size_t m, double chordError, PathSection& s) {
  const Move& move = program.moves[m];
  if (move.isArc()) {
    const ArcGeometry arc = ArcGeometry::from(program.startOf(m), move);
    const double r = std::max(arc.startRadius, arc.endRadius);
    // Sagitta of a chord over angle a on radius r: r (1 - cos(a/2)); solve for a.
    const double maxStep = r > chordError ? 2.0 * std::acos(1.0 - chordError / r) : kPi;
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(arc.sweep) / maxStep)));
    for (int i = 1; i < steps; ++i) {
      s.points.push_back(arc.at(static_cast<double>(i) / steps));
      s.lines.push_back(move.line);
      s.feeds.push_back(move.feed);
    }
  }
  s.points.push_back(move.end);
  s.lines.push_back(move.line);
  s.feeds.push_back(move.feed);
}

bool isFeedMove(const Move& m) {
  return m.kind == MoveKind::Linear || m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW;
}

// Splits one continuous run of points at raster pass boundaries: a segment whose XY direction
// turns by more than the reversal angle against the section's net XY displacement so far. The
// net displacement, not the previous segment, is the reference because a raster's step-over
// turns 90 degrees twice; against the pass it follows, the next pass turns 180 degrees.
std::vector<PathSection> splitAtReversals(const PathSection& run, double reversalAngleDeg) {
  std::vector<PathSection> out(1);
  const double cosLimit = std::cos(reversalAngleDeg * kPi / 180.0);
  Eigen::Vector2d net = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < run.points.size(); ++i) {
    if (i > 0) {
      const Vec3 step = run.points[i] - run.points[i - 1];
      const Eigen::Vector2d xy(step.x(), step.y());
      if (xy.norm() > kLengthEpsilon && net.norm() > kLengthEpsilon &&
          xy.dot(net) / (xy.norm() * net.norm()) < cosLimit - kRoundingSlack) {  // a right angle is no reversal
        PathSection next;
        next.points.push_back(run.points[i - 1]);
        next.lines.push_back(run.lines[i - 1]);
        next.feeds.push_back(run.feeds[i - 1]);
        out.push_back(std::move(next));
        net.setZero();
      }
      net += xy;
    }
    out.back().points.push_back(run.points[i]);
    out.back().lines.push_back(run.lines[i]);
    out.back().feeds.push_back(run.feeds[i]);
  }
  return out;
}

// The paper's rule for a path without boundaries: when the cumulative length passes the
// threshold, the previous CL point ends the section.
std::vector<PathSection> splitByDistance(const PathSection& run, double threshold) {
  std::vector<PathSection> out(1);
  double cumulative = 0;
  for (std::size_t i = 0; i < run.points.size(); ++i) {
    if (i > 0) {
      const double step = (run.points[i] - run.points[i - 1]).norm();
      if (cumulative + step > threshold && out.back().points.size() >= 2) {
        PathSection next;
        next.points.push_back(run.points[i - 1]);
        next.lines.push_back(run.lines[i - 1]);
        next.feeds.push_back(run.feeds[i - 1]);
        out.push_back(std::move(next));
        cumulative = 0;
      }
      cumulative += step;
    }
    out.back().points.push_back(run.points[i]);
    out.back().lines.push_back(run.lines[i]);
    out.back().feeds.push_back(run.feeds[i]);
  }
  return out;
}

}  // namespace

std::vector<PathSection> collectSections(const Program& program, std::uint32_t firstLine,
                                         std::uint32_t lastLine, const SectionOptions& options) {
  if (!(options.distanceThreshold > 0)) badParameter("the section distance threshold must be > 0 mm");
  if (!(options.arcChordError > 0)) badParameter("the arc chord error must be > 0 mm");
  // Continuous runs of feed moves within the range; anything else in between breaks the run.
  std::vector<PathSection> runs;
  bool open = false;
  for (std::size_t m = 0; m < program.moves.size(); ++m) {
    const Move& move = program.moves[m];
    const bool inRange = move.line >= firstLine && move.line <= lastLine;
    if (!inRange || !isFeedMove(move)) {
      // A dwell does not move the tool; it need not end a run.
      if (!(inRange && move.kind == MoveKind::Dwell)) open = false;
      continue;
    }
    if (!open) {
      runs.emplace_back();
      runs.back().points.push_back(program.startOf(m));
      runs.back().lines.push_back(move.line);
      runs.back().feeds.push_back(move.feed);  // the run's start: reached at this move's feed
      open = true;
    }
    appendMovePoints(program, m, options.arcChordError, runs.back());
  }

  std::vector<PathSection> sections;
  for (const PathSection& run : runs) {
    std::vector<PathSection> passes = splitAtReversals(run, options.reversalAngleDeg);
    if (passes.size() == 1) passes = splitByDistance(run, options.distanceThreshold);
    for (PathSection& s : passes)
      if (s.points.size() >= 2) sections.push_back(std::move(s));
  }
  return sections;
}

}  // namespace isurface
