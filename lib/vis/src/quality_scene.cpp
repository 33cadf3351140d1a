#include "isurface/vis/quality_scene.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
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
#include <vtkUniforms.h>

#include <algorithm>
#include <cmath>

#include "isurface/vis/color_map.h"
#include "isurface/vis/resources.h"

namespace isurface::vis {

namespace {

// A shader file split at its //DECLARATIONS and //IMPLEMENTATION markers (or all of it the
// implementation when it has none).
struct ShaderPiece {
  std::string declarations, implementation;
};

ShaderPiece shaderPiece(const std::string& path) {
  const std::string& text = resourceText(path);
  const auto decl = text.find("//DECLARATIONS"), impl = text.find("//IMPLEMENTATION");
  if (decl == std::string::npos || impl == std::string::npos) return {"", text};
  return {text.substr(decl + 14, impl - decl - 14), text.substr(impl + 16)};
}

vtkSmartPointer<vtkPolyData> polylines(const std::vector<std::vector<Vec3>>& lines) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const Vec3& p : line) cells->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(cells);
  return poly;
}

}  // namespace

std::optional<ViewDirection> parseView(const std::string& name) {
  if (name == "iso") return ViewDirection::Iso;
  if (name == "top") return ViewDirection::Top;
  if (name == "front") return ViewDirection::Front;
  if (name == "left") return ViewDirection::Left;
  return std::nullopt;
}

vtkSmartPointer<vtkPolyData> surfacePolyData(const std::vector<Vec3>& positions, const SurfaceMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), positions[i].x(), positions[i].y(), positions[i].z());
  // Fill the cell array's offsets and connectivity directly: no per-triangle insertion calls.
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  const vtkIdType triangles = static_cast<vtkIdType>(mesh.triangles.size());
  offsets->SetNumberOfValues(triangles + 1);
  connectivity->SetNumberOfValues(3 * triangles);
  for (vtkIdType t = 0; t < triangles; ++t) {
    offsets->SetValue(t, 3 * t);
    for (int k = 0; k < 3; ++k) connectivity->SetValue(3 * t + k, mesh.triangles[t][k]);
  }
  offsets->SetValue(triangles, 3 * triangles);
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

struct QualityScene::Parts {
  vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkRenderer> axesCorner = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkPolyData> surface;
  vtkSmartPointer<vtkLookupTable> table;
  vtkSmartPointer<vtkActor> surfaceActor = vtkSmartPointer<vtkActor>::New();
};

