#pragma once
// From samples to a ready scene description: passes, surface mesh, the coloured quantity, its
// range, the programmed tool path and the highlighted line.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "isurface/gcode/program.h"
#include "isurface/analysis/quantities.h"
#include "isurface/base/trajectory.h"
#include "isurface/surface/surface_ray_index.h"
#include "isurface/map/map_style.h"

namespace isurface::vis {

// Vertices enough for a picture of `pixels` pixels: half a vertex a pixel. A mesh has about two
// triangles a vertex, so a surface filling the picture still gets at least a triangle a pixel;
// more vertices change no pixel but cost memory (about 260 bytes a vertex on screen) and time.
constexpr std::size_t vertexBudgetForPixels(std::size_t pixels) { return std::max<std::size_t>(pixels / 2, 50'000); }

// Quality figures and regions are measured on a surface of up to this many vertices, whatever
// the picture it is shown in: the same program gives the same figures in every window.
constexpr std::size_t kFiguresVertices = 3'000'000;

struct QualityMapRequest {
  Quantity quantity = Quantity::Speed;
  std::string channel;                       // when not empty: colour by this channel of the dump instead
  // When set: colour by these values, one per sample (a comparison with another run), named
  // by valuesLabel and valuesUnit, instead of the quantity or channel.
  std::shared_ptr<const std::vector<float>> sampleValues;
  std::string valuesLabel, valuesUnit;
  bool feedbackSurface = false;              // the surface of the feedback positions
  std::optional<std::uint32_t> highlightLine;
  std::string colorMap = "auto";              // see resolveColorMap()
  std::optional<ValueRange> fixedRange;      // else percentile-clipped
  double lowPercent = 1, highPercent = 99;   // with both 0 and 100: the full range
  ViewDirection view = ViewDirection::Iso;
  bool showToolpath = true;
  bool colorToolpath = false;                // the sampled cutting path coloured by the quantity
  bool passWires = true;
  bool toolAxes = false;                     // a five-axis run's tool axis along the passes, where the samples have it
  int isoBands = 12;
  double gapLimit = MeshOptions{}.gapLimit;  // mm; passes further apart are not joined by triangles
  PathPattern pattern = PathPattern::Auto;   // how the samples split into passes
  // Samples are thinned along passes beyond this (a picture needs no more than
  // vertexBudgetForPixels of its size).
  std::size_t maxVertices = kFiguresVertices;
  std::size_t coarseVertices = 0;            // > 0: also a coarse surface of about this many vertices
  bool pickable = false;                     // also index the surface for picking (QualityMap::rayIndex)
  std::string caption;                       // prefix of the caption (e.g. the file name)
  // Values in mm, mm/min, mm/s^2 or mm/s^3 coloured and labelled in inches (in, in/min, ...);
  // the geometry stays in mm.
  bool inch = false;
};

// True when a map of this request reads the servo's positions (fb_x fb_y fb_z).
bool needsFeedback(const QualityMapRequest& request);

// Held by pointer so that `data` keeps pointing at them when the map is moved; shared so that
// picking and region optimisation use the surface the map shows.
struct QualityMap {
  std::shared_ptr<const SurfaceMesh> mesh, coarseMesh;
  std::shared_ptr<const SurfaceRayIndex> rayIndex;  // of `mesh`, when the request was pickable
  PassSet passes;
  SurfaceData data;
  MapStyle style;
  QualityMapRequest request;  // what it was made for: a close-up of it is made alike
};

// A surface on less than this share of the cutting path's vertices is mostly empty.
constexpr double kLittleSurfaceShare = 0.5;
inline constexpr const char* kLittleSurfaceNote = "of the cutting path lies on the surface";

// What a user should know of a map's surface: passes left out or not joined (with their
// lines), and a surface on little of the cutting path, with what may fill it (`remedy`, the
// options or controls that choose the pass pattern and the gap).
std::vector<std::string> surfaceNotes(const Trajectory& samples, const QualityMap& map, const std::string& remedy);

// Throws InputError when the request cannot be met (no feedback, no cutting passes, ...).
QualityMap buildQualityMap(const Trajectory& samples, const Program* program, const QualityMapRequest& request);

// The surface the quality figures of a map's samples are measured on: the map's own when it
// keeps as many samples as kFiguresVertices allows, else its passes meshed again so (a map made
// for a small view keeps fewer).
std::shared_ptr<const SurfaceMesh> figuresMesh(const Trajectory& samples, const QualityMap& map);

// The values a map of this request colours the mesh's vertices by, in the units it shows.
std::vector<float> vertexValuesShown(const QualityMapRequest& request, const Trajectory& samples, const SurfaceMesh& mesh);

// The programmed cutting moves as polylines (arcs sampled within 0.01 mm), rapids left out.
std::vector<std::vector<Vec3>> programPolylines(const Program& program);

}  // namespace isurface::vis
