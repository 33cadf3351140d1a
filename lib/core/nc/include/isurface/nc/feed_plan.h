#pragma once
// Feed planning with look-ahead over the whole program.
//
// The plan is made in two stages that together give a jerk-limited (S-curve) motion:
//  1. an acceleration-limited speed profile along the exact geometry (lines and arcs), with
//     speed limits per segment (feed, axis velocities, arc curvature) and per junction
//     (corner angle, curvature estimated from three points between short G1 moves), found by a
//     forward and a backward pass over all segments, so that short moves flow at speed;
//  2. two moving-average filters applied to the interpolated axis positions (see
//     interpolator.h). A moving average of length T1 turns an acceleration bounded by a into
//     jerk bounded by 2a/T1, and the second, shorter one spreads the velocity change at a
//     corner so that corners, too, have bounded jerk. The filters move samples off the
//     programmed path at corners and on curves; the limits of stage 1 keep that deviation
//     within the machine's chord tolerance.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "isurface/base/progress.h"
#include "isurface/machine/machine.h"
#include "isurface/gcode/program.h"

namespace isurface {

// How the machine's limits are shared between the effects that add up on one axis.
struct LimitBudget {
  double tangentialAccel = 0.5;  // fraction of axis acceleration for speeding up and slowing down
  // Without a jerk limit no filter time depends on the tangential share, so where a segment
  // has no curvature to share its axes with, it may use up to this much.
  double tangentialAccelWithoutJerkLimit = 0.85;
  double normalAccel = 0.35;     // for centripetal acceleration on curves
  double cornerAccel = 0.15;     // for the velocity change at a corner, spread by the filters
  double tangentialJerk = 0.6;   // fraction of axis jerk for the filtered ramps
  double normalJerk = 0.25;      // for the turning of the centripetal acceleration on curves
  double cornerJerk = 0.15;      // for the corner velocity change after both filters
  double cornerTolerance = 0.75; // fraction of the chord tolerance spent on rounding corners and curves
};

struct PlannedSegment {
  std::uint32_t move = 0;   // index in Program::moves
  double length = 0;        // mm
  double entrySpeed = 0;    // mm/s
  double peakSpeed = 0;     // mm/s
  double exitSpeed = 0;     // mm/s
  double accel = 0;         // mm/s^2, tangential, for both ramps
  double holdAfter = 0;     // s of standstill after the segment (dwell)
  double cap = 0;           // mm/s, the segment's own speed limit (feed, axes, curvature)
  double entryLimit = 0;    // mm/s, the limit at its start junction before look-ahead
  // The generic control's path smoothed within its tolerance: a line is shortened by the corner
  // blends next to it (mm at each end); a segment with cornerReach > 0 is the blend arc at the
  // start of its move, tangent to the line before and to its move, reaching this far (mm) along
  // each from the corner.
  double trimStart = 0, trimEnd = 0;
  double cornerReach = 0;
  // With a jerk limit, the generic control runs a run of short G1 chords as a curve through
  // their points (`chord_run.h`): where `smooth`, this segment is its whole move as that curve,
  // whose ends are packed here (offset from the move's end points, mm; tangent; curvature, 1/mm).
  bool smooth = false;
  std::array<float, 18> chordCurve{};

  double accelTime() const { return accel > 0 ? (peakSpeed - entrySpeed) / accel : 0; }
  double decelTime() const { return accel > 0 ? (peakSpeed - exitSpeed) / accel : 0; }
  double accelDistance() const { return 0.5 * (entrySpeed + peakSpeed) * accelTime(); }
  double decelDistance() const { return 0.5 * (exitSpeed + peakSpeed) * decelTime(); }
  double cruiseTime() const;
  double motionTime() const { return accelTime() + cruiseTime() + decelTime(); }
};

struct FeedPlan {
  std::vector<PlannedSegment> segments;  // zero-length moves are left out
  double holdBefore = 0;                 // s of dwell before the first motion
  double filterTime1 = 0;                // s, jerk filter (0 when jerk is not limited)
  double filterTime2 = 0;                // s, corner filter
  double cycle = 0.001;                  // s

  // Time of the unfiltered profile, s.
  double profileDuration() const;
};


FeedPlan planFeed(const Program& program, const Machine& machine, const LimitBudget& budget = {},
                  const ProgressCallback& progress = {});

// The same plan made with a bounded look-ahead window, for programs that are not held whole:
// moves go in one by one, and out come the segments whose profile later moves can no longer
// change, bit for bit those of planFeed. A segment is final once the window ahead of it reaches
// a junction where the speed is set by what lies behind (a corner, a stop, a cap), not by a stop
// assumed at the window's end; so the window spans about one braking distance from the highest
// speed reached (at most V^2 / 2a, 107 mm at 24 m/min and 750 mm/s^2) plus commitEvery
// segments. A window that would hold more than maxHeld segments (a braking distance over that
// many tiny segments) commits all but maxHeld / 2 of them as if the machine stopped at its end:
// slower there than planFeed, never beyond a limit, and counted by forcedCommits(). Memory: about 120 bytes per
// segment held. The machine must outlive the planner.
class StreamingFeedPlanner {
 public:
  struct Window {
    std::size_t commitEvery = 4096;         // segments between attempts to commit
    std::size_t maxHeld = std::size_t{1} << 17;
  };

  StreamingFeedPlanner(const Machine& machine, const LimitBudget& budget, std::string source, const Window& window);
  ~StreamingFeedPlanner();
  StreamingFeedPlanner(const StreamingFeedPlanner&) = delete;
  StreamingFeedPlanner& operator=(const StreamingFeedPlanner&) = delete;

  // Move `index` of the program, which starts at `start` (the end of the move before it). Throws
  // InputError for a dwell longer than a day, and (here or in take()) for a move that would be.
  void add(std::uint32_t index, const Move& move, const Vec3& start);
  // No more moves: the machine comes to rest after the last one.
  void finish();
  // Appends the segments whose profile is final, in order (after finish(), all that are left).
  void take(std::vector<PlannedSegment>& out);

  double holdBefore() const;  // s of dwell before the first motion; final once a segment is out
  double filterTime1() const;
  double filterTime2() const;
  std::size_t held() const;         // segments in the window now
  std::size_t largestHeld() const;  // the most it held
  std::size_t forcedCommits() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isurface
