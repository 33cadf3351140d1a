#pragma once
// The quality-map scene: the CL surface coloured by one quantity (with iso-lines of it and a
// faint wire along every pass, drawn by the shaders in shaders/), the programmed tool path,
// the glowing samples of a selected G-code line, a legend, a caption and orientation axes.
#include <optional>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "isurface/map/map_style.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindow;
class vtkLookupTable;

namespace isurface::vis {

struct DetailSurface;
// The orientation axes take the view's lower left corner: these fractions of its width and height.
constexpr double kAxesCornerWidth = 0.14, kAxesCornerHeight = 0.2;
// The colour legend's left edge, a share of the view's width.
constexpr double kLegendLeft = 0.84;

class QualityScene {
 public:
  QualityScene(const SurfaceData& data, const MapStyle& style);
  ~QualityScene();

  // Adds the scene's renderers to a window (main view and the orientation-axes corner).
  void attachTo(vtkRenderWindow* window);
  void setView(ViewDirection view);
  // Keeps the view's direction and fills the view with a box of the surface (mm), with a
  // margin around it: a region's close-up.
  void frameBox(const Vec3& lower, const Vec3& upper);
  // Keeps the axes corner turned like the main camera, and fades the toolpath out where its
  // passes lie closer than a few pixels (they would cover the colours); call before each render.
  void followCamera();

  // The glowing samples: a selected line's, and the selected sample itself (brighter, larger).
  void setHighlight(const std::vector<Vec3>& line, const std::vector<Vec3>& sample);
  // The tool standing on a cutter-location point (mm; none: not drawn), a D6R3 ball-end mill,
  // along `axis` (unit, from the tip up the tool: a five-axis run's tool axis; +Z otherwise).
  void setTool(const std::optional<Vec3>& tip, const Vec3& axis = Vec3::UnitZ());
  std::optional<Vec3> toolTip() const;
  // Shows the coarse surface instead of the full one (while the camera moves), if there is one.
  void useCoarseSurface(bool coarse);
  // A close-up of part of the surface, finer than the whole one, shown instead of it at rest (the
  // coarse surface still stands in while the camera moves); null takes it away.
  void setDetailSurface(const DetailSurface* detail);
  bool showsDetail() const;
  // A picture of another shape than the view the close-up was made for shows more than it
  // covers: drawn with the whole surface instead while not allowed.
  void allowDetailSurface(bool allowed);
  // `toolAxes`: a five-axis run's tool axis (SurfaceData::toolAxes), where the scene has it.
  void setVisibility(bool surface, bool toolpath, bool points, bool toolAxes);
  bool hasToolAxes() const;
  // Makes the caption and the legend's text smaller where a view `width` pixels wide would cut
  // them (never larger than the style's font size). A view drawn at `drawnScale` of that width
  // (and shown stretched back to it) gets its text and its glows at that scale too.
  void fitOverlaysToWidth(int width, double drawnScale = 1.0);

  vtkRenderer* renderer() const;
  vtkPolyData* surface() const;  // points, triangles, "value" and "pass_coord" arrays
  vtkLookupTable* lookupTable() const;

 private:
  void fadeDenseToolpath();
  struct Parts;
  Parts* parts_;
};

// Surface polydata with any number of named per-vertex arrays (for export to ParaView).
vtkSmartPointer<vtkPolyData> surfacePolyData(const std::vector<Vec3>& positions, const SurfaceMesh& mesh);
void addPointArray(vtkPolyData* polyData, const std::string& name, const std::vector<float>& values);

}  // namespace isurface::vis
