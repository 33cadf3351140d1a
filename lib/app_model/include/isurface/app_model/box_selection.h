#pragma once
// Choosing a region by a rectangle dragged over the 3D view: the surface's samples that appear
// inside it give the G-code lines to re-optimise and the part of the workpiece they cover.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/base/geometry.h"
#include "isurface/base/trajectory.h"
#include "isurface/surface/passes.h"

namespace isurface::app_model {

// How a view maps points to its pixels: the camera's projection from world coordinates (mm) to
// normalised device coordinates (-1..1 across the view, +y up), and the view's size.
struct ScreenProjection {
  Eigen::Matrix4d worldToDevice = Eigen::Matrix4d::Identity();
  double width = 0, height = 0;  // pixels

  // Pixels from the view's top-left corner; nothing for a point behind the camera.
  std::optional<std::pair<double, double>> operator()(const Vec3& point) const;
};

// Pixels from the view's top-left corner; any two opposite corners.
struct ScreenRectangle {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct BoxSelection {
  LineRange lines;                    // first to last line of the samples inside
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // their extent, mm
  std::size_t samples = 0;
  // A region found on the map and widened to the passes joined to it: the lines of the passes it
  // lies on alone, for the user who would rather not re-plan them all.
  std::optional<LineRange> ownPasses;
};

// The samples of the surface's passes (cutting samples only, so that rapids and approach moves
// crossing the rectangle do not widen the range; every one, not a thinned map's vertices) whose
// projection falls inside the rectangle. Samples hidden behind the surface count too: the
// rectangle selects through the part. Nothing when no sample with a line falls inside.
std::optional<BoxSelection> selectInRectangle(const Trajectory& samples, const PassSet& surface,
                                              const ScreenProjection& projection, const ScreenRectangle& rectangle);

}  // namespace isurface::app_model
