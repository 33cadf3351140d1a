#include "view_refinement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "inspector_state.h"
#include "isurface/base/available_memory.h"
#include "isurface/io/biip.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/workflow/record_stretches.h"
#include "isurface/vis/quality_scene.h"

namespace isurface::panels {

namespace {

// How long the camera rests before a close-up is built (a wheel turned notch by notch would
// otherwise start one build a notch).
constexpr std::chrono::milliseconds kRest(250);
// A close-up is built when it is at least this much finer along the passes than what is shown.
constexpr std::size_t kFinerAtLeast = 2;

struct Footprint {
  Vec3 lower, upper;          // mm: what the view shows of the surface, x and y bound it
  std::size_t vertices = 0;   // the map's vertices in sight (0: the view falls between them)
};

bool samePose(const std::optional<ViewPose>& a, const std::optional<ViewPose>& b) {
  if (!a || !b) return false;
  const SceneView::CameraPose &p = a->camera, &q = b->camera;
  return p.position == q.position && p.focalPoint == q.focalPoint && p.viewUp == q.viewUp &&
         p.parallelScale == q.parallelScale && p.viewAngle == q.viewAngle && a->width == b->width &&
         a->height == b->height && a->interacting == b->interacting;
}

// The map's vertices that project inside the view, widened by the longest step from one of them
// to its neighbour along its pass or on the next one: the triangles of the vertices just outside
// the view reach that far into it. With no vertex inside (a view between them), the view's
// rectangle about the focal point. Nothing when the view shows no surface at all.
std::optional<Footprint> footprint(const vis::QualityMap& map, const SceneView& view) {
  const app_model::ScreenProjection projection = view.projection();
  const Eigen::Matrix4d& m = projection.worldToDevice;
  const std::vector<Vec3>& at = map.data.positions;
  const SurfaceMesh& mesh = *map.mesh;
  constexpr double kFar = std::numeric_limits<double>::max();
  Footprint f{Vec3(kFar, kFar, kFar), Vec3(-kFar, -kFar, -kFar), 0};
  double step = 0;
  for (std::size_t v = 0; v < at.size(); ++v) {
    const Vec3& p = at[v];
    const double w = m(3, 0) * p.x() + m(3, 1) * p.y() + m(3, 2) * p.z() + m(3, 3);
    if (!(w > 0)) continue;
    const double x = (m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2) * p.z() + m(0, 3)) / w;
    const double y = (m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2) * p.z() + m(1, 3)) / w;
    if (!(x >= -1 && x <= 1 && y >= -1 && y <= 1)) continue;
    f.lower = f.lower.cwiseMin(p);
    f.upper = f.upper.cwiseMax(p);
    ++f.vertices;
    if (v + 1 < at.size() && mesh.vertexPass[v + 1] == mesh.vertexPass[v]) step = std::max(step, (at[v + 1] - p).norm());
    for (const std::uint32_t n : {mesh.previousPassNeighbour[v], mesh.nextPassNeighbour[v]})
      if (n != kNoVertex) step = std::max(step, (at[n] - p).norm());
  }
  if (f.vertices == 0) {
    const auto pose = view.camera();
    const double reach = 0.5 * std::hypot(projection.width, projection.height) * view.millimetresPerPixel();
    if (!pose || !(reach > 0)) return std::nullopt;
    f.lower = pose->focalPoint - Vec3(reach, reach, reach);
    f.upper = pose->focalPoint + Vec3(reach, reach, reach);
    return f;
  }
  const Vec3 margin = Vec3::Constant(std::isfinite(step) ? step : 0.0);
  f.lower -= margin;
  f.upper += margin;
  return f;
}

bool covers(const vis::DetailSurface& detail, const std::optional<Footprint>& f) {
  return f && f->lower.x() >= detail.lower.x() && f->lower.y() >= detail.lower.y() && f->upper.x() <= detail.upper.x() &&
         f->upper.y() <= detail.upper.y();
}

void dropDetail(Inspector::State& s) {
  ViewRefinement& r = s.refinement;
  if (r.shown && s.view.scene()) {
    s.view.scene()->setDetailSurface(nullptr);
    s.view.invalidate();
  }
  r.shown.reset();
}

