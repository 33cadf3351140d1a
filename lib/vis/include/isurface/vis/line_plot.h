#pragma once
// Line plots of sampled quantities against time, drawn by VTK's charts offscreen: the speed and
// the acceleration over a region of a report.
#include <string>
#include <vector>

namespace isurface::vis {

struct PlotSeries {
  std::string name;       // in the legend, with its unit
  std::vector<double> y;  // one value a point of LinePlot::x (NaN leaves a gap)
};

struct LinePlot {
  std::string title, xLabel, yLabel;
  std::vector<double> x;  // ascending
  std::vector<PlotSeries> series;
};

// The plot as PNG bytes of the size in pixels.
std::string plotToPng(const LinePlot& plot, int width, int height);

}  // namespace isurface::vis
