// What a map says about itself: the colour map chosen for the quantity, the legend's title.
#include <gtest/gtest.h>

#include "isurface/vis/color_map.h"
#include "isurface/vis/quality_map.h"
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
