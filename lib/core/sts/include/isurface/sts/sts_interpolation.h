#pragma once
// PVT (position-velocity-time) interpolation of STS tool paths (the STS tool path paper,
// section 3). The controller joins consecutive nodes by the cubic Hermite polynomial fixed by the
// two positions and two velocities (equations 2-3); methods differ only in the node velocities:
//  - segment cubic Hermite: each node's velocity is the slope of the parabola through the node
//    and its two neighbours (the mean of the two secant velocities on evenly spaced nodes; the
//    first or last three nodes at the ends); velocity is continuous, acceleration is not;
//  - segment cubic spline, natural boundary conditions (zero acceleration at both ends): the
//    velocities solve the three-slope equations (7) or follow from the three-moment
//    equations (9); both give the same curve, continuous in acceleration.
// Spindle speed is constant, so time is proportional to the spindle angle theta: the tracks
// below are parameterised by theta (rad); dividing by the spindle rate gives time.
#include <string>
#include <vector>

#include "isurface/sts/sts_spiral.h"

namespace isurface {

enum class StsNodes { Uniform, NonUniform };
StsNodes parseStsNodes(const std::string& word);  // uniform|nonuniform
std::string toString(StsNodes nodes);

enum class StsInterpolation { Hermite, SplineThreeSlope, SplineThreeMoment };
StsInterpolation parseStsInterpolation(const std::string& word);  // hermite|spline|spline-moment
std::string toString(StsInterpolation method);

// The cubic through (t0, f0) and (t1, f1) with slopes v0 and v1, evaluated at t.
double hermiteValue(double t0, double t1, double f0, double f1, double v0, double v1, double t);

// Node slopes for knots t (strictly increasing) and values f; at least two knots.
std::vector<double> pvtThreePointSlopes(const std::vector<double>& t, const std::vector<double>& f);
std::vector<double> naturalSplineSlopesThreeSlope(const std::vector<double>& t,
                                                  const std::vector<double>& f);
// Second derivatives M_k of the natural spline (M_0 = M_n = 0) from the three-moment equations.
std::vector<double> naturalSplineMoments(const std::vector<double>& t, const std::vector<double>& f);
std::vector<double> naturalSplineSlopesThreeMoment(const std::vector<double>& t,
                                                   const std::vector<double>& f);

// A piecewise cubic Hermite track z(theta).
struct PvtTrack {
  std::vector<double> theta;     // knots, rad, increasing
  std::vector<double> position;  // mm
  std::vector<double> slope;     // dz/dtheta, mm/rad
  double valueAt(double th) const;  // clamped to the knot range
};
PvtTrack buildPvtTrack(const std::vector<SpiralPoint>& nodes, StsInterpolation method);

// Curvature (mm^-1) of the tool path as the PVT track sees it: the compensated (CLP) height Z
// against the X axis, which moves uniformly with the spindle angle (X = r(theta)), so that
// "uniform in X" and "uniform in time" are the same nodes: |Z_XX| / (1 + Z_X^2)^1.5, by central
// differences. Largest where Z turns (its peaks and valleys along the spiral).
double trajectoryCurvature(const StsSurface& surface, const SpiralParameters& p, double theta);

// `count` (>= 2) node angles evenly spaced in theta, hence in X, from 0 to theta_end.
std::vector<double> uniformNodeAngles(const SpiralParameters& p, std::size_t count);

// Non-uniform nodes: the CCPs' angles, with extra nodes where the path bends (Figure 6): a
// segment whose largest curvature rho (at its ends and middle) exceeds rhoMax gets
// min(ceil(rho / rhoMax) - 1, maxInserted) nodes evenly inside it. rhoMax <= 0 means the mean
// curvature over the CCPs.
struct NonUniformNodes {
  std::vector<double> theta;  // rad
  double rhoMax = 0;          // mm^-1, the threshold used
  std::size_t inserted = 0;   // nodes added to the CCPs
};
NonUniformNodes nonUniformNodeAngles(const StsSurface& surface, const SpiralParameters& p,
                                     const std::vector<SpiralPoint>& contactPoints, double rhoMax,
                                     int maxInserted = 4);

// CLPs at the given angles (CCP on the spiral, then nose compensation).
std::vector<SpiralPoint> cuttingLocationPointsAt(const StsSurface& surface,
                                                 const SpiralParameters& p,
                                                 const std::vector<double>& thetas);

// The paper's interpolation error: the PVT track's Z minus the compensated tool height computed
// exactly at `samplesPerSegment` points inside every segment, mm.
ErrorProfile interpolationError(const StsSurface& surface, const SpiralParameters& p,
                                const PvtTrack& track, int samplesPerSegment = 8);

}  // namespace isurface
