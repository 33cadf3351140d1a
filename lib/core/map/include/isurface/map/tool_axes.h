#pragma once
// The tool axis along a five-axis run: strokes from the tool tip along the tool's direction, from
// the samples' tool_i tool_j tool_k channels (written by a five-axis simulation).
#include <array>
#include <vector>

#include "isurface/base/trajectory.h"
#include "isurface/surface/passes.h"

namespace isurface::vis {

// The samples carry the tool axis.
bool hasToolAxes(const Trajectory& samples);

// A stroke (tip, a point `length` mm up the tool axis) every `spacing` mm along each pass, and at
// each pass's start; none where the axis is not finite. Throws InputError when the samples have
// no tool axis.
std::vector<std::array<Vec3, 2>> toolAxisMarks(const Trajectory& samples, const PassSet& passes, double spacing,
                                               double length);

}  // namespace isurface::vis
