#pragma once
// The servo's positions of a simulated run, replayed from its commanded samples: the servo
// depends on nothing else, so a run simulated without them gets them when a view needs them.
#include "isurface/base/progress.h"
#include "isurface/base/trajectory.h"
#include "isurface/machine/machine.h"

namespace isurface {

// Offsets of the encoder positions from the commanded ones (mm), as the simulation with
// `machine` gives them; the servo starts at rest at `start` (the program's start, where the
// simulation started it: the first sample may differ from it in the last bit).
FeedbackOffsets servoFeedback(const Trajectory& commanded, const Machine& machine, const Vec3& start,
                              const ProgressCallback& progress = {});

}  // namespace isurface
