#include "isurface/panels/scene_view.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

namespace {

// While the camera is dragged the view is drawn at 1/kDragScale of its size (a ninth of the
// pixels: llvmpipe then draws cameo.nc at 15 frames a second on two cores) and shown
// stretched: a software renderer's time goes with the pixels it fills as much as with the
// triangles. Mouse positions are scaled alike, so the camera turns as it would at full size.
constexpr int kDragScale = 3;

}  // namespace

struct SceneView::Impl {
  GlHooks hooks;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor =
      vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
  vtkSmartPointer<vtkInteractorStyleTrackballCamera> style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  vtkRenderer* attached = nullptr;
  int width = 0, height = 0;
  bool initialized = false;
  unsigned int texture = 0;          // the last frame
  std::array<double, 11> camera{};   // the camera as it was for that frame
  bool coarse = false;               // whether that frame showed the coarse surface
};

SceneView::SceneView(GlHooks hooks) : impl_(std::make_unique<Impl>()) {
  impl_->hooks = std::move(hooks);
  vtkGenericOpenGLRenderWindow* window = impl_->window;
  window->SetMultiSamples(0);
  // The frame stays in VTK's framebuffer; ImGui shows its colour texture.
  window->SetFrameBlitModeToNoBlit();
  auto makeCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  makeCurrent->SetClientData(impl_.get());
  makeCurrent->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
    auto* impl = static_cast<Impl*>(client);
    if (!impl->hooks.isCurrent()) impl->hooks.makeCurrent();
  });
  auto isCurrent = vtkSmartPointer<vtkCallbackCommand>::New();
  isCurrent->SetClientData(impl_.get());
  isCurrent->SetCallback([](vtkObject*, unsigned long, void* client, void* answer) {
    *static_cast<bool*>(answer) = static_cast<Impl*>(client)->hooks.isCurrent();
  });
  window->AddObserver(vtkCommand::WindowMakeCurrentEvent, makeCurrent);
  window->AddObserver(vtkCommand::WindowIsCurrentEvent, isCurrent);
  impl_->interactor->SetRenderWindow(window);
  impl_->interactor->EnableRenderOff();  // the host renders once a frame
  impl_->interactor->SetInteractorStyle(impl_->style);
}

SceneView::~SceneView() {
  if (impl_->initialized) {
    impl_->hooks.makeCurrent();
    if (impl_->attached) impl_->window->GetRenderers()->RemoveAllItems();
    impl_->window->Finalize();
  }
}

void SceneView::setScene(std::shared_ptr<vis::QualityScene> scene, std::shared_ptr<const SurfaceRayIndex> picking) {
  vtkGenericOpenGLRenderWindow* window = impl_->window;
  window->GetRenderers()->RemoveAllItems();
  impl_->attached = nullptr;
  cancelDrag();  // a drag does not carry over to another scene
  scene_ = std::move(scene);
  picking_ = scene_ ? std::move(picking) : nullptr;
  invalidated_ = true;
  if (!scene_) return;
  if (impl_->width > 0) scene_->fitOverlaysToWidth(impl_->width);
  scene_->attachTo(window);
  impl_->attached = scene_->renderer();
  impl_->interactor->GetInteractorStyle()->SetDefaultRenderer(scene_->renderer());
}

namespace {

// Where a box (x0 x1 y0 y1 z0 z1, mm) falls on the screen: the rectangle of its corners.
std::optional<app_model::ScreenRectangle> screenBox(const app_model::ScreenProjection& project, const double b[6]) {
  if (b[0] > b[1]) return std::nullopt;
  app_model::ScreenRectangle r{1e300, 1e300, -1e300, -1e300};
  for (int corner = 0; corner < 8; ++corner) {
    const auto at = project(Vec3(b[corner & 1 ? 1 : 0], b[corner & 2 ? 3 : 2], b[corner & 4 ? 5 : 4]));
    if (!at) return std::nullopt;
    r.x0 = std::min(r.x0, at->first), r.x1 = std::max(r.x1, at->first);
    r.y0 = std::min(r.y0, at->second), r.y1 = std::max(r.y1, at->second);
  }
  return r;
}

}  // namespace

