#pragma once
// The pieces of a quality-map scene, each built on its own.
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

#include "isurface/base/geometry.h"

class vtkActor;
class vtkActor2D;
class vtkAxesActor;
class vtkLookupTable;
class vtkPolyData;
class vtkScalarBarActor;
class vtkTextActor;

namespace isurface::vis {

struct MapStyle;

// The coloured surface with the iso-line and pass-wire shaders.
vtkSmartPointer<vtkActor> makeSurfaceActor(vtkPolyData* surface, vtkLookupTable* table, const MapStyle& style,
                                           bool passWires);
// Polylines, plain or coloured through the table by per-point values.
vtkSmartPointer<vtkActor> makeToolpathActor(const std::vector<std::vector<Vec3>>& lines,
                                            const std::vector<std::vector<float>>& values, vtkLookupTable* table);
// A five-axis run's tool axis: a dark stroke from each tip up the tool.
vtkSmartPointer<vtkActor> makeToolAxesActor(const std::vector<std::array<Vec3, 2>>& strokes);
// Glowing point sprites; their points are set with setPoints().
vtkSmartPointer<vtkActor> makeGlowActor(vtkPolyData* points, float size, const float core[3], const float rim[3]);
void setPoints(vtkPolyData* points, const std::vector<Vec3>& positions);
// The legend's title: the label's words in lines of up to kLegendLineChars, then "[unit]".
constexpr std::size_t kLegendLineChars = 16;
std::string legendTitle(const std::string& label, const std::string& unit);
vtkSmartPointer<vtkScalarBarActor> makeLegend(vtkLookupTable* table, const MapStyle& style);
vtkSmartPointer<vtkTextActor> makeCaption(const std::string& text, int fontSize);
vtkSmartPointer<vtkAxesActor> makeAxes();

}  // namespace isurface::vis
