#pragma once
// How far apart two tool paths are: the figure that says a re-fitted path stayed within its
// tolerance of the programmed one.
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

// The largest distance from any point of `a`'s polyline vertices to `b`'s polyline, both ways
// (a Hausdorff distance over vertices), mm. Exact; about linear in the points for paths that
// run alike (a re-fitted region of a whole program: hundreds of thousands of points).
double polylineDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace isurface
