// The Locate window's model: it opens at the selection, goes to a sample, a line or the sample
// nearest a point, and says why a request went nowhere.
#include <gtest/gtest.h>

#include "isurface/app_model/locate_window.h"

using namespace isurface;
using namespace isurface::app_model;

namespace {

// Samples along X at x = index mm, lines 3, 3, 5, 5, 7.
Trajectory fiveSamples() {
  Trajectory t;
  t.hasLine = true;
  t.line = std::vector<std::uint32_t>{3, 3, 5, 5, 7};
  for (int i = 0; i < 5; ++i) {
    t.time.push_back(0.001 * i);
    t.x.push_back(i);
    t.y.push_back(0);
    t.z.push_back(0);
  }
  return t;
}

}  // namespace

TEST(locateWindow, OpensAtTheSelection) {
  const Trajectory t = fiveSamples();
  SelectionModel selection;
  selection.setTrajectory(&t);
  selection.selectSample(3);
  LocateWindow w;
  w.message = "left over";
  w.show(selection);
  EXPECT_TRUE(w.open && w.opening);
  EXPECT_EQ(w.sample, 3);
  EXPECT_EQ(w.line, 5);
  EXPECT_EQ(w.point, Vec3(3, 0, 0));
  EXPECT_EQ(w.message, "");
}

TEST(locateWindow, GoesToASampleALineOrAPoint) {
  const Trajectory t = fiveSamples();
  SelectionModel selection;
  selection.setTrajectory(&t);
  LocateWindow w;
  w.sample = 2;
  w.goToSample(selection);
  EXPECT_EQ(selection.current().sample, 2u);
  w.line = 7;
  w.goToLine(selection, 10);
  EXPECT_EQ(selection.current().sample, 4u);
  w.point = Vec3(1.0004, 0, 0);
  w.goToPoint(selection);
  EXPECT_EQ(selection.current().sample, 1u);
  EXPECT_EQ(w.message, "");  // on the point
  w.point = Vec3(1, 2, 0);
  w.goToPoint(selection);
  EXPECT_EQ(selection.current().sample, 1u);
  EXPECT_EQ(w.message, "the nearest sample, 1, is 2 mm from the point");
}

TEST(locateWindow, SaysWhyARequestWentNowhere) {
  const Trajectory t = fiveSamples();
  SelectionModel selection;
  LocateWindow w;
  w.goToSample(selection);
  EXPECT_EQ(w.message, "no samples: simulate or open a dump");
  w.goToPoint(selection);
  EXPECT_EQ(w.message, "no samples with a position: simulate or open a dump");
  selection.setTrajectory(&t);
  w.sample = 5;
  w.goToSample(selection);
  EXPECT_EQ(w.message, "sample 5 is out of range: 0 .. 4");
  w.line = 0;
  w.goToLine(selection, 10);
  EXPECT_EQ(w.message, "line 0 is out of range: 1 .. 10");
  w.line = 4;
  w.goToLine(selection, 10);
  EXPECT_EQ(w.message, "line 4 produced no samples");
  w.goToLine(selection, 0);
  EXPECT_EQ(w.message, "no program");
  w.point = Vec3(std::nan(""), 0, 0);
  w.goToPoint(selection);
  EXPECT_EQ(w.message, "the point must have finite X, Y and Z");
  EXPECT_FALSE(selection.current().sample);
}
