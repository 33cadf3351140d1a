#pragma once
// What a quality map shows and how, without VTK: its surface's vertices and values, the
// programmed path, the glowing samples, the colouring choice and the view. `vis` turns it into a
// scene (quality_scene.h). Units: mm.
#include <optional>
#include <array>
#include <string>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/base/value_range.h"
#include "isurface/surface/surface_mesh.h"

namespace isurface::vis {

enum class ViewDirection { Iso, Top, Front, Left };

std::optional<ViewDirection> parseView(const std::string& name);  // "iso", "top", "front", "left"

struct SurfaceData {
  std::vector<Vec3> positions;   // mesh vertices, mm
  const SurfaceMesh* mesh = nullptr;
  std::vector<float> scalars;    // the coloured quantity, one per vertex
  std::vector<std::vector<Vec3>> toolpath;  // cutting path as polylines, mm
  std::vector<std::vector<float>> toolpathScalars;  // when not empty: a value per toolpath point
  std::vector<Vec3> highlight;   // samples to make glow (a selected line's), mm
  std::vector<std::array<Vec3, 2>> toolAxes;  // a five-axis run's tool axis: strokes from the tip up the tool, mm
  // A coarser surface shown while the camera moves (level of detail); optional.
  std::vector<Vec3> coarsePositions;
  const SurfaceMesh* coarseMesh = nullptr;
  std::vector<float> coarseScalars;
};

struct MapStyle {
  std::string colorMap = "rainbow";
  ValueRange range;              // the colour map's span
  std::string quantityLabel;     // legend title, e.g. "Path speed"
  std::string unit;              // e.g. "mm/min"
  std::string caption;           // top-left text
  ViewDirection view = ViewDirection::Iso;
  bool showToolpath = true;
  bool passWires = true;
  bool showToolAxes = false;     // the tool axis strokes (SurfaceData::toolAxes) shown at first
  int isoBands = 12;             // iso-lines across the range; 0 for none
  int fontSize = 16;             // points of the caption and legend text
};

// A text size that reads well at a given image height (16 at 1000 pixels).
inline int fontSizeForHeight(int height) { return height < 700 ? 12 + height / 250 : 6 + height / 100; }

// "auto": the paper's rainbow, or "coolwarm" (diverging, white at the middle) for values of
// both signs. Any other name is itself.
constexpr const char* kAutoColorMap = "auto";
std::string resolveColorMap(const std::string& name, bool signedValues);

}  // namespace isurface::vis
