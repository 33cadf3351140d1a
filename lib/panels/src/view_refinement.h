#pragma once
// The surface refined where the camera looks. A document's map has about half a vertex for each
// pixel of the view (thinned along the passes); once the camera has rested on a close-up, the
// part of the surface in sight is built again in the background with as many vertices for the
// view alone, and shown instead of the whole surface until the camera looks beyond it.
#include <chrono>
#include <cstddef>
#include <future>
#include <memory>
#include <optional>

#include "isurface/panels/scene_view.h"
#include "isurface/vis/detail_surface.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

// Where the camera stands and the size of the view it draws: a close-up covers one of these.
struct ViewPose {
  SceneView::CameraPose camera;
  int width = 0, height = 0;  // pixels
  bool interacting = false;   // a drag in progress
};

struct ViewRefinement {
  std::shared_ptr<const vis::DetailSurface> shown;   // on `scene` now
  const vis::QualityScene* scene = nullptr;          // the scene `shown` and `building` are for
  std::future<std::optional<vis::DetailSurface>> building;
  std::optional<ViewPose> askedAt;                   // the view the last decision was made for
  std::optional<ViewPose> lastPose;                  // the view at the last frame
  std::chrono::steady_clock::time_point movedAt;     // when the view last changed
  std::size_t vertexBudget = 0;                      // of the view it was last drawn at

  // A close-up is being made, or may be once the camera has rested: the host keeps drawing
  // frames so that it is decided on and shown without waiting for input.
  bool pending() const;
};

}  // namespace isurface::panels
