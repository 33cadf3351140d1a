#pragma once
// The 3D view of the application: VTK renders a quality-map scene into its own framebuffer in
// the host's OpenGL context (a GLFW window, or OSMesa for snapshots), and the frame is shown as
// a texture in an ImGui panel. Mouse input reaches VTK's trackball camera; a click picks.
#include <functional>
#include <memory>
#include <optional>

#include "isurface/core/geometry.h"

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

  void setScene(std::shared_ptr<vis::QualityScene> scene);  // null: nothing to show
  vis::QualityScene* scene() const { return scene_.get(); }
  void setView(vis::ViewDirection view);

  // Renders at the given size (pixels) and returns the colour texture to show (0 if none).
  unsigned int render(int width, int height);

  // Mouse input in pixels from the view's top-left corner.
  void mouseMove(double x, double y);
  void mouseButton(int button, bool pressed, double x, double y);  // 0 left, 1 right, 2 middle
  void mouseWheel(double steps, double x, double y);
  bool interacting() const { return dragging_; }
  // Zooms to a rectangle given in view pixels.
  void zoomToRectangle(double x0, double y0, double x1, double y1);
  // The surface point under a pixel, if any (mm).
  std::optional<Vec3> pick(double x, double y);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::shared_ptr<vis::QualityScene> scene_;
  bool dragging_ = false;
};

}  // namespace isurface::panels