QualityScene::QualityScene(const SurfaceData& data, const MapStyle& style) : parts_(new Parts) {
  Parts& p = *parts_;
  p.renderer->SetBackground(1.0, 1.0, 1.0);
  p.renderer->SetBackground2(0.86, 0.89, 0.93);
  p.renderer->GradientBackgroundOn();
  p.renderer->SetBackgroundAlpha(1.0);
  p.renderer->SetUseFXAA(false);

  p.table = makeLookupTable(style.colorMap, style.range.lo, style.range.hi);
  p.surface = surfacePolyData(data.positions, *data.mesh);
  addPointArray(p.surface, "value", data.scalars);
  p.surface->GetPointData()->SetActiveScalars("value");

  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(p.surface);
  mapper->SetLookupTable(p.table);
  mapper->SetScalarRange(style.range.lo, style.range.hi);
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  mapper->UseLookupTableScalarRangeOn();
  // Interpolating the value (not the colour) across triangles keeps bands sharp and gives the
  // fragment shader the value itself (as the colour texture coordinate) for the iso-lines.
  mapper->InterpolateScalarsBeforeMappingOn();
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->MapDataArrayToVertexAttribute("passCoord", "pass_coord", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  p.surfaceActor->SetMapper(mapper);
  p.surfaceActor->GetProperty()->SetAmbient(0.25);
  p.surfaceActor->GetProperty()->SetDiffuse(0.8);
  p.surfaceActor->GetProperty()->SetSpecular(0.08);
  p.surfaceActor->GetProperty()->SetSpecularPower(20);
  p.surfaceActor->GetProperty()->BackfaceCullingOff();

  vtkShaderProperty* shaders = p.surfaceActor->GetShaderProperty();
  const ShaderPiece passVertex = shaderPiece("shaders/pass_wire.vert.glsl");
  const ShaderPiece passFragment = shaderPiece("shaders/pass_wire.frag.glsl");
  std::string lightImpl = "//VTK::Light::Impl\n";
  if (style.isoBands > 0) lightImpl += resourceText("shaders/iso_bands.frag.glsl");
  if (style.passWires) lightImpl += passFragment.implementation;
  shaders->AddVertexShaderReplacement("//VTK::PositionVC::Dec", true,
                                      "//VTK::PositionVC::Dec\n" + passVertex.declarations, false);
  shaders->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true,
                                      "//VTK::PositionVC::Impl\n" + passVertex.implementation, false);
  shaders->AddFragmentShaderReplacement("//VTK::Color::Dec", true, "//VTK::Color::Dec\n" + passFragment.declarations,
                                        false);
  shaders->AddFragmentShaderReplacement("//VTK::Light::Impl", true, lightImpl, false);
  shaders->GetFragmentCustomUniforms()->SetUniformf("isoBands", static_cast<float>(std::max(style.isoBands, 1)));
  shaders->GetFragmentCustomUniforms()->SetUniformf("isoStrength", 0.4f);
  shaders->GetFragmentCustomUniforms()->SetUniformf("passWireStrength", 0.12f);
  p.renderer->AddActor(p.surfaceActor);

  if (style.showToolpath && !data.toolpath.empty()) {
    auto pathMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    vtkSmartPointer<vtkPolyData> path = polylines(data.toolpath);
    const bool coloured = data.toolpathScalars.size() == data.toolpath.size();
    if (coloured) {
      std::vector<float> values;
      for (std::size_t k = 0; k < data.toolpath.size(); ++k)
        if (data.toolpath[k].size() >= 2)
          values.insert(values.end(), data.toolpathScalars[k].begin(), data.toolpathScalars[k].end());
      addPointArray(path, "value", values);
      path->GetPointData()->SetActiveScalars("value");
      pathMapper->SetLookupTable(p.table);
      pathMapper->UseLookupTableScalarRangeOn();
      pathMapper->ScalarVisibilityOn();
    } else {
      pathMapper->ScalarVisibilityOff();
    }
    pathMapper->SetInputData(path);
    auto pathActor = vtkSmartPointer<vtkActor>::New();
    pathActor->SetMapper(pathMapper);
    pathActor->GetProperty()->SetColor(0.15, 0.15, 0.2);
    pathActor->GetProperty()->SetOpacity(coloured ? 1.0 : 0.35);
    pathActor->GetProperty()->SetLineWidth(coloured ? 2.0 : 1.0);
    pathActor->GetProperty()->LightingOff();
    p.renderer->AddActor(pathActor);
  }

  if (!data.highlight.empty()) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    for (const Vec3& h : data.highlight) {
      const vtkIdType id = points->InsertNextPoint(h.x(), h.y(), h.z());
      verts->InsertNextCell(1, &id);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(verts);
    auto glowMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    glowMapper->SetInputData(poly);
    glowMapper->ScalarVisibilityOff();
    auto glow = vtkSmartPointer<vtkActor>::New();
    glow->SetMapper(glowMapper);
    glow->GetProperty()->SetPointSize(14);
    glow->GetProperty()->SetOpacity(0.99);  // drawn in the translucent pass, blended
    glow->GetProperty()->LightingOff();
    vtkShaderProperty* glowShader = glow->GetShaderProperty();
    glowShader->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                             "//VTK::Light::Impl\n" + resourceText("shaders/glow.frag.glsl"), false);
    const float core[3] = {1.0f, 1.0f, 0.85f}, rim[3] = {1.0f, 0.15f, 0.55f};
    glowShader->GetFragmentCustomUniforms()->SetUniform3f("glowCore", core);
    glowShader->GetFragmentCustomUniforms()->SetUniform3f("glowRim", rim);
    p.renderer->AddActor(glow);
  }

  auto legend = vtkSmartPointer<vtkScalarBarActor>::New();
  legend->SetLookupTable(p.table);
  // Long labels go one word a line: the legend is narrow.
  std::string label = style.quantityLabel;
  if (label.size() > 12) std::replace(label.begin(), label.end(), ' ', '\n');
  const std::string title = label + (style.unit.empty() ? "" : "\n[" + style.unit + "]");
  legend->SetTitle(title.c_str());
  legend->SetNumberOfLabels(6);
  legend->SetLabelFormat("%.4g");
  legend->SetMaximumWidthInPixels(130);
  legend->SetBarRatio(0.25);
  legend->GetPositionCoordinate()->SetValue(0.88, 0.1);
  legend->SetWidth(0.11);
  legend->SetHeight(0.8);
  for (vtkTextProperty* text : {legend->GetTitleTextProperty(), legend->GetLabelTextProperty()}) {
    text->SetColor(0.1, 0.1, 0.12);
    text->ShadowOff();
    text->ItalicOff();
    text->BoldOff();
  }
  legend->GetTitleTextProperty()->SetFontSize(style.fontSize);
  legend->GetLabelTextProperty()->SetFontSize(style.fontSize - 2);
  legend->UnconstrainedFontSizeOn();
  p.renderer->AddActor2D(legend);

  if (!style.caption.empty()) {
    auto caption = vtkSmartPointer<vtkTextActor>::New();
    caption->SetInput(style.caption.c_str());
    caption->GetTextProperty()->SetColor(0.1, 0.1, 0.12);
    caption->GetTextProperty()->SetFontSize(style.fontSize);
    caption->GetTextProperty()->SetVerticalJustificationToTop();
    caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    caption->GetPositionCoordinate()->SetValue(0.01, 0.985);
    p.renderer->AddActor2D(caption);
  }

  auto axes = vtkSmartPointer<vtkAxesActor>::New();
  axes->SetShaftTypeToCylinder();
  axes->SetTotalLength(1, 1, 1);
  for (vtkCaptionActor2D* label : {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(),
                                   axes->GetZAxisCaptionActor2D()}) {
    label->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.12);
    label->GetCaptionTextProperty()->ShadowOff();
    label->GetCaptionTextProperty()->ItalicOff();
  }
  p.axesCorner->AddActor(axes);
  p.axesCorner->SetViewport(0.0, 0.0, 0.14, 0.2);
  p.axesCorner->SetLayer(1);
  p.axesCorner->InteractiveOff();
  setView(style.view);
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
  syncAxes();
}

void QualityScene::syncAxes() {
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

vtkRenderer* QualityScene::renderer() const { return parts_->renderer; }
vtkPolyData* QualityScene::surface() const { return parts_->surface; }
vtkLookupTable* QualityScene::lookupTable() const { return parts_->table; }

}  // namespace isurface::vis
