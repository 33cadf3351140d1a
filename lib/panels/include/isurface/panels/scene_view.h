#pragma once
// The 3D view of the application: VTK renders a quality-map scene into its own framebuffer in
// the host's OpenGL context (a GLFW window, or OSMesa for snapshots), and the frame is shown as
// a texture in an ImGui panel. Mouse input reaches VTK's trackball camera; a click picks.
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/app_model/box_selection.h"
#include "isurface/surface/surface_ray_index.h"

namespace isurface::vis {
class QualityScene;
enum class ViewDirection;
}

namespace isurface::panels {

struct GlHooks {
  std::function<void()> makeCurrent;  // make the host's context current
  std::function<bool()> isCurrent;    // whether it is
};

class SceneView {
 public:
  explicit SceneView(GlHooks hooks);
  ~SceneView();

  // null: nothing to show. `picking` indexes the scene's surface for pick() (none: no picks).
  void setScene(std::shared_ptr<vis::QualityScene> scene, std::shared_ptr<const SurfaceRayIndex> picking = nullptr);
  vis::QualityScene* scene() const { return scene_.get(); }
  void setView(vis::ViewDirection view);
  // Looks at its scene the way another view looks at its own.
  void copyCameraFrom(const SceneView& other);

  // Returns the colour texture to show (0 if none) at the given size (pixels), rendering again
  // only when something changed: the size, the scene, the camera, a drag, or invalidate().
  unsigned int render(int width, int height);
  void invalidate() { invalidated_ = true; }
  // Fits the camera to the scene again at the next frame, at the size the view has then,
  // looking from where it looks now (the view was made narrower or wider).
  void refit() { refitPending_ = invalidated_ = true; }
  // The view drawn at another size, as the camera stands: RGB rows, the bottom row first
  // (empty when there is nothing to draw).
  std::vector<unsigned char> snapshot(int width, int height);
  // Where a point (mm) appears in the view, in pixels from its top-left corner.
  std::optional<std::pair<double, double>> project(const Vec3& point) const;
  // The same mapping for many points at once, as the camera stands now (an empty view: 0 x 0).
  app_model::ScreenProjection projection() const;
  // Millimetres a pixel spans at the camera's focal point (0 with nothing shown).
  double millimetresPerPixel() const;
  // Where the surface's bounding box stands in the view (pixels from its top-left corner).
  std::optional<app_model::ScreenRectangle> surfaceOnScreen() const;
  // Where the camera stands and what it looks at (mm), and which way is up on the screen.
  // How much it takes in: half the view's height (mm) in a parallel projection (0 in a
  // perspective one), and the perspective's angle (degrees).
  struct CameraPose {
    Vec3 position, focalPoint, viewUp;
    double parallelScale = 0, viewAngle = 0;
  };
  std::optional<CameraPose> camera() const;

  // Mouse input in pixels from the view's top-left corner.
  void mouseMove(double x, double y);
  void mouseButton(int button, bool pressed, double x, double y);  // 0 left, 1 right, 2 middle
  void mouseWheel(double steps, double x, double y);
  bool interacting() const { return dragging_; }
  // Ends a press or a drag whose release will not come (the view stopped being drawn).
  void cancelDrag();
  // Zooms to a rectangle given in view pixels.
  void zoomToRectangle(double x0, double y0, double x1, double y1);
  // The surface under a pixel, if any: the point (mm) and the triangle of the picking index.
  std::optional<SurfaceHit> pick(double x, double y) const;

 private:
  void fitToSurface();

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::shared_ptr<vis::QualityScene> scene_;
  std::shared_ptr<const SurfaceRayIndex> picking_;
  // The size the view is drawn at (smaller while dragging) and mouse positions in it, pixels.
  int drawnWidth() const;
  int drawnHeight() const;
  void setEventPosition(double x, double y);
  void applyDrawnSize();  // the interactor's, the window's and the text's, for drawnWidth()
  bool pressed_ = false, dragging_ = false;
  double pressX_ = 0, pressY_ = 0;
  bool invalidated_ = true;
  bool refitPending_ = false;
};

}  // namespace isurface::panels
