#pragma once
// Region re-optimisation (the loop of the paper's Figure 6): the G1 moves of a line range are
// split into passes, each pass is fitted by an Akima spline in arc length and resampled into
// G1 moves within a chord tolerance, and every constant speed interval gets one feed; or,
// instead of the fit, its points are drawn taut or its corners rounded (PathShape) and it keeps
// the program's feed.
// Every line outside the changed passes is kept byte for byte; new blocks carry comments naming
// the lines they replace.
#include <cstdint>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/machine/machine.h"
#include "isurface/surface/passes.h"
#include "isurface/gcode/program.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/base/trajectory.h"

namespace isurface {

// How interval feeds are planned across passes.
enum class CrossPassRule {
  None,      // each pass keeps its own interval feeds (the paper's steps, pass by pass)
  Median,    // an interval runs at the median feed of the passes around it, never above its own
  Envelope,  // an interval runs at the slowest feed of the passes around it
};

// How a pass's path is drawn anew.
enum class PathShape {
  Fitted,          // an Akima spline through the program's own points (the paper's steps)
  DrawnTaut,       // its points drawn taut within maximumDeviation (taut_path.h), not fitted
  CornersRounded,  // its corners cut by arcs within maximumDeviation (rounded_corners.h), not fitted
  Eased,           // the Akima fit with its bends eased in and out within maximumDeviation (eased_path.h)
};

// mm: how far a chord of the new G1 moves may stray from the fitted spline unless the user
// says otherwise (`--tolerance`).
constexpr double kDefaultChordTolerance = 0.005;

struct OptimizeOptions {
  IntervalThresholds thresholds;
  double chordTolerance = kDefaultChordTolerance;  // mm, resampling of the spline into G1 moves
  // mm: a fit that strays further from the old path is not used; a path drawn taut or rounded
  // stays within it.
  double maximumDeviation = 0.008;
  double maxTurn = 0.01;          // rad, largest turn of the path between two new G1 moves
  std::size_t minimumMoves = 4;   // shorter runs of moves are left as they are
  double feedScale = 1.0;         // share of each interval's planned feed that is programmed
  // mm/s^2: the centripetal acceleration v^2 * curvature no move of a bend exceeds, taken at
  // every point (feed_ramps.h); 0: only the machine's limits.
  double normalAccelerationLimit = 0;
  // mm/s^2: changes of feed between intervals spread into ramps at this acceleration
  // (feed_ramps.h); 0: one step at the interval's end.
  double rampAcceleration = 0;
  // XY, mm: where the region's figures are taken. Outside, ramps run at half the machine's
  // acceleration (its slowest axis) instead, if that is faster (feed_ramps.h): gentle ramps are
  // what evens the speed where it is judged, and cost time everywhere; a quick one still spares
  // the servo the NC's full braking into a bend. None: rampAcceleration everywhere.
  std::optional<std::pair<Vec3, Vec3>> rampBox;
  // XY, mm: where a pass crosses this box's stretch of it (the box's extent along the pass, a
  // margin added) is what is re-planned, from its first move that reaches into the stretch to its
  // last; its moves before and after stay as they were. A pass over a part with two bends,
  // re-planned from end to end for a defect at one, changes its speed at the other too, where
  // its neighbours cut the other way slowed alike before. None: whole passes.
  std::optional<std::pair<Vec3, Vec3>> planBox;
  CrossPassRule crossPass = CrossPassRule::None;
  PathShape shape = PathShape::Fitted;  // how each pass's path is drawn anew
  // Every interval keeps the program's feed, so that the NC's planner alone sets the speed
  // (where it already runs at its own limits at every point, one feed per interval is slower),
  // but no faster than `feedCap` (mm/min, whole; 0: no cap).
  bool programmedFeed = false;
  double feedCap = 0;
  // mm/min, indexed by source line (0: none): no interval runs faster than the lowest ceiling
  // of the old lines it replaces.
  std::vector<double> lineFeedCeiling;
};

struct OptimizedPass {
  std::uint32_t firstLine = 0, lastLine = 0;        // replaced source lines
  // Where their replacement stands in the output: its comment line, then one block per new move.
  std::uint32_t newFirstLine = 0, newLastLine = 0;
  std::size_t oldMoves = 0, newMoves = 0;
  std::vector<double> intervalFeeds;                // mm/min, one per constant speed interval
  std::vector<std::uint32_t> sourceLines;           // per new move, the old line it stands for
};

struct OptimizeResult {
  std::string text;                    // the new program
  std::vector<OptimizedPass> passes;
  LineRange newRange;                  // the region's lines in the new program
  // Where the path was re-fitted (the intervals with curvature, not the straight runs), mm:
  // the part of the surface the comparison looks at.
  Vec3 fittedLower = Vec3::Zero(), fittedUpper = Vec3::Zero();
};

// `text` is the program's source, `program` its interpretation. Throws InputError when the
// range holds no run of plain G1 moves to optimise.
OptimizeResult optimizeRegion(const std::string& text, const Program& program, LineRange lines,
                              const Machine& machine, const OptimizeOptions& options = {});

// The first and last source line of a pass's samples ({UINT32_MAX, 0} when it has none).
LineRange linesOfPass(const Trajectory& samples, const Pass& pass);

// A region's lines widened to whole passes and one more pass on each side: optimising only
// part of a pass, or stopping at the region's last pass, would leave a seam (a pass next to an
// unchanged neighbour) inside the region. Lines outside every pass are returned unchanged.
LineRange widenToWholePasses(const Trajectory& samples, const PassSet& passes, LineRange lines);

}  // namespace isurface