double SceneView::millimetresPerPixel() const {
  if (!scene_ || impl_->height <= 0) return 0;
  vtkCamera* camera = scene_->renderer()->GetActiveCamera();
  const double span = camera->GetParallelProjection()
                          ? 2.0 * camera->GetParallelScale()
                          : 2.0 * camera->GetDistance() * std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0);
  return span / impl_->height;
}

std::optional<app_model::ScreenRectangle> SceneView::surfaceOnScreen() const {
  if (!scene_ || impl_->height <= 0) return std::nullopt;
  double bounds[6];
  scene_->surface()->GetBounds(bounds);
  return screenBox(projection(), bounds);
}

std::optional<SceneView::CameraPose> SceneView::camera() const {
  if (!scene_) return std::nullopt;
  vtkCamera* c = scene_->renderer()->GetActiveCamera();
  CameraPose pose;
  c->GetPosition(pose.position.data());
  c->GetFocalPoint(pose.focalPoint.data());
  c->GetViewUp(pose.viewUp.data());
  pose.parallelScale = c->GetParallelProjection() ? c->GetParallelScale() : 0;
  pose.viewAngle = c->GetViewAngle();
  return pose;
}

void SceneView::copyCameraFrom(const SceneView& other) {
  if (!scene_ || !other.scene_) return;
  vtkCamera* camera = scene_->renderer()->GetActiveCamera();
  camera->DeepCopy(other.scene_->renderer()->GetActiveCamera());
  const Impl& a = *other.impl_;
  const Impl& b = *impl_;
  if (a.width <= 0 || a.height <= 0 || b.width <= 0 || b.height <= 0) return;
  // The same width of the workpiece as the other view shows, as far as what the other view
  // frames of the surface still fits top to bottom: a wider, lower view would otherwise show
  // it smaller.
  double zoom = (double(b.width) / b.height) / (double(a.width) / a.height);
  double bounds[6];
  other.scene_->surface()->GetBounds(bounds);
  if (const auto r = screenBox(other.projection(), bounds); r && r->y1 > r->y0)
    zoom = std::min(zoom, 0.9 * a.height / (r->y1 - r->y0));
  if (zoom > 1.0) camera->Zoom(zoom);
}

void SceneView::setView(vis::ViewDirection view) {
  if (scene_) scene_->setView(view);
  invalidated_ = true;
}

unsigned int SceneView::render(int width, int height) {
  if (!scene_ || width < 8 || height < 8) return 0;
  Impl& d = *impl_;
  d.hooks.makeCurrent();
  if (!d.initialized) {
    d.window->InitializeFromCurrentContext();
    d.initialized = true;
  }
  const bool resized = width != d.width || height != d.height;
  if (resized) {
    d.width = width;
    d.height = height;
  }
  applyDrawnSize();
  // Fitting works in the view's own pixels: it waits for the drag to end.
  if (refitPending_ && !dragging_) {
    refitPending_ = false;
    fitToSurface();
  }
  // What the camera shows (not its modification time, which clipping-range updates bump too).
  vtkCamera* camera = scene_->renderer()->GetActiveCamera();
  std::array<double, 11> view{};
  camera->GetPosition(&view[0]);
  camera->GetFocalPoint(&view[3]);
  camera->GetViewUp(&view[6]);
  view[9] = camera->GetParallelScale();
  view[10] = camera->GetViewAngle();
  // A frame of a million triangles costs llvmpipe over 100 ms: draw one only when it changed.
  if (!resized && !invalidated_ && !dragging_ && d.coarse == dragging_ && view == d.camera && d.texture)
    return d.texture;
  scene_->useCoarseSurface(dragging_);
  scene_->followCamera();
  // ImGui changes GL state behind VTK's back: let VTK start from what is really bound.
  d.window->GetState()->Reset();
  d.window->GetState()->Push();
  d.window->Render();
  d.window->GetState()->Pop();
  d.camera = view;
  d.coarse = dragging_;
  invalidated_ = false;
  vtkOpenGLFramebufferObject* frame = d.window->GetDisplayFramebuffer();
  vtkTextureObject* texture = frame ? frame->GetColorAttachmentAsTextureObject(0) : nullptr;
  d.texture = texture ? texture->GetHandle() : 0;
  return d.texture;
}

