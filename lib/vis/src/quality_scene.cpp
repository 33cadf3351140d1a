#include "isurface/vis/quality_scene.h"

#include <vtkAutoInit.h>

#include <vtkActor.h>
#include <vtkAssembly.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkShaderProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTypeInt32Array.h>
#include <vtkUniforms.h>

#include <algorithm>
#include <cmath>

#include "isurface/base/units.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/vis/color_map.h"
#include "isurface/vis/detail_surface.h"
#include "scene_actors.h"
#include "tool_actor.h"

// VTK's rendering classes come from object factories that these register; without them every
// renderer, mapper and shader property would be an empty base class and every picture black.
// Registering here, where scenes are made, serves every executable that shows one.
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);
VTK_MODULE_INIT(vtkInteractionStyle);

namespace isurface::vis {

vtkSmartPointer<vtkPolyData> surfacePolyData(const std::vector<Vec3>& positions, const SurfaceMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), positions[i].x(), positions[i].y(), positions[i].z());
  // Fill the cell array's offsets and connectivity directly: no per-triangle insertion calls,
  // and 32-bit ids (half the memory of vtkIdType; a mesh has under 2^31 vertices).
  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  const vtkIdType triangles = static_cast<vtkIdType>(mesh.triangles.size());
  offsets->SetNumberOfValues(triangles + 1);
  connectivity->SetNumberOfValues(3 * triangles);
  for (vtkIdType t = 0; t < triangles; ++t) {
    offsets->SetValue(t, static_cast<std::int32_t>(3 * t));
    for (int k = 0; k < 3; ++k) connectivity->SetValue(3 * t + k, static_cast<std::int32_t>(mesh.triangles[t][k]));
  }
  offsets->SetValue(triangles, static_cast<std::int32_t>(3 * triangles));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  // The pass index of every vertex, for the pass-wire shader.
  std::vector<float> passCoord(mesh.vertexPass.begin(), mesh.vertexPass.end());
  addPointArray(poly, "pass_coord", passCoord);
  return poly;
}

void addPointArray(vtkPolyData* polyData, const std::string& name, const std::vector<float>& values) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) array->SetValue(static_cast<vtkIdType>(i), values[i]);
  polyData->GetPointData()->AddArray(array);
}

constexpr float kLineGlowSize = 14, kSampleGlowSize = 26;  // pixels

struct QualityScene::Parts {
  vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkRenderer> axesCorner = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkPolyData> surface, coarseSurface;
  vtkSmartPointer<vtkLookupTable> table;
  vtkSmartPointer<vtkActor> surfaceActor, coarseActor, detailActor, toolpathActor, toolAxesActor, lineGlow, sampleGlow,
      pointsActor;
  vtkSmartPointer<vtkAssembly> tool;  // made when first shown
  std::optional<Vec3> toolTip;
  MapStyle style;
  vtkSmartPointer<vtkPolyData> lineGlowPoints = vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkPolyData> sampleGlowPoints = vtkSmartPointer<vtkPolyData>::New();
  bool coarse = false, showSurface = true, detailAllowed = true, showToolpath = true;
  double passSpacing = 0;  // mm, median distance between neighbouring passes
  double toolpathOpacity = 1;  // the toolpath's own, where its passes lie far enough apart
  vtkSmartPointer<vtkScalarBarActor> legend;
  vtkSmartPointer<vtkTextActor> caption;
  std::string captionText, legendText;
  int fontSize = 16;  // the style's: the largest the text is drawn
};

