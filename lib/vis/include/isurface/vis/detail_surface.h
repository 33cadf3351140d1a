#pragma once
// The surface where the camera looks, built again closer to the samples' own resolution. A map
// is thinned to what a whole view can show; a close-up of part of it needs the samples between
// its vertices, and only that part's.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "isurface/base/trajectory.h"
#include "isurface/surface/passes.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/map/quality_map.h"

namespace isurface::vis {

struct DetailSurface {
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // the box it was asked for, mm (x and y bound it)
  std::size_t stride = 1;                           // every stride-th sample of a pass
  std::shared_ptr<const SurfaceMesh> mesh;
  std::vector<Vec3> positions;  // mm, one per vertex
  std::vector<float> scalars;   // the map's values, in the units it shows
};

// Each pass cut to the stretch from its first sample inside the box to its last (x and y, mm;
// commanded or feedback positions). A raster pass crosses a box once; a loop may leave it and
// come back, and then keeps what lies between so that it stays one pass beside its neighbours.
// Passes with no sample inside are left out.
PassSet passesInBox(const Trajectory& samples, const PassSet& passes, const Vec3& lower, const Vec3& upper,
                    bool feedback = false);

// The map's surface inside the box with no more than request.maxVertices vertices (thinned along
// the passes as the map is), coloured as the map of `request` is. Nothing when no triangle lies
// there.
std::optional<DetailSurface> buildDetailSurface(const Trajectory& samples, const PassSet& passes,
                                                const QualityMapRequest& request, const Vec3& lower, const Vec3& upper);

}  // namespace isurface::vis