void SceneView::fitToSurface() {
  vtkRenderer* renderer = scene_->renderer();
  renderer->ResetCamera();  // the bounding sphere in view: room to spare around a flat surface
  double bounds[6];
  scene_->surface()->GetBounds(bounds);
  // Then the surface's box on the screen brought into the part of the view that the caption
  // (top) and the legend (right) leave free: the rectangle zoomed to the whole view is the
  // one that maps the box onto that part.
  const auto r = screenBox(projection(), bounds);
  if (!r || r->x1 - r->x0 < 1 || r->y1 - r->y0 < 1) return;
  const double w = impl_->width, h = impl_->height;
  const double freeX0 = 0.03 * w, freeX1 = 0.84 * w, freeY0 = 0.17 * h, freeY1 = 0.97 * h;
  const double scale = std::min((freeX1 - freeX0) / (r->x1 - r->x0), (freeY1 - freeY0) / (r->y1 - r->y0));
  const double cx = 0.5 * (r->x0 + r->x1) - (0.5 * (freeX0 + freeX1) - 0.5 * w) / scale;
  const double cy = 0.5 * (r->y0 + r->y1) - (0.5 * (freeY0 + freeY1) - 0.5 * h) / scale;
  zoomToRectangle(cx - 0.5 * w / scale, cy - 0.5 * h / scale, cx + 0.5 * w / scale, cy + 0.5 * h / scale);
}

std::vector<unsigned char> SceneView::snapshot(int width, int height) {
  invalidated_ = true;
  // Drawn at the size asked for, the full surface, even in the middle of a drag.
  const bool wasDragging = dragging_;
  dragging_ = false;
  // A close-up covers what the view shows; a picture of another shape shows more.
  const Impl& view = *impl_;
  const bool sameShape = view.height > 0 && height > 0 &&
                         std::abs(double(width) / height - double(view.width) / view.height) < 0.01;
  if (scene_) scene_->allowDetailSurface(sameShape);
  const unsigned int drawn = render(width, height);
  if (scene_) scene_->allowDetailSurface(true);
  dragging_ = wasDragging;
  if (!drawn) return {};
  Impl& d = *impl_;
  vtkOpenGLFramebufferObject* frame = d.window->GetDisplayFramebuffer();
  if (!frame) return {};
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  d.window->GetState()->Reset();
  d.window->GetState()->Push();
  frame->Bind(GL_READ_FRAMEBUFFER);
  frame->ActivateReadBuffer(0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  frame->UnBind(GL_READ_FRAMEBUFFER);
  d.window->GetState()->Pop();
  invalidated_ = true;  // the next frame is drawn at the panel's own size again
  applyDrawnSize();
  return rgb;
}

std::optional<std::pair<double, double>> SceneView::project(const Vec3& point) const {
  if (!scene_ || impl_->height <= 0) return std::nullopt;
  return projection()(point);
}

app_model::ScreenProjection SceneView::projection() const {
  app_model::ScreenProjection p;
  if (!scene_ || impl_->height <= 0) return p;
  // What vtkRenderer::WorldToDisplay does per point, once: the renderer fills the whole view.
  vtkRenderer* renderer = scene_->renderer();
  vtkMatrix4x4* m = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), 0, 1);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) p.worldToDevice(r, c) = m->GetElement(r, c);
  p.width = impl_->width;
  p.height = impl_->height;
  return p;
}

int SceneView::drawnWidth() const { return std::max(1, impl_->width / (dragging_ ? kDragScale : 1)); }
int SceneView::drawnHeight() const { return std::max(1, impl_->height / (dragging_ ? kDragScale : 1)); }

void SceneView::applyDrawnSize() {
  Impl& d = *impl_;
  if (d.width <= 0 || d.height <= 0) return;
  d.interactor->SetSize(drawnWidth(), drawnHeight());
  const int* size = d.window->GetSize();
  if (size[0] == drawnWidth() && size[1] == drawnHeight()) return;
  d.window->SetSize(drawnWidth(), drawnHeight());
  if (scene_) scene_->fitOverlaysToWidth(d.width, double(drawnWidth()) / d.width);
}

