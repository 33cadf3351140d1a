#pragma once
// One servo cycle of LinuxCNC 2.9's planner over its queue (tpRunCycle): the front segment's
// trapezoid (or ramp) for the cycle, its parabolic blend into the next, the split cycle in
// which a segment ends and the next begins.
#include <deque>

#include "linuxcnc_segment.h"

namespace isurface::linuxcnc {

struct MotionQueue {
  std::deque<Segment> segments;
  Vec3 position = Vec3::Zero();  // commanded, mm
  Vec3 rotary = Vec3::Zero();    // commanded A B C, deg
  double cycle = 0.001;          // s
};

// The speed the segment is commanded now (its feed, its limits) and the speed it may end at.
double realTargetVelocity(const Segment& s);
double realFinalVelocity(const Segment& s, const Segment* next);

// Runs one cycle (the queue must not be empty); removes the segment that ended in it. Returns
// the program move the cycle was mostly spent on.
SegmentPart runCycle(MotionQueue& queue);

}  // namespace isurface::linuxcnc
