#pragma once
// Renders a quality-map scene to a PNG file with no display (OSMesa).
#include <string>

namespace isurface::vis {

class QualityScene;

// Writes the PNG through a temporary file renamed into place. Returns the render time in s.
double renderSceneToPng(QualityScene& scene, int width, int height, const std::string& path);

}  // namespace isurface::vis