void SceneView::cancelDrag() {
  if (pressed_) impl_->style->StopState();
  pressed_ = dragging_ = false;
  applyDrawnSize();
}

void SceneView::setEventPosition(double x, double y) {
  const double scale = dragging_ ? 1.0 / kDragScale : 1.0;
  impl_->interactor->SetEventInformationFlipY(static_cast<int>(std::lround(x * scale)),
                                              static_cast<int>(std::lround(y * scale)));
}

void SceneView::mouseMove(double x, double y) {
  // A drag (not a click) shows the coarse surface, drawn smaller, until the button is let go.
  if (pressed_ && !dragging_ && (std::abs(x - pressX_) > 2 || std::abs(y - pressY_) > 2)) {
    dragging_ = true;
    applyDrawnSize();
    setEventPosition(pressX_, pressY_);  // the drag's first step is measured from the press
  }
  setEventPosition(x, y);
  impl_->interactor->MouseMoveEvent();
}

void SceneView::mouseButton(int button, bool pressed, double x, double y) {
  vtkGenericRenderWindowInteractor* i = impl_->interactor;
  setEventPosition(x, y);
  pressed_ = pressed;
  pressX_ = x;
  pressY_ = y;
  switch (button) {
    case 0: pressed ? i->LeftButtonPressEvent() : i->LeftButtonReleaseEvent(); break;
    case 1: pressed ? i->RightButtonPressEvent() : i->RightButtonReleaseEvent(); break;
    default: pressed ? i->MiddleButtonPressEvent() : i->MiddleButtonReleaseEvent(); break;
  }
  if (!pressed && dragging_) {
    dragging_ = false;
    applyDrawnSize();  // a pick right after works in the view's own pixels
  }
}

void SceneView::mouseWheel(double steps, double x, double y) {
  vtkGenericRenderWindowInteractor* i = impl_->interactor;
  setEventPosition(x, y);
  if (steps > 0) i->MouseWheelForwardEvent();
  else if (steps < 0) i->MouseWheelBackwardEvent();
}

void SceneView::zoomToRectangle(double x0, double y0, double x1, double y1) {
  invalidated_ = true;
  if (!scene_ || impl_->width <= 0) return;
  vtkRenderer* renderer = scene_->renderer();
  vtkCamera* camera = renderer->GetActiveCamera();
  const double w = std::abs(x1 - x0), h = std::abs(y1 - y0);
  if (w < 4 || h < 4) return;
  // Move the focal point to the rectangle's centre, then scale the view to fit it.
  const double cx = 0.5 * (x0 + x1), cy = impl_->height - 0.5 * (y0 + y1);
  renderer->SetDisplayPoint(cx, cy, 0.5);
  renderer->DisplayToWorld();
  double world[4];
  renderer->GetWorldPoint(world);
  if (world[3] != 0)
    for (int k = 0; k < 3; ++k) world[k] /= world[3];
  double focal[3], position[3];
  camera->GetFocalPoint(focal);
  camera->GetPosition(position);
  const double shift[3] = {world[0] - focal[0], world[1] - focal[1], world[2] - focal[2]};
  camera->SetFocalPoint(world[0], world[1], world[2]);
  camera->SetPosition(position[0] + shift[0], position[1] + shift[1], position[2] + shift[2]);
  camera->Zoom(std::min(impl_->width / w, impl_->height / h));
}

std::optional<SurfaceHit> SceneView::pick(double x, double y) const {
  if (!scene_ || !picking_ || impl_->height <= 0 || impl_->width <= 0) return std::nullopt;
  // The pixel's ray: from the near clipping plane through the far one.
  vtkRenderer* renderer = scene_->renderer();
  Vec3 ends[2];
  for (int k = 0; k < 2; ++k) {
    renderer->SetDisplayPoint(x, impl_->height - y, k);
    renderer->DisplayToWorld();
    double w[4];
    renderer->GetWorldPoint(w);
    if (w[3] == 0) return std::nullopt;
    ends[k] = Vec3(w[0], w[1], w[2]) / w[3];
  }
  return picking_->firstHit(ends[0], ends[1]);
}

}  // namespace isurface::panels
