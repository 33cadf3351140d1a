#pragma once
// A slow tool servo turning job from surface to NC program: discretisation, nose compensation,
// interpolation nodes, PVT track, errors; its NC program and JSON report; and the comparison
// with the figures the STS tool path paper reports for its two surfaces.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "isurface/sts/sts_interpolation.h"

namespace isurface {

// One of the paper's simulation cases: the surface and its Table 1 or Table 2 parameters.
struct StsCase {
  std::string surface;  // "toric" or "sinusoid"
  SpiralParameters spiral;
};
StsCase paperToricCase();     // Table 1
StsCase paperSinusoidCase();  // Table 2

// rev/min: the spindle speeds a job is planned for (PVT times and speeds stay readable numbers).
constexpr double kSlowestSpindleRpm = 0.001;
constexpr double kFastestSpindleRpm = 100000;

struct StsJobOptions {
  StsDiscretisation discretisation = StsDiscretisation::EqualHeight;
  StsNodes nodes = StsNodes::NonUniform;
  StsInterpolation interpolation = StsInterpolation::SplineThreeSlope;
  double rhoMax = 0;                // mm^-1; 0: the mean path curvature over the CCPs
  int maxInserted = 4;              // most nodes added inside one CCP segment
  std::size_t uniformNodeCount = 0; // 0: as many as CCPs
  double spindleRpm = 10;           // rev/min, turns spindle angle into PVT time
  int samplesPerSegment = 8;        // error samples inside each segment
};

struct StsJobResult {
  std::vector<SpiralPoint> contactPoints;  // CCPs
  ErrorProfile discrete;                   // per CCP segment
  std::vector<SpiralPoint> nodes;          // interpolation nodes, compensated (CLPs)
  PvtTrack track;                          // Z against theta
  ErrorProfile interpolation;              // per node segment
  double rhoMax = 0;                       // threshold used for non-uniform nodes, mm^-1
  std::size_t insertedNodes = 0;
  // Largest |three-slope - three-moment| node slope over the nodes, mm/rad (spline only, else 0).
  double splineSlopeDisagreement = 0;
};

StsJobResult runStsJob(const StsSurface& surface, const SpiralParameters& p, const StsJobOptions& o);

// The NC program: one block per node, "N<k> X<radius mm> C<spindle angle deg> Z<height mm>",
// with the PVT data as a trailing comment "; T<ms from the previous node> VX<mm/s> VC<deg/s>
// VZ<mm/s>". C accumulates over the revolutions. The header comments describe the job.
std::string formatStsNcProgram(const StsSurface& surface, const SpiralParameters& p,
                               const StsJobOptions& o, const StsJobResult& r);

// Parameters, counts, maxima and per-segment errors (mm).
nlohmann::json stsReportJson(const StsSurface& surface, const SpiralParameters& p,
                             const StsJobOptions& o, const StsJobResult& r);

// Maximum errors (mm) over the whole path and away from its ends (ErrorProfile::interiorMax).
struct StsErrorMaxima {
  double overall = 0, interior = 0;
};

// The comparison for one of the paper's cases.
struct StsPaperComparison {
  std::string surface;
  StsErrorMaxima discreteAngle, discreteArc, discreteHeight;
  std::size_t ccpAngle = 0, ccpArc = 0, ccpHeight = 0;
  // Interpolation of the equal height CCPs' path: uniform nodes are as many as those CCPs
  // (evenly spaced in X); non-uniform nodes are the CCPs plus the nodes added where the path
  // bends (nodeCount in all), as in the paper's Figure 6.
  std::size_t nodeCount = 0;
  StsErrorMaxima hermiteUniform, hermiteNonUniform, splineSlope, splineMoment;
  double slopeDisagreement = 0;  // three-slope vs three-moment node slopes, mm/rad
  // The paper's figures: discrete error reduction of equal height vs equal angle (fraction),
  // non-uniform vs uniform Hermite reduction (fraction); Hermite / spline is "two orders".
  double paperHeightReduction = 0, paperNodeReduction = 0, paperSplineRatio = 100;
};
StsPaperComparison compareWithPaper(const StsCase& c);
std::string formatStsPaperTable(const std::vector<StsPaperComparison>& rows);

}  // namespace isurface