QualityScene::QualityScene(const SurfaceData& data, const MapStyle& style) : parts_(new Parts) {
  Parts& p = *parts_;
  p.renderer->SetBackground(1.0, 1.0, 1.0);
  p.renderer->SetBackground2(0.86, 0.89, 0.93);
  p.renderer->GradientBackgroundOn();
  p.renderer->SetBackgroundAlpha(1.0);
  p.renderer->SetUseFXAA(false);

  p.style = style;
  p.table = makeLookupTable(style.colorMap, style.range.lo, style.range.hi);
  p.surface = surfacePolyData(data.positions, *data.mesh);
  addPointArray(p.surface, "value", data.scalars);
  p.surface->GetPointData()->SetActiveScalars("value");
  p.surfaceActor = makeSurfaceActor(p.surface, p.table, style, style.passWires);
  p.renderer->AddActor(p.surfaceActor);

  if (data.coarseMesh) {
    p.coarseSurface = surfacePolyData(data.coarsePositions, *data.coarseMesh);
    addPointArray(p.coarseSurface, "value", data.coarseScalars);
    p.coarseSurface->GetPointData()->SetActiveScalars("value");
    p.coarseActor = makeSurfaceActor(p.coarseSurface, p.table, style, false);
    p.coarseActor->VisibilityOff();
    p.renderer->AddActor(p.coarseActor);
  }

  // The surface's vertices as small points, hidden unless asked for.
  auto pointsMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  pointsMapper->SetInputData(p.surface);
  pointsMapper->SetLookupTable(p.table);
  pointsMapper->UseLookupTableScalarRangeOn();
  p.pointsActor = vtkSmartPointer<vtkActor>::New();
  p.pointsActor->SetMapper(pointsMapper);
  p.pointsActor->GetProperty()->SetRepresentationToPoints();
  p.pointsActor->GetProperty()->SetPointSize(2);
  p.pointsActor->VisibilityOff();
  p.renderer->AddActor(p.pointsActor);

  if (!data.toolAxes.empty()) {
    p.toolAxesActor = makeToolAxesActor(data.toolAxes);
    p.toolAxesActor->SetVisibility(style.showToolAxes);
    p.renderer->AddActor(p.toolAxesActor);
  }
  // The toolpath blends over what is drawn before it (makeToolpathActor): after the surfaces.
  if (style.showToolpath && !data.toolpath.empty()) {
    p.toolpathActor = makeToolpathActor(data.toolpath, data.toolpathScalars, p.table);
    p.toolpathOpacity = p.toolpathActor->GetProperty()->GetOpacity();
    // A toolpath coloured by the values shows them where the surface is hidden: never faded.
    if (data.toolpathScalars.empty()) p.passSpacing = medianPassSpacing(data.positions, *data.mesh);
    p.renderer->AddActor(p.toolpathActor);
  }

  const float lineCore[3] = {1.0f, 1.0f, 0.85f}, lineRim[3] = {1.0f, 0.15f, 0.55f};
  const float sampleCore[3] = {1.0f, 1.0f, 1.0f}, sampleRim[3] = {1.0f, 0.85f, 0.1f};
  p.lineGlow = makeGlowActor(p.lineGlowPoints, kLineGlowSize, lineCore, lineRim);
  p.sampleGlow = makeGlowActor(p.sampleGlowPoints, kSampleGlowSize, sampleCore, sampleRim);
  setHighlight(data.highlight, {});
  p.renderer->AddActor(p.lineGlow);
  p.renderer->AddActor(p.sampleGlow);

  p.legend = makeLegend(p.table, style);
  p.renderer->AddActor2D(p.legend);
  p.legendText = legendTitle(style.quantityLabel, style.unit);
  p.fontSize = style.fontSize;
  if (!style.caption.empty()) {
    p.caption = makeCaption(style.caption, style.fontSize);
    p.captionText = style.caption;
    p.renderer->AddActor2D(p.caption);
  }
  p.axesCorner->AddActor(makeAxes());
  p.axesCorner->SetViewport(0.0, 0.0, kAxesCornerWidth, kAxesCornerHeight);
  p.axesCorner->SetLayer(1);
  p.axesCorner->InteractiveOff();
  setView(style.view);
}

namespace {

// Characters of the longest line of a text.
std::size_t longestLine(const std::string& text) {
  std::size_t longest = 0, length = 0;
  for (char c : text) {
    length = c == '\n' ? 0 : length + 1;
    longest = std::max(longest, length);
  }
  return longest;
}

// A proportional font's average advance, in font sizes: what a line of n characters takes.
constexpr double kAdvance = 0.56;
constexpr int kSmallestCaption = 11;

// Each line of `text` longer than `chars` broken at the last blank that keeps it within.
std::string wrapLines(const std::string& text, std::size_t chars) {
  std::string out;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != '\n') continue;
    std::string line = text.substr(lineStart, i - lineStart);
    while (line.size() > chars) {
      std::size_t cut = line.rfind(' ', chars);
      if (cut != std::string::npos && cut > 0) {
        out += line.substr(0, cut) + "\n";
        line = line.substr(cut + 1);
        continue;
      }
      // No blank to break at: cut between characters, not inside one (UTF-8).
      cut = chars;
      while (cut > 1 && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80) --cut;
      out += line.substr(0, cut) + "\n";
      line = line.substr(cut);
    }
    out += line + (i < text.size() ? "\n" : "");
    lineStart = i + 1;
  }
  return out;
}

}  // namespace

