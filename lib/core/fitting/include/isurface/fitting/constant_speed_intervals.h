#pragma once
// Constant speed intervals of a tool path (section 2 of "Constant speed interval and quality
// prediction"): a run of cutter-location (CL) points whose curvature varies little is given one
// planned feed instead of one per point, so that the feed does not fluctuate from point to point.
//
// How the paper's steps are read here, where it leaves room:
//  - Step 2, characteristic points: the Douglas-Peucker simplification with tolerance E_thr. It
//    keeps the first and last points and every point needed so that the simplified polyline is
//    within E_thr of all original points. It is not guaranteed to be the very fewest such points,
//    but it is the usual stand-in and is exact on the paths the method is meant for.
//  - Curvature 1/rho_i comes from equation 1 (threePointRadius) with the ORIGINAL neighbours
//    i-1 and i+1, not the neighbouring characteristic points; collinear points have curvature 0.
//    The first and last points have no three-point circle and take their neighbour's curvature.
//  - Step 4: distance ratio L_i = |Q_{i+1} - Q_i| / |Q_i - Q_{i-1}| and curvature ratio
//    Q_i = k_i / k_{i-1} (k = 1/rho), both to the original neighbours. Guards: both curvatures
//    ~0 -> ratio 1; only the previous ~0 -> kLargeRatio; only this one ~0 -> 1 / kLargeRatio.
//  - Steps 5-6: a characteristic point strictly inside both threshold bands is inside an interval;
//    every other characteristic point, and always the first and last point, is a boundary.
//  - Step 7: the intervals are the spans between consecutive boundaries; neighbouring intervals
//    share their boundary point (it ends one and starts the next). Every original point between
//    two boundaries belongs to that interval, and its average curvature is the mean of 1/rho over
//    all of its original points.
//  - Only characteristic points are tested. Where a finely sampled arc meets a line tangentially,
//    the junction point is usually within E_thr of a chord and so not characteristic, and the
//    arc's own characteristic points all have Q ~ 1: line and arc then share one interval.
//  - Duplicate points (closer than kLengthEpsilon to the previous kept point) are dropped first;
//    indices reported are into the caller's sequence (the first of each run of duplicates).
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "isurface/base/line_range.h"
#include "isurface/base/geometry.h"
#include "isurface/gcode/program.h"

namespace isurface {

struct IntervalThresholds {
  double error = 0.1;           // E_thr, mm
  double distanceRatio = 5;     // L_thr, > 1
  double curvatureRatio = 2;    // Q_thr, > 1
};

// Stands for "unbounded" in a curvature ratio whose previous curvature is zero.
constexpr double kLargeRatio = 1e9;
// Curvatures below kZeroCurvature (isurface/base/tolerances.h, 1e-6 mm^-1) are zero.

struct CharacteristicPoint {
  std::size_t index = 0;       // into the caller's points
  Vec3 position = Vec3::Zero();
  double radius = std::numeric_limits<double>::infinity();  // mm, rho_i
  double distanceRatio = 1;    // L_i; NaN at the first and last point (one neighbour only)
  double curvatureRatio = 1;   // Q_i; NaN at the first point
  bool inside = false;         // inside an interval (false: starts or ends one)
};

struct ConstantSpeedInterval {
  std::size_t first = 0, last = 0;  // inclusive range of indices into the caller's points
  double averageCurvature = 0;      // mm^-1, mean of 1/rho over the interval's points
  double length = 0;                // mm, along the polyline
};

struct IntervalPartition {
  std::vector<CharacteristicPoint> characteristic;
  std::vector<ConstantSpeedInterval> intervals;
};

// Indices (into `points`) of the points that survive Douglas-Peucker with tolerance `tolerance`
// (mm), first and last included, ascending.
std::vector<std::size_t> douglasPeuckerIndices(const std::vector<Vec3>& points, double tolerance);

// k_i / k_previous with the guards described above.
double curvatureRatio(double curvature, double previousCurvature);

// Steps 2-7 on one section of CL points (mm). Fewer than two distinct points: no intervals; two:
// one interval; thresholds must be positive (ratios > 1), else InputError.
IntervalPartition partitionConstantSpeedIntervals(const std::vector<Vec3>& points,
                                                  const IntervalThresholds& thresholds = {});

// --- Sections of a program (step 1) ---

struct SectionOptions {
  double reversalAngleDeg = 90;  // a turn sharper than this in XY ends a raster pass
  double distanceThreshold = 50; // mm, cumulative length that ends a section without boundaries
  double arcChordError = 0.001;  // mm, largest chord error when sampling arcs into CL points
};

struct PathSection {
  std::vector<Vec3> points;          // CL points, mm
  std::vector<std::uint32_t> lines;  // source line of each point (the move that ends there)
  std::vector<double> feeds;         // mm/min, programmed feed of the move that ends there
};


// CL points of the feed moves (G1, G2, G3) whose source lines lie in [firstLine, lastLine]
// (1-based, inclusive), split into sections at raster pass boundaries, or, on a path with no such
// boundary, every `distanceThreshold` mm. Consecutive sections share their boundary point. A
// rapid move inside the range ends a section too. Empty when the range has no feed moves.
std::vector<PathSection> collectSections(const Program& program, std::uint32_t firstLine,
                                         std::uint32_t lastLine, const SectionOptions& options = {});

}  // namespace isurface
