#pragma once
// Named tolerances shared by every module: what counts as zero, and why that size.

namespace isurface {

// Lengths below this are treated as zero (mm). Well below any machine's resolution.
constexpr double kLengthEpsilon = 1e-9;

// Three points are collinear when |a x b| is below this share of |a| |b| |c| (relative, so
// that it holds at any scale; about a thousand times the double's rounding of the product).
constexpr double kCollinearRelative = 1e-15;

// Curvatures below this are zero (mm^-1): a radius of a kilometre is a straight line here.
constexpr double kZeroCurvature = 1e-6;

// Searches for a nearest or highest point (golden section along a path, a pattern search on
// a surface) stop when their step is below this (mm): a nanometre, a thousandth of the
// finest tolerance a program works to (about a micrometre).
constexpr double kSearchResolution = 1e-6;

// A dimensionless factor about to be divided by (a direction cosine, the pitch of a helix, the
// sine of a turn) is zero below this, and a ratio this close to 1 is 1. About 4500 times the
// double's rounding of 1, so the rounding of a unit vector's components stays far inside, yet
// no real geometry comes near it (a pitch of 1e-12 rises a picometre over a metre).
constexpr double kRatioEpsilon = 1e-12;

// Slack in comparisons of dimensionless values of order 1 (cosines, scores, a ratio to a
// threshold, a length over a piece size before rounding up), so that the double's rounding
// (about 1e-16, times a few operations) cannot flip the result: ten million times that
// rounding, yet far below any difference that means something.
constexpr double kRoundingSlack = 1e-9;

// A G-code word's number counts as a whole number (an L or P count, a G or M code's tenths)
// within this: a decimal written with the usual 4 places is either exactly whole or at least
// 1e-4 away, while reading it into a double errs by about 1e-16 of its size.
constexpr double kWholeNumberTolerance = 1e-6;

// A point this close to a box's side (mm) lies on it: a region's extent is taken from samples
// interpolated between a program's points, and the pass on its edge, at the written coordinate,
// may lie outside it by the rounding of the last digits (4e-14 mm seen). Far below the 0.1 um
// a program writes.
constexpr double kOnBoxSide = 1e-6;

}  // namespace isurface
