#pragma once
// Linking samples, G-code lines and points in space (the paper's locate functions).
#include <cstddef>
#include <cstdint>
#include <optional>

#include "isurface/core/trajectory.h"

namespace isurface {

// The first sample produced by a G-code line (as the paper's locate does), if any.
std::optional<std::size_t> firstSampleOfLine(const Trajectory& samples, std::uint32_t line);

// The sample nearest to a point (commanded positions), if there are samples.
std::optional<std::size_t> nearestSample(const Trajectory& samples, const Vec3& point);

}  // namespace isurface
