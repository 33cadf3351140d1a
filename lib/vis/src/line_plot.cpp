#include "isurface/vis/line_plot.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "isurface/vis/offscreen_render.h"

namespace isurface::vis {

namespace {

vtkSmartPointer<vtkDoubleArray> column(const std::string& name, const std::vector<double>& values) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) array->SetValue(static_cast<vtkIdType>(i), values[i]);
  return array;
}

// About five ticks at 1, 2 or 5 times a power of ten over [low, high], placed from `origin` and
// labelled with their own values.
void tickFromOrigin(vtkAxis* axis, double low, double high, double origin) {
  const double span = high - low;
  if (!(span > 0) || !std::isfinite(span)) return;
  const double rough = span / 5, power = std::pow(10.0, std::floor(std::log10(rough)));
  const double step = power * (rough / power < 1.5 ? 1 : rough / power < 3.5 ? 2 : rough / power < 7.5 ? 5 : 10);
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  auto positions = vtkSmartPointer<vtkDoubleArray>::New();
  auto labels = vtkSmartPointer<vtkStringArray>::New();
  for (double tick = std::ceil(low / step) * step; tick <= high + 1e-9 * span; tick += step) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, tick);
    positions->InsertNextValue(tick - origin);
    labels->InsertNextValue(text);
  }
  axis->SetCustomTickPositions(positions, labels);
}

// Distinct on white and in print, in the order the series come.
constexpr unsigned char kColours[][3] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}};

}  // namespace

std::string plotToPng(const LinePlot& plot, int width, int height) {
  // VTK's charts draw in single precision after shifting the data themselves: three seconds of a
  // run 400 s in came out as an empty plot. x is drawn from its first value, and the axis
  // labelled with the values themselves.
  const double origin = plot.x.empty() ? 0.0 : plot.x.front();
  std::vector<double> fromOrigin(plot.x);
  for (double& x : fromOrigin) x -= origin;
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(column(plot.xLabel, fromOrigin));
  for (const PlotSeries& s : plot.series) table->AddColumn(column(s.name, s.y));

  auto chart = vtkSmartPointer<vtkChartXY>::New();
  chart->SetTitle(plot.title);
  chart->GetTitleProperties()->SetFontSize(14);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(plot.xLabel);
  if (origin != 0.0) tickFromOrigin(chart->GetAxis(vtkAxis::BOTTOM), plot.x.front(), plot.x.back(), origin);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(plot.yLabel);
  chart->SetShowLegend(plot.series.size() > 1);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(table, 0, static_cast<vtkIdType>(k + 1));
    const unsigned char* c = kColours[k % (sizeof kColours / sizeof kColours[0])];
    line->SetColor(c[0], c[1], c[2], 255);
    line->SetWidth(1.5f);
  }
  auto scene = vtkSmartPointer<vtkContextScene>::New();
  scene->AddItem(chart);
  auto actor = vtkSmartPointer<vtkContextActor>::New();
  actor->SetScene(scene);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(actor);
  scene->SetRenderer(renderer);
  return renderOffscreen(width, height, [&](vtkRenderWindow* window) { window->AddRenderer(renderer); });
}

}  // namespace isurface::vis
