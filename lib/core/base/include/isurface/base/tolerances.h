#pragma once
// Named tolerances shared by every module: what counts as zero, and why that size.

namespace isurface {

// Lengths below this are treated as zero (mm). Well below any machine's resolution.
constexpr double kLengthEpsilon = 1e-9;

// Three points are collinear when |a x b| is below this share of |a| |b| |c| (relative, so
// that it holds at any scale; about a thousand times the double's rounding of the product).
constexpr double kCollinearRelative = 1e-15;

}  // namespace isurface
