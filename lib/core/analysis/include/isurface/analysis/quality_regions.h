#pragma once
// Quality prediction (the paper's Figure 6): regions of the CL surface where adjacent passes
// disagree in speed or acceleration, or where consecutive samples jerk, beyond thresholds:
// where pits and bulges are to be expected. Each region is ranked by severity and tied to the
// G-code lines that made it.
#include <cstdint>
#include <vector>

#include "isurface/surface/surface_mesh.h"
#include "isurface/base/trajectory.h"

namespace isurface {

struct QualityThresholds {
  double speedInconsistency = 150;   // mm/min between neighbouring passes
  double accelInconsistency = 600;   // mm/s^2 between neighbouring passes
  double jerk = 40000;               // mm/s^3 along the path (consecutive samples disagreeing)
  std::size_t minimumVertices = 3;   // smaller clusters are noise, not a region
  double passEndLength = 3.0;        // mm from a pass's start or end: where the tool enters or leaves it
};

struct QualityRegion {
  double severity = 0;               // sum over its vertices of the worst threshold ratio exceeded
  std::uint32_t firstLine = 0, lastLine = 0;  // G-code lines of its samples
  std::size_t vertices = 0;
  double area = 0;                   // mm^2 of the triangles whose corners all lie in it
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero(), centroid = Vec3::Zero();  // mm
  double maxSpeedInconsistency = 0;  // mm/min
  double maxAccelInconsistency = 0;  // mm/s^2
  double maxJerk = 0;                // mm/s^3
  double maxDeviation = 0;           // um, largest |predicted deviation| (0 without feedback)
  std::size_t worstSample = 0;       // the sample where the worst ratio is
  // Every vertex lies within passEndLength of its pass's start or end: marks of starting and
  // stopping at the edge of the cut, which re-fitting the path cannot change.
  bool atPassEnds = false;
};

struct QualityReport {
  std::vector<QualityRegion> regions;  // most severe first
  std::size_t flaggedVertices = 0, vertices = 0;
};

// Regions are the connected parts (through the mesh's triangles) of the vertices beyond a
// threshold.
QualityReport findQualityRegions(const Trajectory& samples, const SurfaceMesh& mesh,
                                 const QualityThresholds& thresholds = {});

// The most severe region away from the pass ends (what re-fitting can improve); null if none.
const QualityRegion* worstRegionInsidePasses(const QualityReport& report);

}  // namespace isurface