void QualityScene::fitOverlaysToWidth(int width, double drawnScale) {
  Parts& p = *parts_;
  if (width <= 0) return;
  // The glows are points of so many pixels: as large on the screen, and as cheap, at any scale.
  p.lineGlow->GetProperty()->SetPointSize(static_cast<float>(kLineGlowSize * drawnScale));
  p.sampleGlow->GetProperty()->SetPointSize(static_cast<float>(kSampleGlowSize * drawnScale));
  const auto drawn = [&](int size) { return std::max(4, static_cast<int>(std::lround(size * drawnScale))); };
  // The caption spans at most the width left of the legend; the legend's title, centred over
  // the bar, at most what lies right of 0.80 of the width.
  const auto fit = [&](std::size_t chars, double share) {
    if (chars == 0) return p.fontSize;
    const double size = share * width / (kAdvance * static_cast<double>(chars));
    return std::clamp(static_cast<int>(size), 8, p.fontSize);
  };
  if (p.caption) {
    // Smaller down to a size still easy to read, then lines broken at words instead.
    const int size = std::max(kSmallestCaption, fit(longestLine(p.captionText), 0.80));
    const auto chars = static_cast<std::size_t>(0.80 * width / (kAdvance * size));
    p.caption->GetTextProperty()->SetFontSize(drawn(size));
    p.caption->SetInput(wrapLines(p.captionText, std::max<std::size_t>(chars, 20)).c_str());
  }
  const int legendSize = fit(longestLine(p.legendText), 0.17);
  p.legend->GetTitleTextProperty()->SetFontSize(drawn(legendSize));
  p.legend->GetLabelTextProperty()->SetFontSize(drawn(std::max(8, legendSize - 2)));
}

void QualityScene::setHighlight(const std::vector<Vec3>& line, const std::vector<Vec3>& sample) {
  setPoints(parts_->lineGlowPoints, line);
  setPoints(parts_->sampleGlowPoints, sample);
  parts_->lineGlow->SetVisibility(!line.empty());
  parts_->sampleGlow->SetVisibility(!sample.empty());
}

void QualityScene::setTool(const std::optional<Vec3>& tip, const Vec3& axis) {
  Parts& p = *parts_;
  p.toolTip = tip;
  if (!tip) {
    if (p.tool) p.tool->SetVisibility(false);
    return;
  }
  if (!p.tool) {
    p.tool = makeBallEndMill(kShownToolRadius);
    p.renderer->AddActor(p.tool);
  }
  p.tool->SetPosition(tip->x(), tip->y(), tip->z());
  // The mill stands along +Z about its tip (the origin): turned onto the tool axis.
  p.tool->SetOrientation(0, 0, 0);
  const Vec3 up = Vec3::UnitZ(), along = axis.norm() > 1e-9 ? Vec3(axis.normalized()) : up;
  const Vec3 turnAbout = up.cross(along);
  const double degrees = std::atan2(turnAbout.norm(), up.dot(along)) * 180.0 / 3.14159265358979323846;
  if (turnAbout.norm() > 1e-12) p.tool->RotateWXYZ(degrees, turnAbout.x(), turnAbout.y(), turnAbout.z());
  else if (up.dot(along) < 0) p.tool->RotateWXYZ(180, 1, 0, 0);
  p.tool->SetVisibility(true);
}

std::optional<Vec3> QualityScene::toolTip() const { return parts_->toolTip; }

void QualityScene::useCoarseSurface(bool coarse) {
  Parts& p = *parts_;
  p.coarse = coarse && p.coarseActor;
  const bool detail = p.detailActor && p.detailAllowed;
  p.surfaceActor->SetVisibility(p.showSurface && !p.coarse && !detail);
  if (p.detailActor) p.detailActor->SetVisibility(p.showSurface && !p.coarse && detail);
  if (p.coarseActor) p.coarseActor->SetVisibility(p.showSurface && p.coarse);
}

void QualityScene::setDetailSurface(const DetailSurface* detail) {
  Parts& p = *parts_;
  if (p.detailActor) p.renderer->RemoveActor(p.detailActor);
  p.detailActor = nullptr;
  if (detail && detail->mesh) {
    vtkSmartPointer<vtkPolyData> poly = surfacePolyData(detail->positions, *detail->mesh);
    addPointArray(poly, "value", detail->scalars);
    poly->GetPointData()->SetActiveScalars("value");
    p.detailActor = makeSurfaceActor(poly, p.table, p.style, p.style.passWires);
    p.renderer->AddActor(p.detailActor);
    // The toolpath blends over what is drawn before it (makeToolpathActor): it stays last.
    if (p.toolpathActor) {
      p.renderer->RemoveActor(p.toolpathActor);
      p.renderer->AddActor(p.toolpathActor);
    }
  }
  useCoarseSurface(p.coarse);
}

bool QualityScene::showsDetail() const { return parts_->detailActor != nullptr; }

void QualityScene::allowDetailSurface(bool allowed) {
  parts_->detailAllowed = allowed;
  useCoarseSurface(parts_->coarse);
}

bool QualityScene::hasToolAxes() const { return parts_->toolAxesActor != nullptr; }

void QualityScene::setVisibility(bool surface, bool toolpath, bool points, bool toolAxes) {
  Parts& p = *parts_;
  if (p.toolAxesActor) p.toolAxesActor->SetVisibility(toolAxes);
  p.showSurface = surface;
  useCoarseSurface(p.coarse);
  p.showToolpath = toolpath;
  fadeDenseToolpath();
  p.pointsActor->SetVisibility(points);
}

