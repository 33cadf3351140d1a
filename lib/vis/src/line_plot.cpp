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
#include <vtkTable.h>
#include <vtkTextProperty.h>

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

// Distinct on white and in print, in the order the series come.
constexpr unsigned char kColours[][3] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}};

}  // namespace

std::string plotToPng(const LinePlot& plot, int width, int height) {
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(column(plot.xLabel, plot.x));
  for (const PlotSeries& s : plot.series) table->AddColumn(column(s.name, s.y));

  auto chart = vtkSmartPointer<vtkChartXY>::New();
  chart->SetTitle(plot.title);
  chart->GetTitleProperties()->SetFontSize(14);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(plot.xLabel);
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
