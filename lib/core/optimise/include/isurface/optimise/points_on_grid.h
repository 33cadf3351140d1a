#pragma once
// The points of a smooth path, each moved a little along the path, so that written to the last
// decimal of a program they still lie on it. An NC that plans at every point estimates the
// curvature from three points, and rounding makes that estimate noise where the points are
// close: pieces of 0.05 mm written to 0.1 um alternate between curvatures 0 and 1/25 mm on a
// bend of radius 300 mm, and a machine that holds its chord tolerance slows at each, differently
// from one pass to the next.
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

// `points`, mm, on a smooth path (each piece turning by little); `grid`, mm, the step of the last
// decimal written (0.0001 for 4 decimals of mm, 0.000254 for 5 of an inch). Each point but the
// ends slides along the parabola through it and its neighbours, by up to a quarter of the shorter
// piece beside it, to where its rounding carries it least off that parabola; returned rounded to the
// grid (the ends too). A point next to a piece shorter than a thousandth of a micrometre stays.
std::vector<Vec3> pointsOnGrid(const std::vector<Vec3>& points, double grid);

}  // namespace isurface
