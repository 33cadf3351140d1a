#include "scene_actors.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkScalarBarActor.h>
#include <vtkShaderProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUniforms.h>

#include <algorithm>
#include <sstream>

#include "isurface/vis/quality_scene.h"
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

}  // namespace

vtkSmartPointer<vtkActor> makeSurfaceActor(vtkPolyData* surface, vtkLookupTable* table, const MapStyle& style,
                                           bool passWires) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(surface);
  mapper->SetLookupTable(table);
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  mapper->UseLookupTableScalarRangeOn();
  // Interpolating the value (not the colour) across triangles keeps bands sharp and gives the
  // fragment shader the value itself (as the colour texture coordinate) for the iso-lines.
  mapper->InterpolateScalarsBeforeMappingOn();
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->MapDataArrayToVertexAttribute("passCoord", "pass_coord", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.25);
  actor->GetProperty()->SetDiffuse(0.8);
  actor->GetProperty()->SetSpecular(0.08);
  actor->GetProperty()->SetSpecularPower(20);
  actor->GetProperty()->BackfaceCullingOff();

  vtkShaderProperty* shaders = actor->GetShaderProperty();
  const ShaderPiece passVertex = shaderPiece("shaders/pass_wire.vert.glsl");
  const ShaderPiece passFragment = shaderPiece("shaders/pass_wire.frag.glsl");
  std::string lightImpl = "//VTK::Light::Impl\n";
  if (style.isoBands > 0) lightImpl += resourceText("shaders/iso_bands.frag.glsl");
  if (passWires) lightImpl += passFragment.implementation;
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
  return actor;
}

vtkSmartPointer<vtkActor> makeToolpathActor(const std::vector<std::vector<Vec3>>& lines,
                                            const std::vector<std::vector<float>>& values, vtkLookupTable* table) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  const bool coloured = values.size() == lines.size();
  std::vector<float> pointValues;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto& line = lines[k];
    if (line.size() < 2) continue;
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const Vec3& p : line) cells->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
    if (coloured) pointValues.insert(pointValues.end(), values[k].begin(), values[k].end());
  }
  auto path = vtkSmartPointer<vtkPolyData>::New();
  path->SetPoints(points);
  path->SetLines(cells);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  if (coloured) {
    addPointArray(path, "value", pointValues);
    path->GetPointData()->SetActiveScalars("value");
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    mapper->ScalarVisibilityOn();
  } else {
    mapper->ScalarVisibilityOff();
  }
  mapper->SetInputData(path);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.15, 0.15, 0.2);
  actor->GetProperty()->SetOpacity(coloured ? 1.0 : 0.35);
  // Drawn after the surfaces in the opaque pass, blended over them all the same: as translucent
  // geometry it made VTK build its order-independent transparency's whole-window buffers for
  // every picture, a tenth of a second under llvmpipe.
  actor->ForceOpaqueOn();
  actor->GetProperty()->SetLineWidth(coloured ? 2.0f : 1.0f);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkActor> makeToolAxesActor(const std::vector<std::array<Vec3, 2>>& strokes) {
  std::vector<std::vector<Vec3>> lines;
  lines.reserve(strokes.size());
  for (const auto& stroke : strokes) lines.push_back({stroke[0], stroke[1]});
  vtkSmartPointer<vtkActor> actor = makeToolpathActor(lines, {}, nullptr);
  actor->GetProperty()->SetColor(0.05, 0.1, 0.35);
  actor->GetProperty()->SetOpacity(0.9);
  actor->GetProperty()->SetLineWidth(1.5f);
  return actor;
}

void setPoints(vtkPolyData* poly, const std::vector<Vec3>& positions) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (const Vec3& h : positions) {
    const vtkIdType id = points->InsertNextPoint(h.x(), h.y(), h.z());
    verts->InsertNextCell(1, &id);
  }
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->Modified();
}

vtkSmartPointer<vtkActor> makeGlowActor(vtkPolyData* points, float size, const float core[3], const float rim[3]) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(points);
  mapper->ScalarVisibilityOff();
  auto glow = vtkSmartPointer<vtkActor>::New();
  glow->SetMapper(mapper);
  glow->GetProperty()->SetPointSize(size);
  glow->GetProperty()->SetOpacity(0.99);  // drawn in the translucent pass, blended
  glow->GetProperty()->LightingOff();
  vtkShaderProperty* shader = glow->GetShaderProperty();
  shader->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
                                       "//VTK::Light::Impl\n" + resourceText("shaders/glow.frag.glsl"), false);
  shader->GetFragmentCustomUniforms()->SetUniform3f("glowCore", core);
  shader->GetFragmentCustomUniforms()->SetUniform3f("glowRim", rim);
  return glow;
}

std::string legendTitle(const std::string& label, const std::string& unit) {
  // Words fill lines of up to kLegendLineChars (a word longer than that has a line of its own):
  // the legend is narrow, but one word a line reads badly.
  std::string title, line;
  std::istringstream words(label);
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > kLegendLineChars) {
      title += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  title += line;
  return unit.empty() ? title : title + "\n[" + unit + "]";
}

vtkSmartPointer<vtkScalarBarActor> makeLegend(vtkLookupTable* table, const MapStyle& style) {
  auto legend = vtkSmartPointer<vtkScalarBarActor>::New();
  legend->SetLookupTable(table);
  const std::string title = legendTitle(style.quantityLabel, style.unit);
  legend->SetTitle(title.c_str());
  legend->SetNumberOfLabels(6);
  legend->SetLabelFormat("%.4g");
  legend->SetMaximumWidthInPixels(130);
  legend->SetBarRatio(0.25);
  // Far enough from the right edge that a title wider than the bar, centred over the legend,
  // stays inside a view half the window wide (the maps side by side).
  legend->GetPositionCoordinate()->SetValue(kLegendLeft, 0.1);
  // Room between the title's last line and the top label, which it touched.
  legend->SetVerticalTitleSeparation(6);
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
  return legend;
}

vtkSmartPointer<vtkTextActor> makeCaption(const std::string& text, int fontSize) {
  auto caption = vtkSmartPointer<vtkTextActor>::New();
  caption->SetInput(text.c_str());
  caption->GetTextProperty()->SetColor(0.1, 0.1, 0.12);
  caption->GetTextProperty()->SetFontSize(fontSize);
  caption->GetTextProperty()->SetVerticalJustificationToTop();
  caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  caption->GetPositionCoordinate()->SetValue(0.01, 0.985);
  return caption;
}

vtkSmartPointer<vtkAxesActor> makeAxes() {
  auto axes = vtkSmartPointer<vtkAxesActor>::New();
  axes->SetShaftTypeToCylinder();
  axes->SetTotalLength(1, 1, 1);
  for (vtkCaptionActor2D* label : {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(),
                                   axes->GetZAxisCaptionActor2D()}) {
    label->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.12);
    label->GetCaptionTextProperty()->ShadowOff();
    label->GetCaptionTextProperty()->ItalicOff();
  }
  return axes;
}

}  // namespace isurface::vis
