#pragma once
// Renders a quality-map scene to a PNG file with no display (OSMesa).
#include <functional>
#include <string>

class vtkRenderWindow;

namespace isurface::vis {

class QualityScene;

// A PNG of RGB rows, the bottom row first (as OpenGL and VTK hold images), in memory.
std::string pngOfRgb(const unsigned char* rgbBottomFirst, int width, int height);

// An offscreen window of the size (OSMesa), given to `draw` to fill, rendered to PNG bytes.
std::string renderOffscreen(int width, int height, const std::function<void(vtkRenderWindow*)>& draw);

// The scene as PNG bytes.
std::string renderSceneToPngBytes(QualityScene& scene, int width, int height);

// Writes the PNG through a temporary file renamed into place. Returns the render time in s.
double renderSceneToPng(QualityScene& scene, int width, int height, const std::string& path);

}  // namespace isurface::vis
