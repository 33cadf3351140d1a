#pragma once
// Giving a recorded trace the G-code line of each sample when the recording has none, from the
// program it ran: each sample goes to the programmed move nearest to it, walking the program
// forward only, so that a pass crossing an earlier one is not mistaken for it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isurface/gcode/program.h"
#include "isurface/base/trajectory.h"

namespace isurface {

struct LineMappingOptions {
  // How many motion moves ahead of the current one a sample may land on. Raise it for traces
  // sampled so slowly that many short moves pass between two samples.
  std::size_t lookaheadMoves = 8;
  double tolerance = 0.1;  // mm, the distance counted as "on the path" in the report
  // Controllers that report the line of the move they are blending into (LinuxCNC's
  // motion.program-line under G64) switch lines before the programmed corner. With this set, a
  // sample within `lead` of the end of a move, before a corner deflecting by more than
  // blendMinAngle (and not reversing), takes the next move's line, where
  // lead = min(blendFraction * the shorter of the two moves, maxBlendLead).
  // Off (the default): every sample takes the line of the move nearest to it.
  bool nextLineInBlends = false;
  double blendMinAngle = 0.001;  // rad, gentler corners are passed as tangent, without a blend
  double blendFraction = 0.5;    // LinuxCNC's upper bound (BLEND_DIST_FRACTION)
  double maxBlendLead = 1e9;     // mm
};

struct LineMappingReport {
  std::size_t samples = 0;      // samples with a finite position, the ones mapped
  double meanDistance = 0;      // mm, sample to its chosen move
  double maxDistance = 0;       // mm
  double fractionWithin = 0;    // of the mapped samples, those within the tolerance
  double tolerance = 0.1;       // mm
};

struct LineMapping {
  std::vector<std::uint32_t> line;  // per sample, 1-based G-code line, 0 when not mapped
  std::vector<double> distance;     // mm per sample to its move (NaN when not mapped)
  LineMappingReport report;
};

// Blend handover fitted to LinuxCNC 2.9's recording in shared realdata (1 ms, 1000 mm/s^2, G64):
// its line switches about 0.42 mm before the corners of 1 mm moves, and well under a millimetre
// before those of long moves at these feeds. An approximation of its planner, not a model of it.
LineMappingOptions linuxcncLineMappingOptions();

// Maps every sample of `samples` (commanded positions) to a line of `program`. A program with
// no motion leaves every line 0.
LineMapping mapSamplesToLines(const Trajectory& samples, const Program& program,
                              const LineMappingOptions& options = {});

// Distance (mm) from `point` to the exact path of motion move `moveIndex` of `program`.
double distanceToMove(const Program& program, std::size_t moveIndex, const Vec3& point);

}  // namespace isurface
