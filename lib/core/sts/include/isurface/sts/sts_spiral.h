#pragma once
// Spiral tool paths for slow tool servo turning (the STS tool path paper, section 2).
//
// The tool feeds from the rim to the centre while the spindle (C axis) turns: equation 1,
//   r(theta) = R - a_f theta / (2 pi),  z = f(r cos theta, r sin theta),
// with R the workpiece radius (mm), a_f the feed per revolution (mm/rev) and theta >= 0 the
// spindle angle (rad) from the entry point. The path ends at the centre, theta_end = 2 pi R / a_f.
//
// Cutting contact points (CCPs) are chosen along the spiral by equal angle, equal arc length
// or equal height discretisation, then moved to cutting location points (CLPs) by tool nose
// radius compensation along Z.
#include <string>
#include <vector>

#include "isurface/base/units.h"
#include "isurface/sts/sts_surface.h"

namespace isurface {

enum class StsDiscretisation { EqualAngle, EqualArcLength, EqualHeight };
StsDiscretisation parseStsDiscretisation(const std::string& word);  // angle|arc|height
std::string toString(StsDiscretisation method);

struct SpiralParameters {
  double workpieceRadius = 20.0;  // R, mm
  double feedPerRev = 0.5;        // a_f, mm/rev
  double angleStep = 5.0 * kPi / 180.0;  // allowable angle, rad
  double arcStep = 1.0;     // allowable arc length in the XY plane, mm
  double heightStep = 0.04; // allowable height difference Delta Z_m, mm
  double toolRadius = 0.2;  // tool nose radius R_t, mm

  void validate() const;  // throws InputError for a non-positive or inconsistent value
  double endAngle() const;                     // theta_end, rad
  double radiusAt(double theta) const;         // r(theta), mm (0 past the end)
  // d(XY arc length)/d theta = sqrt(r^2 + (a_f / 2 pi)^2), mm/rad.
  double arcRate(double theta) const;
};

struct SpiralPoint {
  double theta = 0;  // rad, from the entry point
  double r = 0;      // mm
  double z = 0;      // mm
  double x() const;  // r cos theta, mm
  double y() const;  // r sin theta, mm
};

// The CCP on the spiral at angle theta.
SpiralPoint spiralContactPoint(const StsSurface& surface, const SpiralParameters& p, double theta);

// CCPs from the entry point (theta = 0) to the centre (theta_end), both included.
// EqualAngle steps by angleStep; EqualArcLength by arcStep of spiral length in the XY plane;
// EqualHeight follows the paper's Figures 2-3: try the equal arc length step; when that exceeds
// the allowable angle and keeps |dz| within heightStep, take the equal angle step instead; while
// |z_{i+1} - z_i| > heightStep, halve the step (theta_{i+1} <- (theta_i + theta_{i+1}) / 2).
std::vector<SpiralPoint> discretiseSpiral(const StsSurface& surface, const SpiralParameters& p,
                                          StsDiscretisation method);

// Z-direction tool nose compensation. The tool keeps the CCP's X (= r) and C (= theta), which
// keeps the X axis moving uniformly; its nose, an arc of radius R_t in the radial plane, is lifted
// until it touches the surface's radial section without cutting into it. Returns the height of
// the nose's lowest point (the CLP, mm) and where it touches, as a radial offset from r (mm).
// For a plane of radial slope s the lift is R_t (sqrt(1 + s^2) - 1).
struct NoseCompensation {
  double z = 0;              // CLP height, mm
  double contactOffset = 0;  // contact point radius minus r, mm
};
NoseCompensation compensateNoseRadius(const StsSurface& surface, double r, double theta,
                                      double toolRadius);

// The CLPs of the CCPs (same theta and r; z compensated).
std::vector<SpiralPoint> cuttingLocationPoints(const StsSurface& surface,
                                               const std::vector<SpiralPoint>& contactPoints,
                                               double toolRadius);

// Maximum absolute error per segment [i, i+1] (mm, size n - 1) and over all.
struct ErrorProfile {
  std::vector<double> perSegment;
  double max = 0;
  double thetaAtMax = 0;  // rad
  double radiusAtMax = 0; // mm
  // The maximum away from the path's ends (more than one revolution from the entry point and
  // from the centre), where the spline's natural end conditions do not weigh in, mm.
  double interiorMax = 0;
};

// Records one sample's absolute error in `e` (segment `segment`, spindle angle theta).
void recordError(ErrorProfile& e, const SpiralParameters& p, std::size_t segment, double theta,
                 double error);

// The paper's discrete error: the CCPs' heights are interpolated against theta by the natural
// cubic spline and compared with the surface along the spiral at `samplesPerSegment` points
// inside every segment.
ErrorProfile discreteError(const StsSurface& surface, const SpiralParameters& p,
                           const std::vector<SpiralPoint>& contactPoints, int samplesPerSegment = 8);

}  // namespace isurface