QualityScene::~QualityScene() { delete parts_; }

void QualityScene::attachTo(vtkRenderWindow* window) {
  window->SetNumberOfLayers(2);
  window->AddRenderer(parts_->renderer);
  window->AddRenderer(parts_->axesCorner);
}

void QualityScene::setView(ViewDirection view) {
  vtkCamera* camera = parts_->renderer->GetActiveCamera();
  double bounds[6];
  parts_->surface->GetBounds(bounds);
  const double centre[3] = {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])};
  double direction[3] = {1, -1, 0.9}, up[3] = {0, 0, 1};
  switch (view) {
    case ViewDirection::Top: direction[0] = 0, direction[1] = 0, direction[2] = 1, up[1] = 1, up[2] = 0; break;
    case ViewDirection::Front: direction[0] = 0, direction[1] = -1, direction[2] = 0; break;
    case ViewDirection::Left: direction[0] = -1, direction[1] = 0, direction[2] = 0; break;
    case ViewDirection::Iso: break;
  }
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + direction[0], centre[1] + direction[1], centre[2] + direction[2]);
  camera->SetViewUp(up);
  camera->ParallelProjectionOn();
  parts_->renderer->ResetCamera(bounds);
  camera->Zoom(1.15);
  followCamera();
}

void QualityScene::frameBox(const Vec3& lower, const Vec3& upper) {
  // A box of a few samples (a region at one point) is widened to a readable neighbourhood.
  double bounds[6];
  parts_->surface->GetBounds(bounds);
  const double whole = std::max({bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-3});
  double box[6];
  for (int a = 0; a < 3; ++a) {
    const double half = std::max(0.5 * (upper[a] - lower[a]), 0.03 * whole) * 1.25;
    const double centre = 0.5 * (lower[a] + upper[a]);
    box[2 * a] = centre - half;
    box[2 * a + 1] = centre + half;
  }
  for (const double b : box)
    if (!std::isfinite(b)) return;  // keeps the whole view
  vtkCamera* camera = parts_->renderer->GetActiveCamera();
  parts_->renderer->ResetCamera(box);
  // The parallel view's scale is set; the camera then steps back along its direction beyond the
  // whole surface, so that no part of it higher than the box (a wall by a cavity) is behind it
  // and cut away.
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  double direction[3] = {position[0] - focal[0], position[1] - focal[1], position[2] - focal[2]};
  const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                                    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                                    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  if (length > 0) {
    const double away = (length + 2 * diagonal) / length;
    camera->SetPosition(focal[0] + direction[0] * away, focal[1] + direction[1] * away, focal[2] + direction[2] * away);
  }
  parts_->renderer->ResetCameraClippingRange();  // the whole surface, not the box
  followCamera();
}

void QualityScene::followCamera() {
  fadeDenseToolpath();
  vtkCamera* main = parts_->renderer->GetActiveCamera();
  vtkCamera* corner = parts_->axesCorner->GetActiveCamera();
  double position[3], focal[3];
  main->GetPosition(position);
  main->GetFocalPoint(focal);
  double direction[3] = {position[0] - focal[0], position[1] - focal[1], position[2] - focal[2]};
  const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (double& d : direction) d = length > 0 ? d / length : 0;
  corner->SetFocalPoint(0, 0, 0);
  corner->SetPosition(4 * direction[0], 4 * direction[1], 4 * direction[2]);
  corner->SetViewUp(main->GetViewUp());
  parts_->axesCorner->ResetCamera();
}

// As the pass wires do (pass_wire.frag.glsl): full from 6 pixels apart, gone at 2.
void QualityScene::fadeDenseToolpath() {
  Parts& p = *parts_;
  if (!p.toolpathActor) return;
  const int* size = p.renderer->GetSize();
  vtkCamera* camera = p.renderer->GetActiveCamera();
  double apart = 1;
  if (p.passSpacing > 0 && size && size[1] > 0) {
    const double shown = camera->GetParallelProjection()
                             ? 2 * camera->GetParallelScale()
                             : 2 * camera->GetDistance() * std::tan(0.5 * camera->GetViewAngle() * kPi / 180);
    const double pixels = p.passSpacing * size[1] / shown;
    if (std::isfinite(pixels)) apart = std::clamp((pixels - 2) / 4, 0.0, 1.0);
  }
  p.toolpathActor->GetProperty()->SetOpacity(p.toolpathOpacity * apart);
  p.toolpathActor->SetVisibility(p.showToolpath && apart > 0);
}

vtkRenderer* QualityScene::renderer() const { return parts_->renderer; }
vtkPolyData* QualityScene::surface() const { return parts_->surface; }
vtkLookupTable* QualityScene::lookupTable() const { return parts_->table; }

}  // namespace isurface::vis
