#pragma once
// locate.h's questions answered in place from a dump (nothing is loaded): fast on any size.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "isurface/analysis/locate.h"

namespace isurface {

class BiipReader;

// Without a line channel no sample has a line.
std::optional<std::size_t> firstSampleOfLine(const BiipReader& reader, std::uint32_t line);
std::optional<std::size_t> nearestSample(const BiipReader& reader, const Vec3& point);
// `sample` must be below the number of records.
SampleMotion motionAtSample(const BiipReader& reader, std::size_t sample);

}  // namespace isurface
