#include "isurface/sts/sts_interpolation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "isurface/fitting/cubic_spline.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"

namespace isurface {

namespace {

[[noreturn]] void badParameter(const std::string& message) {
  throw InputError({"sts", 0, 0, message});
}

void checkKnots(const std::vector<double>& t, const std::vector<double>& f) {
  if (t.size() != f.size() || t.size() < 2)
    throw std::invalid_argument("interpolation needs at least two knots and one value per knot");
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    if (!(t[i + 1] > t[i])) throw std::invalid_argument("interpolation knots must increase");
}

// Divided differences f[t_k, t_{k+1}].
std::vector<double> secants(const std::vector<double>& t, const std::vector<double>& f) {
  std::vector<double> d(t.size() - 1);
  for (std::size_t k = 0; k + 1 < t.size(); ++k) d[k] = (f[k + 1] - f[k]) / (t[k + 1] - t[k]);
  return d;
}
}  // namespace

StsNodes parseStsNodes(const std::string& word) {
  if (word == "uniform") return StsNodes::Uniform;
  if (word == "nonuniform" || word == "non-uniform") return StsNodes::NonUniform;
  badParameter("--nodes: expected uniform or nonuniform, got '" + word + "'");
}

std::string toString(StsNodes nodes) { return nodes == StsNodes::Uniform ? "uniform" : "nonuniform"; }

StsInterpolation parseStsInterpolation(const std::string& word) {
  if (word == "hermite") return StsInterpolation::Hermite;
  if (word == "spline" || word == "spline-slope") return StsInterpolation::SplineThreeSlope;
  if (word == "spline-moment") return StsInterpolation::SplineThreeMoment;
  badParameter("--interp: expected hermite, spline (three-slope) or spline-moment, got '" + word + "'");
}

std::string toString(StsInterpolation method) {
  switch (method) {
    case StsInterpolation::Hermite: return "hermite";
    case StsInterpolation::SplineThreeSlope: return "spline";
    case StsInterpolation::SplineThreeMoment: return "spline-moment";
  }
  return "?";
}

double hermiteValue(double t0, double t1, double f0, double f1, double v0, double v1, double t) {
  const double h = t1 - t0, s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * f1 +
         (s3 - s2) * h * v1;
}

std::vector<double> pvtThreePointSlopes(const std::vector<double>& t, const std::vector<double>& f) {
  checkKnots(t, f);
  const std::vector<double> d = secants(t, f);
  const std::size_t n = t.size() - 1;
  if (n == 1) return {d[0], d[0]};
  std::vector<double> m(n + 1);
  // Slope of the parabola through three consecutive nodes: weighting each secant by the other
  // interval keeps the estimate second-order accurate on unevenly spaced nodes.
  for (std::size_t k = 1; k < n; ++k) {
    const double hPrev = t[k] - t[k - 1], h = t[k + 1] - t[k];
    m[k] = (h * d[k - 1] + hPrev * d[k]) / (hPrev + h);
  }
  const double h0 = t[1] - t[0], h1 = t[2] - t[1];
  m[0] = d[0] - h0 * (d[1] - d[0]) / (h0 + h1);
  const double hl = t[n] - t[n - 1], hl1 = t[n - 1] - t[n - 2];
  m[n] = d[n - 1] + hl * (d[n - 1] - d[n - 2]) / (hl + hl1);
  return m;
}

std::vector<double> naturalSplineSlopesThreeSlope(const std::vector<double>& t,
                                                  const std::vector<double>& f) {
  checkKnots(t, f);
  const std::vector<double> d = secants(t, f);
  const std::size_t n = t.size() - 1;
  std::vector<double> sub(n + 1, 0.0), diag(n + 1, 2.0), super(n + 1, 0.0), rhs(n + 1);
  // Natural ends, I''(t_0) = I''(t_n) = 0: 2 m_0 + m_1 = 3 d_0 and m_{n-1} + 2 m_n = 3 d_{n-1}.
  super[0] = 1.0;
  rhs[0] = 3 * d[0];
  sub[n] = 1.0;
  rhs[n] = 3 * d[n - 1];
  // Equation 7: lambda_k m_{k-1} + 2 m_k + mu_k m_{k+1} = 3 (lambda_k d_{k-1} + mu_k d_k),
  // lambda_k = h_k / (h_{k-1} + h_k), mu_k = h_{k-1} / (h_{k-1} + h_k).
  for (std::size_t k = 1; k < n; ++k) {
    const double hPrev = t[k] - t[k - 1], h = t[k + 1] - t[k];
    const double lambda = h / (hPrev + h), mu = hPrev / (hPrev + h);
    sub[k] = lambda;
    super[k] = mu;
    rhs[k] = 3 * (lambda * d[k - 1] + mu * d[k]);
  }
  solveTridiagonal(sub, diag, super, rhs);
  return rhs;
}

std::vector<double> naturalSplineMoments(const std::vector<double>& t, const std::vector<double>& f) {
  checkKnots(t, f);
  const std::vector<double> d = secants(t, f);
  const std::size_t n = t.size() - 1;
  std::vector<double> M(n + 1, 0.0);  // natural: M_0 = M_n = 0
  if (n < 2) return M;
  // Equation 9 for k = 1 .. n-1: mu_k M_{k-1} + 2 M_k + lambda_k M_{k+1} = 6 f[t_{k-1}, t_k, t_{k+1}],
  // mu_k = h_{k-1} / (h_{k-1} + h_k), lambda_k = h_k / (h_{k-1} + h_k).
  const std::size_t m = n - 1;
  std::vector<double> sub(m), diag(m, 2.0), super(m), rhs(m);
  for (std::size_t k = 1; k < n; ++k) {
    const double hPrev = t[k] - t[k - 1], h = t[k + 1] - t[k];
    sub[k - 1] = hPrev / (hPrev + h);
    super[k - 1] = h / (hPrev + h);
    rhs[k - 1] = 6 * (d[k] - d[k - 1]) / (hPrev + h);
  }
  solveTridiagonal(sub, diag, super, rhs);
  std::copy(rhs.begin(), rhs.end(), M.begin() + 1);
  return M;
}

std::vector<double> naturalSplineSlopesThreeMoment(const std::vector<double>& t,
                                                   const std::vector<double>& f) {
  const std::vector<double> M = naturalSplineMoments(t, f);
  const std::vector<double> d = secants(t, f);
  const std::size_t n = t.size() - 1;
  std::vector<double> m(n + 1);
  // Equation 8 at the segments' ends.
  for (std::size_t k = 0; k < n; ++k) m[k] = d[k] - (t[k + 1] - t[k]) * (2 * M[k] + M[k + 1]) / 6;
  m[n] = d[n - 1] + (t[n] - t[n - 1]) * (M[n - 1] + 2 * M[n]) / 6;
  return m;
}

double PvtTrack::valueAt(double th) const {
  if (theta.empty()) return 0;
  if (theta.size() == 1 || th <= theta.front()) return position.front();
  if (th >= theta.back()) return position.back();
  const std::size_t i = std::upper_bound(theta.begin(), theta.end(), th) - theta.begin() - 1;
  return hermiteValue(theta[i], theta[i + 1], position[i], position[i + 1], slope[i], slope[i + 1], th);
}

PvtTrack buildPvtTrack(const std::vector<SpiralPoint>& nodes, StsInterpolation method) {
  PvtTrack track;
  for (const SpiralPoint& q : nodes) {
    track.theta.push_back(q.theta);
    track.position.push_back(q.z);
  }
  switch (method) {
    case StsInterpolation::Hermite: track.slope = pvtThreePointSlopes(track.theta, track.position); break;
    case StsInterpolation::SplineThreeSlope:
      track.slope = naturalSplineSlopesThreeSlope(track.theta, track.position);
      break;
    case StsInterpolation::SplineThreeMoment:
      track.slope = naturalSplineSlopesThreeMoment(track.theta, track.position);
      break;
  }
  return track;
}

double trajectoryCurvature(const StsSurface& surface, const SpiralParameters& p, double theta) {
  const double end = p.endAngle();
  const double delta = 1e-3;  // rad; rounding in z stays ~1e-16 mm / delta^2, far below curvature
  const double th = std::clamp(theta, delta, std::max(delta, end - delta));
  auto z = [&](double a) { return compensateNoseRadius(surface, p.radiusAt(a), a, p.toolRadius).z; };
  const double zm = z(th - delta), z0 = z(th), zp = z(th + delta);
  // X = r moves uniformly with theta: dX/dtheta = -a_f / 2 pi.
  const double xTheta = p.feedPerRev / kTwoPi;
  const double zx = (zp - zm) / (2 * delta) / xTheta;
  const double zxx = (zp - 2 * z0 + zm) / (delta * delta) / (xTheta * xTheta);
  return std::abs(zxx) / std::pow(1 + zx * zx, 1.5);
}

std::vector<double> uniformNodeAngles(const SpiralParameters& p, std::size_t count) {
  if (count < 2) badParameter("uniform nodes: at least two nodes are needed");
  const double end = p.endAngle();
  std::vector<double> t(count);
  for (std::size_t i = 0; i < count; ++i) t[i] = end * double(i) / double(count - 1);
  t.back() = end;
  return t;
}

NonUniformNodes nonUniformNodeAngles(const StsSurface& surface, const SpiralParameters& p,
                                     const std::vector<SpiralPoint>& contactPoints, double rhoMax,
                                     int maxInserted) {
  NonUniformNodes out;
  if (contactPoints.empty()) return out;
  std::vector<double> atPoint(contactPoints.size());
  for (std::size_t i = 0; i < contactPoints.size(); ++i)
    atPoint[i] = trajectoryCurvature(surface, p, contactPoints[i].theta);
  out.rhoMax = rhoMax > 0 ? rhoMax
                          : std::accumulate(atPoint.begin(), atPoint.end(), 0.0) / atPoint.size();
  out.theta.push_back(contactPoints.front().theta);
  for (std::size_t i = 0; i + 1 < contactPoints.size(); ++i) {
    const double a = contactPoints[i].theta, b = contactPoints[i + 1].theta;
    const double rho = std::max({atPoint[i], atPoint[i + 1], trajectoryCurvature(surface, p, 0.5 * (a + b))});
    int extra = 0;
    // Capped in double before the cast: a near-infinite ratio must not overflow an int.
    if (out.rhoMax > 0 && rho > out.rhoMax)
      extra = static_cast<int>(std::min<double>(maxInserted, std::ceil(rho / out.rhoMax) - 1));
    for (int j = 1; j <= extra; ++j) out.theta.push_back(a + (b - a) * j / (extra + 1));
    out.inserted += std::max(0, extra);
    out.theta.push_back(b);
  }
  return out;
}

std::vector<SpiralPoint> cuttingLocationPointsAt(const StsSurface& surface,
                                                 const SpiralParameters& p,
                                                 const std::vector<double>& thetas) {
  std::vector<SpiralPoint> out;
  out.reserve(thetas.size());
  for (double th : thetas) {
    SpiralPoint q = spiralContactPoint(surface, p, th);
    q.z = compensateNoseRadius(surface, q.r, th, p.toolRadius).z;
    out.push_back(q);
  }
  return out;
}

ErrorProfile interpolationError(const StsSurface& surface, const SpiralParameters& p,
                                const PvtTrack& track, int samplesPerSegment) {
  ErrorProfile e;
  const auto& t = track.theta;
  if (t.size() < 2) return e;
  e.perSegment.assign(t.size() - 1, 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    for (int j = 1; j <= samplesPerSegment; ++j) {
      const double th = t[i] + (t[i + 1] - t[i]) * j / (samplesPerSegment + 1);
      const double exact = compensateNoseRadius(surface, p.radiusAt(th), th, p.toolRadius).z;
      const double err = std::abs(track.valueAt(th) - exact);
      recordError(e, p, i, th, err);
    }
  }
  return e;
}

}  // namespace isurface
