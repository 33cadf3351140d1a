#include "view_refinement.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "inspector_state.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

namespace {

// How long the camera rests before a close-up is built (a wheel turned notch by notch would
// otherwise start one build a notch).
constexpr std::chrono::milliseconds kRest(250);
// A close-up is built when it is at least this much finer than the map along the passes.
constexpr std::size_t kFinerAtLeast = 2;

struct Footprint {
  Vec3 lower, upper;            // mm, of the map's vertices in sight (widened by a margin)
  std::size_t vertices = 0;     // the map's vertices in sight
};

// The part of the map's surface the view shows: its vertices that project inside the view.
std::optional<Footprint> footprint(const std::vector<Vec3>& positions, const app_model::ScreenProjection& view) {
  if (view.width <= 0 || view.height <= 0) return std::nullopt;
  Footprint f;
  constexpr double kFar = std::numeric_limits<double>::max();
  f.lower = Vec3(kFar, kFar, kFar);
  f.upper = -f.lower;
  const Eigen::Matrix4d& m = view.worldToDevice;
  for (const Vec3& p : positions) {
    const double w = m(3, 0) * p.x() + m(3, 1) * p.y() + m(3, 2) * p.z() + m(3, 3);
    if (!(w > 0)) continue;
    const double x = (m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2) * p.z() + m(0, 3)) / w;
    const double y = (m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2) * p.z() + m(1, 3)) / w;
    if (x < -1 || x > 1 || y < -1 || y > 1) continue;
    f.lower = f.lower.cwiseMin(p);
    f.upper = f.upper.cwiseMax(p);
    ++f.vertices;
  }
  if (f.vertices == 0) return std::nullopt;
  // Triangles reach a vertex spacing beyond their last vertex in sight: a twentieth of the box
  // on each side covers that on a close-up of a few hundred vertices across.
  const Vec3 margin = (f.upper - f.lower) * 0.05;
  f.lower -= margin;
  f.upper += margin;
  return f;
}

bool covers(const vis::DetailSurface& detail, const Footprint& f) {
  return f.lower.x() >= detail.lower.x() && f.lower.y() >= detail.lower.y() && f.upper.x() <= detail.upper.x() &&
         f.upper.y() <= detail.upper.y();
}

bool samePose(const std::optional<SceneView::CameraPose>& a, const std::optional<SceneView::CameraPose>& b) {
  return a && b && a->position == b->position && a->focalPoint == b->focalPoint && a->viewUp == b->viewUp &&
         a->parallelScale == b->parallelScale && a->viewAngle == b->viewAngle;
}

// Every how many samples of a pass the map keeps a vertex.
std::size_t mapStride(const vis::QualityMap& map) {
  std::size_t cutting = 0;
  for (const Pass& pass : map.passes.passes) cutting += pass.size();
  const std::size_t vertices = map.mesh ? map.mesh->vertexSample.size() : 0;
  return vertices == 0 ? 1 : std::max<std::size_t>(1, cutting / vertices);
}

void dropDetail(Inspector::State& s) {
  ViewRefinement& r = s.refinement;
  if (r.shown && s.view.scene() && r.scene == s.view.scene()) {
    s.view.scene()->setDetailSurface(nullptr);
    s.view.invalidate();
  }
  r.shown.reset();
}

// A finished build goes on the scene when the camera still stands where it was asked for.
void takeFinishedBuild(Inspector::State& s) {
  ViewRefinement& r = s.refinement;
  if (!r.building.valid() || r.building.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  std::optional<vis::DetailSurface> detail = r.building.get();
  vis::QualityScene* scene = s.view.scene();
  if (!detail || !scene || scene != r.scene || !samePose(s.view.camera(), r.askedAt)) return;
  r.shown = std::make_shared<const vis::DetailSurface>(std::move(*detail));
  scene->setDetailSurface(r.shown.get());
  s.view.invalidate();
}

void startBuild(Inspector::State& s, const Document& doc, const Footprint& f) {
  ViewRefinement& r = s.refinement;
  vis::QualityMapRequest request = doc.map.request;
  request.maxVertices = r.vertexBudget;
  request.pickable = false;
  request.coarseVertices = 0;
  r.askedAt = s.view.camera();
  r.building = std::async(std::launch::async, [samples = doc.samples, passes = doc.map.passes, request, f] {
    return vis::buildDetailSurface(*samples, passes, request, f.lower, f.upper);
  });
}

}  // namespace

void refineWhereTheCameraLooks(Inspector::State& s, int viewWidth, int viewHeight) {
  ViewRefinement& r = s.refinement;
  vis::QualityScene* scene = s.view.scene();
  if (r.scene != scene) {  // another document, or a new colouring: the close-up was of the old one
    r.shown.reset();
    r.askedAt.reset();
    r.askedAtLastPose = false;
    r.scene = scene;
  }
  r.vertexBudget = vis::vertexBudgetForPixels(std::size_t(std::max(viewWidth, 0)) * std::size_t(std::max(viewHeight, 0)));
  takeFinishedBuild(s);
  Document* doc = s.activeDocument();
  if (!scene || !doc || !doc->samples || !doc->map.mesh || doc->scene.get() != scene) {
    r.lastPose.reset();  // nothing to refine: no frames needed for it
    return;
  }
  const std::optional<SceneView::CameraPose> pose = s.view.camera();
  if (s.view.interacting() || !samePose(pose, r.lastPose)) {
    r.lastPose = pose;
    r.movedAt = std::chrono::steady_clock::now();
    r.askedAtLastPose = samePose(pose, r.askedAt);
    if (!s.view.interacting() && r.shown) {
      const auto inSight = footprint(doc->map.data.positions, s.view.projection());
      if (!inSight || !covers(*r.shown, *inSight)) dropDetail(s);
    }
    return;
  }
  // Once per resting place, and not beside a load or a colouring that replaces the map.
  if (std::chrono::steady_clock::now() - r.movedAt < kRest || samePose(pose, r.askedAt) || r.building.valid() ||
      s.job.running())
    return;
  const auto inSight = footprint(doc->map.data.positions, s.view.projection());
  r.askedAt = pose;
  r.askedAtLastPose = true;
  if (!inSight || (r.shown && covers(*r.shown, *inSight))) return;
  const std::size_t stride = mapStride(doc->map);
  const std::size_t samplesInSight = inSight->vertices * stride;
  const std::size_t closeUpStride = (samplesInSight + r.vertexBudget - 1) / std::max<std::size_t>(r.vertexBudget, 1);
  if (closeUpStride * kFinerAtLeast > stride) return;  // the map is about as fine here already
  startBuild(s, *doc, *inSight);
}

}  // namespace isurface::panels
