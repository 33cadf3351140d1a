#pragma once
// One unit per quantity inside iSurface: mm, s, mm/s, mm/s^2, mm/s^3, radians. Feeds shown to
// users (F words, JSON fields named *_mm_min, the display) are mm/min: they meet the internal
// mm/s here and nowhere else. Spindle speeds are given in rev/min (rpm) and meet rad/s here.
//
// Each conversion is written once, with its arithmetic fixed (a division by 60 stays a division,
// never a multiplication by 1/60): results are bit for bit those of the code it replaced.

namespace isurface {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;   // exact: doubling does not round
constexpr double kHalfPi = kPi / 2;  // exact: halving does not round

// Angles are radians inside; degrees only where shown or typed (options, reports).
constexpr double kDegreesPerRadian = 180.0 / kPi;

constexpr double kSecondsPerMinute = 60.0;

// Inch programs (G20) are read into mm and, when rewritten, written back in inches.
constexpr double kMmPerInch = 25.4;  // exact, by definition

// mm/min (an F word, a display) -> mm/s.
constexpr double mmPerMinToMmPerS(double mmPerMin) { return mmPerMin / kSecondsPerMinute; }
// mm/s -> mm/min (an F word, a display).
constexpr double mmPerSToMmPerMin(double mmPerS) { return mmPerS * kSecondsPerMinute; }

// Spindle speed rev/min -> angular speed rad/s: rpm * 2 * pi / 60, in that order.
constexpr double rpmToRadPerS(double rpm) { return rpm * 2 * kPi / kSecondsPerMinute; }
// Spindle speed rev/min -> deg/s: rpm * 6 (360 / 60 is exactly 6).
constexpr double rpmToDegreesPerS(double rpm) { return rpm * (360.0 / kSecondsPerMinute); }
// Time (s) the spindle takes to turn one radian at `rpm`: 60 / (rpm * 2 pi).
constexpr double secondsPerRadianAtRpm(double rpm) { return kSecondsPerMinute / (rpm * kTwoPi); }

}  // namespace isurface