// A finished build goes on the scene when the view still stands where it was asked for.
void takeFinishedBuild(Inspector::State& s) {
  ViewRefinement& r = s.refinement;
  if (!r.building.valid() || r.building.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  std::optional<vis::DetailSurface> detail;
  try {
    detail = r.building.get();
  } catch (const std::exception& e) {
    s.status = std::string("the surface in sight was not refined: ") + e.what();
    return;
  }
  vis::QualityScene* scene = s.view.scene();
  if (!detail || !scene || scene != r.scene || !samePose(r.lastPose, r.askedAt)) return;
  r.shown = std::make_shared<const vis::DetailSurface>(std::move(*detail));
  scene->setDetailSurface(r.shown.get());
  s.view.invalidate();
}

// A thinned document's close-up is made from its dump's records in sight, as many as half the
// free memory holds (every j-th, j below the document's own thinning k), so that its speeds,
// accelerations and jerks are the machine's own rather than the thinned samples' means. Its
// vertices then name the document's samples nearest them, which the selection and the G-code
// pane know. Nothing when no finer close-up fits.
std::optional<vis::DetailSurface> detailFromDump(const BiipReader& reader, const Trajectory& thinned,
                                                 const PassSet& passes, const vis::QualityMapRequest& request,
                                                 const Footprint& f) {
  const std::size_t k = thinned.thinning;
  const PassSet inBox = vis::passesInBox(thinned, passes, f.lower, f.upper, request.feedbackSurface);
  std::vector<RecordStretch> stretches;
  std::uint64_t records = 0;
  for (const Pass& pass : inBox.passes) {
    stretches.push_back({pass.begin * k, (pass.end - 1 - pass.begin) * k + 1});
    records += stretches.back().count;
  }
  if (stretches.empty()) return std::nullopt;
  TrajectoryChannels channels;
  channels.block = false;
  channels.feedback = vis::needsFeedback(request);
  channels.extra = !request.channel.empty() || quantityInfo(request.quantity).needsJoints;
  const std::optional<std::uint64_t> free = availableMemory();
  channels.thinning = free ? thinningToFit(records, bytesPerSample(reader, channels), *free / 2) : 1;
  if (channels.thinning >= k) return std::nullopt;
  PassSet fine;
  fine.pattern = passes.pattern;
  const Trajectory samples = loadRecordStretches(reader, stretches, channels, fine);
  std::optional<vis::DetailSurface> detail = vis::buildDetailSurface(samples, fine, request, f.lower, f.upper);
  if (!detail) return std::nullopt;
  // The stride the view compares with is in the dump's records, as decide() counts them.
  detail->stride *= channels.thinning;
  auto mesh = std::make_shared<SurfaceMesh>(*detail->mesh);
  std::vector<std::size_t> recordOf(samples.size());
  for (std::size_t p = 0; p < stretches.size() && p < fine.passes.size(); ++p)
    // Pass p of `fine` starts at stretch p's first record; its samples are j records apart.
    for (std::size_t i = fine.passes[p].begin; i < fine.passes[p].end; ++i)
      recordOf[i] = stretches[p].first + (i - fine.passes[p].begin) * channels.thinning;
  for (std::uint32_t& v : mesh->vertexSample)
    v = static_cast<std::uint32_t>(std::min(thinned.size() - 1, (recordOf[v] + k / 2) / k));
  detail->mesh = std::move(mesh);
  return detail;
}

// Whether a document's close-ups come from its dump's records rather than its samples.
bool refinedFromDump(const Document& doc) { return doc.samples->thinning > 1 && doc.thinnedDump; }

void startBuild(Inspector::State& s, const Document& doc, const Footprint& f) {
  vis::QualityMapRequest request = doc.map.request;
  request.maxVertices = s.refinement.vertexBudget;
  request.pickable = false;
  request.coarseVertices = 0;
  std::shared_ptr<const BiipReader> dump = refinedFromDump(doc) ? doc.thinnedDump : nullptr;
  s.refinement.building = std::async(std::launch::async, [samples = doc.samples, passes = doc.map.passes, request, f, dump] {
    if (dump) return detailFromDump(*dump, *samples, passes, request, f);
    return vis::buildDetailSurface(*samples, passes, request, f.lower, f.upper);
  });
}

// Once the view has rested: the close-up goes when it does not cover the view, and a finer one
// is built when the view shows few enough samples for it.
void decide(Inspector::State& s, const Document& doc) {
  ViewRefinement& r = s.refinement;
  r.askedAt = r.lastPose;
  const std::optional<Footprint> inSight = footprint(doc.map, s.view);
  if (r.shown && !covers(*r.shown, inSight)) dropDetail(s);
  if (!inSight) return;
  // In the dump's records when the close-up comes from them (its stride is counted so too).
  const std::size_t unit = refinedFromDump(doc) ? doc.samples->thinning : 1;
  const std::size_t mapStride = strideWithin(doc.map.passes, doc.map.request.maxVertices) * unit;
  const std::size_t stride = r.shown ? r.shown->stride : mapStride;
  if (inSight->vertices > 0) {
    const std::size_t samplesInSight = inSight->vertices * mapStride;
    const std::size_t budget = std::max<std::size_t>(r.vertexBudget, 1);
    if ((samplesInSight + budget - 1) / budget * kFinerAtLeast > stride) return;  // about as fine already
  } else if (stride == 1) {
    return;
  }
  startBuild(s, doc, *inSight);
}

}  // namespace

bool ViewRefinement::pending() const { return building.valid() || (lastPose && !samePose(lastPose, askedAt)); }

void refineWhereTheCameraLooks(Inspector::State& s, int viewWidth, int viewHeight) {
  ViewRefinement& r = s.refinement;
  vis::QualityScene* scene = s.view.scene();
  if (r.scene != scene) {  // another document, or a new colouring: a close-up is of the old one
    if (scene && scene->showsDetail()) scene->setDetailSurface(nullptr);
    r.shown.reset();
    r.askedAt.reset();
    r.scene = scene;
  }
  r.vertexBudget = vis::vertexBudgetForPixels(std::size_t(std::max(viewWidth, 0)) * std::size_t(std::max(viewHeight, 0)));
  takeFinishedBuild(s);
  Document* doc = s.activeDocument();
  const auto camera = s.view.camera();
  if (!scene || !doc || !doc->samples || !doc->map.mesh || doc->scene.get() != scene || !camera || viewWidth <= 0 ||
      viewHeight <= 0) {
    r.lastPose.reset();  // nothing to refine: no frames are needed for it
    return;
  }
  const ViewPose pose{*camera, viewWidth, viewHeight, s.view.interacting()};
  if (!samePose(pose, r.lastPose)) {
    r.lastPose = pose;
    r.movedAt = std::chrono::steady_clock::now();
    // Not shown over a view it does not cover, not even until the camera rests.
    if (!pose.interacting && r.shown && !covers(*r.shown, footprint(doc->map, s.view))) dropDetail(s);
    return;
  }
  // Not beside a load or a colouring that replaces the map.
  if (pose.interacting || samePose(pose, r.askedAt) || std::chrono::steady_clock::now() - r.movedAt < kRest ||
      r.building.valid() || s.job.running())
    return;
  decide(s, *doc);
}

}  // namespace isurface::panels
