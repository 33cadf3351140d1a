// What a map says about itself: the colour map chosen for the quantity, the legend's title.
#include <gtest/gtest.h>
#include <vtkActor2DCollection.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

#include "isurface/vis/color_map.h"
#include "isurface/map/quality_map.h"
#include "isurface/vis/quality_scene.h"
#include "surface_fixtures.h"

using namespace isurface;

TEST(mapStyle, SignedQuantitiesDefaultToADivergingMap) {
  const Trajectory raster = test::zigZagRaster(12, 40.0, 1.0, 50.0);
  vis::QualityMapRequest request;  // colour map "auto"
  request.quantity = Quantity::Speed;
  EXPECT_EQ(vis::buildQualityMap(raster, nullptr, request).style.colorMap, "rainbow");
  for (Quantity q : {Quantity::Acceleration, Quantity::VelocityX, Quantity::AccelerationY}) {
    request.quantity = q;
    EXPECT_EQ(vis::buildQualityMap(raster, nullptr, request).style.colorMap, "coolwarm") << quantityInfo(q).name;
  }
  request.colorMap = "viridis";  // a map the user chose stays
  EXPECT_EQ(vis::buildQualityMap(raster, nullptr, request).style.colorMap, "viridis");
  EXPECT_EQ(vis::resolveColorMap("auto", true), "coolwarm");
  EXPECT_EQ(vis::resolveColorMap("grey", true), "grey");
}

TEST(mapStyle, UnitsAreWrittenAsPeopleWriteThem) {
  EXPECT_STREQ(quantityInfo(Quantity::Deviation).unit, "\u00b5m");
  EXPECT_STREQ(quantityInfo(Quantity::FollowingError).unit, "\u00b5m");
}

TEST(mapStyle, TheDivergingMapAutoChoosesIsCentredOnZero) {
  const Trajectory raster = test::zigZagRaster(12, 40.0, 1.0, 50.0);
  vis::QualityMapRequest request;
  request.quantity = Quantity::Acceleration;
  const vis::QualityMap map = vis::buildQualityMap(raster, nullptr, request);
  EXPECT_DOUBLE_EQ(map.style.range.lo, -map.style.range.hi);
  EXPECT_GT(map.style.range.hi, 0.0);
}

namespace {

vtkTextActor* captionOf(vis::QualityScene& scene) {
  vtkActor2DCollection* actors = scene.renderer()->GetActors2D();
  actors->InitTraversal();
  while (vtkActor2D* a = actors->GetNextActor2D())
    if (auto* text = vtkTextActor::SafeDownCast(a)) return text;
  return nullptr;
}

vtkScalarBarActor* legendOf(vis::QualityScene& scene) {
  vtkActor2DCollection* actors = scene.renderer()->GetActors2D();
  actors->InitTraversal();
  while (vtkActor2D* a = actors->GetNextActor2D())
    if (auto* legend = vtkScalarBarActor::SafeDownCast(a)) return legend;
  return nullptr;
}

}  // namespace

TEST(mapStyle, LegendTitlesGoInLinesOfWordsNotAWordALine) {
  const Trajectory raster = test::zigZagRaster(12, 40.0, 1.0, 50.0);
  vis::QualityMapRequest request;
  request.quantity = Quantity::SpeedInconsistency;
  const vis::QualityMap map = vis::buildQualityMap(raster, nullptr, request);
  vis::QualityScene scene(map.data, map.style);
  ASSERT_NE(legendOf(scene), nullptr);
  EXPECT_STREQ(legendOf(scene)->GetTitle(), "Speed\ninconsistency\nbetween passes\n[mm/min]");
}

TEST(mapStyle, TextInANarrowViewIsMadeToFit) {
  const Trajectory raster = test::zigZagRaster(12, 40.0, 1.0, 50.0);
  vis::QualityMapRequest request;
  request.caption = "machine: a machine whose name is rather long for a narrow view";
  const vis::QualityMap map = vis::buildQualityMap(raster, nullptr, request);
  vis::QualityScene scene(map.data, map.style);
  vtkTextActor* caption = captionOf(scene);
  ASSERT_NE(caption, nullptr);
  scene.fitOverlaysToWidth(1600);
  EXPECT_EQ(caption->GetTextProperty()->GetFontSize(), map.style.fontSize);  // room enough: as styled
  const int wideLegend = legendOf(scene)->GetTitleTextProperty()->GetFontSize();
  scene.fitOverlaysToWidth(300);
  EXPECT_LT(caption->GetTextProperty()->GetFontSize(), map.style.fontSize);
  EXPECT_LT(legendOf(scene)->GetTitleTextProperty()->GetFontSize(), wideLegend);
  // Each caption line now fits: at most 0.8 of 300 pixels at the font's average advance.
  const std::string text = caption->GetInput();
  std::size_t longest = 0, length = 0;
  for (char c : text) length = c == '\n' ? 0 : length + 1, longest = std::max(longest, length);
  EXPECT_LE(static_cast<double>(longest) * 0.56 * caption->GetTextProperty()->GetFontSize(), 0.8 * 300 + 1);
}

TEST(mapStyle, AConstantSpeedIsOneColourWithoutIsoLines) {
  // 12 passes of 40 mm at a constant 600 mm/min: the speeds differ only by rounding.
  const Trajectory raster = test::zigZagRaster(12, 40.0, 1.0, 600.0);
  vis::QualityMapRequest request;
  request.quantity = Quantity::Speed;
  const vis::QualityMap map = vis::buildQualityMap(raster, nullptr, request);
  EXPECT_NEAR(map.style.range.hi - map.style.range.lo, 1.2, 0.01);  // two thousandths of 600
  EXPECT_NEAR(0.5 * (map.style.range.lo + map.style.range.hi), 600.0, 0.05);
  EXPECT_EQ(map.style.isoBands, 0) << map.style.range.lo << " .. " << map.style.range.hi;
  // Speeds that do vary keep their range and their iso-lines.
  const Trajectory wavy = test::zigZagRaster(12, 40.0, 1.0, 600.0, [](double x, double) { return 2.0 * std::sin(x); });
  request.quantity = Quantity::VelocityZ;
  const vis::QualityMap varying = vis::buildQualityMap(wavy, nullptr, request);
  EXPECT_EQ(varying.style.isoBands, request.isoBands);
  EXPECT_GT(varying.style.range.hi - varying.style.range.lo, 10.0);
}
