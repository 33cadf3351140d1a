#pragma once
// A coarse surface of about a given number of vertices, for drawing while the camera moves: a
// software renderer spends its time per triangle, so the coarse surface is thinned both along
// the passes and across them (every k-th pass), keeping its vertices about as far apart one way
// as the other.
#include <cstddef>

#include "isurface/surface/passes.h"
#include "isurface/surface/surface_mesh.h"

namespace isurface {

// `options` as for the full surface (its stride is replaced; its gap limit grows with the passes
// left out, so that the passes kept are still joined).
SurfaceMesh buildCoarseSurfaceMesh(const Trajectory& samples, const PassSet& passes, MeshOptions options,
                                   std::size_t vertexBudget);

}  // namespace isurface
