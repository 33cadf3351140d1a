// Choosing the lines to re-optimise by a rectangle over the view.
#include <gtest/gtest.h>

#include <algorithm>

#include "isurface/app_model/box_selection.h"

using namespace isurface;
using namespace isurface::app_model;

namespace {

// A raster seen from the top in a 200 x 100 pixel view spanning X 0..100 and Y 0..50 mm: a
// point appears at (2x, 100 - 2y) pixels. Passes along X at Y = 0, 5, ..., 45 mm, one G-code
// line per pass (line 10 + pass), samples every 1 mm; between passes a rapid (line 100 + pass)
// jumping across the whole part, which is not part of the surface.
struct Raster {
  Trajectory samples;
  PassSet surface;
};

Raster raster() {
  Raster r;
  Trajectory& t = r.samples;
  t.hasLine = true;
  auto add = [&](double x, double y, std::uint32_t line, bool onSurface) {
    if (onSurface && (r.surface.passes.empty() || r.surface.passes.back().end != t.size()))
      r.surface.passes.push_back(Pass{t.size(), t.size()});
    if (onSurface) ++r.surface.passes.back().end;
    t.time.push_back(0.001 * static_cast<double>(t.size()));
    t.x.push_back(x), t.y.push_back(y), t.z.push_back(0), t.line.push_back(line);
  };
  for (std::uint32_t pass = 0; pass < 10; ++pass) {
    for (int x = 0; x <= 100; ++x) add(pass % 2 ? 100 - x : x, 5.0 * pass, 10 + pass, true);
    for (int x = 0; x <= 100; x += 10) add(x, 5.0 * pass + 2.5, 100 + pass, false);
  }
  return r;
}

ScreenProjection topView() {
  ScreenProjection p;
  p.width = 200, p.height = 100;
  p.worldToDevice.setIdentity();
  p.worldToDevice(0, 0) = 1.0 / 50, p.worldToDevice(0, 3) = -1;  // x 0..100 -> -1..1
  p.worldToDevice(1, 1) = 1.0 / 25, p.worldToDevice(1, 3) = -1;  // y 0..50 -> -1..1
  return p;
}

}  // namespace

TEST(boxSelection, ProjectionPutsPointsWhereTheViewShowsThem) {
  const ScreenProjection p = topView();
  const auto corner = p(Vec3(0, 0, 0));
  ASSERT_TRUE(corner);
  EXPECT_DOUBLE_EQ(corner->first, 0);
  EXPECT_DOUBLE_EQ(corner->second, 100);  // the bottom-left corner: y grows downwards
  const auto centre = p(Vec3(50, 25, 7));
  EXPECT_DOUBLE_EQ(centre->first, 100);
  EXPECT_DOUBLE_EQ(centre->second, 50);
  // Behind the camera (w <= 0): nowhere on the screen.
  ScreenProjection behind = p;
  behind.worldToDevice(3, 3) = -1;
  EXPECT_FALSE(behind(Vec3(50, 25, 0)));
}

TEST(boxSelection, RectangleGivesThePassesInsideAndTheirExtent) {
  const Raster r = raster();
  // X 20..40 mm, Y 8..22 mm: the passes at Y 10, 15, 20 (lines 12-14); the rapids between
  // them cross the rectangle but are no surface.
  const ScreenRectangle rectangle{80, 56, 40, 84};  // corners in either order
  const auto s = selectInRectangle(r.samples, r.surface, topView(), rectangle);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->lines.first, 12u);
  EXPECT_EQ(s->lines.last, 14u);
  EXPECT_EQ(s->samples, 3u * 21u);
  EXPECT_DOUBLE_EQ(s->lower.x(), 20);
  EXPECT_DOUBLE_EQ(s->upper.x(), 40);
  EXPECT_DOUBLE_EQ(s->lower.y(), 10);
  EXPECT_DOUBLE_EQ(s->upper.y(), 20);
}

TEST(boxSelection, EmptyRectangleOrNoSurfaceSelectsNothing) {
  const Raster r = raster();
  // Between two passes (Y 11..14 mm): only rapids there.
  EXPECT_FALSE(selectInRectangle(r.samples, r.surface, topView(), ScreenRectangle{0, 72, 200, 78}));
  // Beside the part.
  EXPECT_FALSE(selectInRectangle(r.samples, r.surface, topView(), ScreenRectangle{-50, 0, -10, 100}));
  EXPECT_FALSE(selectInRectangle(r.samples, PassSet{}, topView(), ScreenRectangle{0, 0, 200, 100}));
  // Samples without a line, or indices past the samples, are passed over.
  Raster unknown = raster();
  unknown.samples.line.assign(unknown.samples.size(), 0u);
  EXPECT_FALSE(selectInRectangle(unknown.samples, unknown.surface, topView(), ScreenRectangle{0, 0, 200, 100}));
  const PassSet beyondTheSamples{PathPattern::NoBoundary, {Pass{999999, 1000000}}};
  EXPECT_FALSE(selectInRectangle(r.samples, beyondTheSamples, topView(), ScreenRectangle{0, 0, 200, 100}));
}

TEST(boxSelection, WholeViewSelectsEveryPass) {
  const Raster r = raster();
  const auto s = selectInRectangle(r.samples, r.surface, topView(), ScreenRectangle{0, 0, 200, 100});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->lines.first, 10u);
  EXPECT_EQ(s->lines.last, 19u);
  EXPECT_EQ(s->samples, 10u * 101u);  // every sample of the ten passes
}
