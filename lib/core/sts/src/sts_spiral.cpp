#include "isurface/sts/sts_spiral.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "isurface/sts/sts_interpolation.h"

namespace isurface {

namespace {
// Halving stops below this step (rad): a surface with a jump could otherwise halve forever.
constexpr double kSmallestAngleStep = 1e-9;
constexpr int kMaxHalvings = 60;
// A path of more contact points than this is no turning job: a real one has thousands (a
// 20 mm part at 0.5 mm/rev and 5 degrees: 2,880), and each costs surface evaluations.
constexpr std::size_t kMostContactPoints = 2000000;
// Halving the step for the height rule evaluates the surface again each time; a surface too
// steep for the height step would halve at every point down to 1e-9 rad.
constexpr std::size_t kMostHeightEvaluations = 20000000;

[[noreturn]] void badParameter(const std::string& message) {
  throw InputError({"sts", 0, 0, message});
}
}  // namespace

StsDiscretisation parseStsDiscretisation(const std::string& word) {
  if (word == "angle") return StsDiscretisation::EqualAngle;
  if (word == "arc") return StsDiscretisation::EqualArcLength;
  if (word == "height") return StsDiscretisation::EqualHeight;
  badParameter("--discretise: expected angle, arc or height, got '" + word + "'");
}

std::string toString(StsDiscretisation method) {
  switch (method) {
    case StsDiscretisation::EqualAngle: return "angle";
    case StsDiscretisation::EqualArcLength: return "arc";
    case StsDiscretisation::EqualHeight: return "height";
  }
  return "?";
}

void SpiralParameters::validate() const {
  auto positive = [](double v, const char* what) {
    if (!(v > 0) || !std::isfinite(v)) badParameter(std::string(what) + " must be positive");
  };
  positive(workpieceRadius, "--radius (workpiece radius, mm)");
  positive(feedPerRev, "--feed (feed per revolution, mm/rev)");
  positive(angleStep, "--angle-step (deg)");
  positive(arcStep, "--arc-step (mm)");
  positive(heightStep, "--height-step (mm)");
  if (!(toolRadius >= 0) || !std::isfinite(toolRadius))
    badParameter("--tool-radius (mm) must not be negative");
  if (feedPerRev > workpieceRadius) badParameter("--feed must not exceed the workpiece radius");
  // 10^7 revolutions of points would not fit in memory anyway.
  if (workpieceRadius / feedPerRev > 1e5) badParameter("--radius / --feed: too many revolutions");
  // The steps bound the number of contact points ahead: refused before minutes of work.
  const double byAngle = endAngle() / angleStep;
  const double spiralLength = kPi * workpieceRadius * workpieceRadius / feedPerRev;  // mm, about
  if (byAngle > kMostContactPoints)
    badParameter(fmt::format("--angle-step {:.3g} deg makes {:.3g} contact points, more than {:.3g}: give a larger step",
                             angleStep * kDegreesPerRadian, byAngle, double(kMostContactPoints)));
  if (spiralLength / arcStep > kMostContactPoints)
    badParameter(fmt::format("--arc-step {:.3g} mm makes {:.3g} contact points, more than {:.3g}: give a larger step",
                             arcStep, spiralLength / arcStep, double(kMostContactPoints)));
}

double SpiralParameters::endAngle() const { return kTwoPi * workpieceRadius / feedPerRev; }

double SpiralParameters::radiusAt(double theta) const {
  return std::max(0.0, workpieceRadius - feedPerRev * theta / kTwoPi);
}

double SpiralParameters::arcRate(double theta) const {
  const double r = radiusAt(theta), b = feedPerRev / kTwoPi;
  return std::sqrt(r * r + b * b);
}

double SpiralPoint::x() const { return r * std::cos(theta); }
double SpiralPoint::y() const { return r * std::sin(theta); }

SpiralPoint spiralContactPoint(const StsSurface& surface, const SpiralParameters& p, double theta) {
  SpiralPoint q;
  q.theta = theta;
  q.r = p.radiusAt(theta);
  q.z = surface.height(q.x(), q.y());
  if (!std::isfinite(q.z))
    badParameter(fmt::format("the surface is not defined at x = {:.6g} mm, y = {:.6g} mm "
                             "(inside the workpiece radius)", q.x(), q.y()));
  return q;
}

std::vector<SpiralPoint> discretiseSpiral(const StsSurface& surface, const SpiralParameters& p,
                                          StsDiscretisation method) {
  p.validate();
  const double end = p.endAngle();
  std::vector<SpiralPoint> points{spiralContactPoint(surface, p, 0.0)};
  // Halves the step until the height difference is allowed (Figure 3).
  std::size_t evaluations = 0;
  auto limitHeight = [&](const SpiralPoint& from, double candidate) {
    SpiralPoint next = spiralContactPoint(surface, p, candidate);
    for (int i = 0; i < kMaxHalvings && std::abs(next.z - from.z) > p.heightStep &&
                    next.theta - from.theta > kSmallestAngleStep;
         ++i) {
      if (++evaluations > kMostHeightEvaluations)
        badParameter(fmt::format("the surface rises more than --height-step {:g} mm between points too close to "
                                 "count (at r = {:.4g} mm): give a larger --height-step",
                                 p.heightStep, next.r));
      next = spiralContactPoint(surface, p, 0.5 * (from.theta + next.theta));
    }
    return next;
  };
  while (points.back().theta < end) {
    const SpiralPoint& last = points.back();
    const double angleCandidate = std::min(end, last.theta + p.angleStep);
    const double arcCandidate = std::min(end, last.theta + p.arcStep / p.arcRate(last.theta));
    SpiralPoint next;
    switch (method) {
      case StsDiscretisation::EqualAngle: next = spiralContactPoint(surface, p, angleCandidate); break;
      case StsDiscretisation::EqualArcLength: next = spiralContactPoint(surface, p, arcCandidate); break;
      case StsDiscretisation::EqualHeight: {
        next = spiralContactPoint(surface, p, arcCandidate);
        if (std::abs(next.z - last.z) > p.heightStep)
          next = limitHeight(last, arcCandidate);
        else if (next.theta - last.theta > p.angleStep)
          next = limitHeight(last, angleCandidate);
        break;
      }
    }
    points.push_back(next);
    // Equal height halves its steps where the surface is steep: no estimate bounds it ahead.
    if (points.size() > kMostContactPoints)
      badParameter(fmt::format("more than {:.3g} contact points: give a larger --height-step or --arc-step",
                               double(kMostContactPoints)));
  }
  return points;
}

NoseCompensation compensateNoseRadius(const StsSurface& surface, double r, double theta,
                                      double toolRadius) {
  const double c = std::cos(theta), s = std::sin(theta);
  // The radial section through the C axis; rho may go negative, past the axis.
  auto height = [&](double rho) { return surface.height(rho * c, rho * s); };
  auto slope = [&](double rho) { return surface.gradient(rho * c, rho * s).dot(Eigen::Vector2d(c, s)); };
  NoseCompensation out;
  if (toolRadius <= 0) {
    out.z = height(r);
    return out;
  }
  // The nose touches where the section's slope equals the nose arc's: u = R_t s / sqrt(1 + s^2)
  // with s taken at the contact r + u. Fixed-point iteration; it contracts while the section's
  // curvature stays below 1 / R_t (no gouging).
  double u = 0;
  for (int i = 0; i < 100; ++i) {
    const double k = slope(r + u);
    const double next = toolRadius * k / std::sqrt(1 + k * k);
    const bool done = std::abs(next - u) < 1e-14;
    u = next;
    if (done) break;
  }
  out.contactOffset = u;
  out.z = height(r + u) + std::sqrt(std::max(0.0, toolRadius * toolRadius - u * u)) - toolRadius;
  if (!std::isfinite(out.z))
    badParameter(fmt::format("tool nose compensation failed at r = {:.6g} mm, theta = {:.6g} rad "
                             "(surface undefined or steeper than the nose allows)", r, theta));
  return out;
}

std::vector<SpiralPoint> cuttingLocationPoints(const StsSurface& surface,
                                               const std::vector<SpiralPoint>& contactPoints,
                                               double toolRadius) {
  std::vector<SpiralPoint> out = contactPoints;
  for (SpiralPoint& q : out) q.z = compensateNoseRadius(surface, q.r, q.theta, toolRadius).z;
  return out;
}

void recordError(ErrorProfile& e, const SpiralParameters& p, std::size_t segment, double theta,
                 double error) {
  e.perSegment[segment] = std::max(e.perSegment[segment], error);
  if (error > e.max) {
    e.max = error;
    e.thetaAtMax = theta;
    e.radiusAtMax = p.radiusAt(theta);
  }
  if (theta > kTwoPi && theta < p.endAngle() - kTwoPi) e.interiorMax = std::max(e.interiorMax, error);
}

ErrorProfile discreteError(const StsSurface& surface, const SpiralParameters& p,
                           const std::vector<SpiralPoint>& contactPoints, int samplesPerSegment) {
  ErrorProfile e;
  if (contactPoints.size() < 2) return e;
  std::vector<double> t, f;
  for (const SpiralPoint& q : contactPoints) {
    t.push_back(q.theta);
    f.push_back(q.z);
  }
  const std::vector<double> m = naturalSplineSlopesThreeMoment(t, f);
  e.perSegment.assign(t.size() - 1, 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    for (int j = 1; j <= samplesPerSegment; ++j) {
      const double th = t[i] + (t[i + 1] - t[i]) * j / (samplesPerSegment + 1);
      const double err = std::abs(hermiteValue(t[i], t[i + 1], f[i], f[i + 1], m[i], m[i + 1], th) -
                                  spiralContactPoint(surface, p, th).z);
      recordError(e, p, i, th, err);
    }
  }
  return e;
}

}  // namespace isurface
