#pragma once
// One unit per quantity inside iSurface: mm, s, mm/s, mm/s^2, mm/s^3, radians. Feeds shown to
// users (F words, JSON fields named *_mm_min, the display) are mm/min: they meet the internal
// mm/s here and nowhere else.

namespace isurface {

constexpr double kPi = 3.14159265358979323846;

constexpr double kSecondsPerMinute = 60.0;

// mm/min (an F word, a display) -> mm/s.
constexpr double mmPerMinToMmPerS(double mmPerMin) { return mmPerMin / kSecondsPerMinute; }
// mm/s -> mm/min (an F word, a display).
constexpr double mmPerSToMmPerMin(double mmPerS) { return mmPerS * kSecondsPerMinute; }

}  // namespace isurface
