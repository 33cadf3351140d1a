// The Optimise dialog's model: the region belongs to its program, a box stands for its lines only,
// and the result is offered for saving where the user saves, not in the program's folder.
#include <gtest/gtest.h>

#include "isurface/app_model/optimise_dialog.h"

using namespace isurface;
using namespace isurface::app_model;

TEST(optimiseDialog, TheRegionBelongsToItsProgram) {
  OptimiseDialog d;
  d.forgetTheRegionOfAnotherProgram("/shop/a.nc");
  BoxSelection box;
  box.lines = LineRange{10, 20};
  d.notice = "left over";
  d.hold(box.lines, box);
  EXPECT_EQ(d.first, 10);
  EXPECT_EQ(d.last, 20);
  EXPECT_TRUE(d.boxed());
  EXPECT_EQ(d.notice, "");
  d.last = 21;  // typed over: the box no longer stands for the lines
  EXPECT_FALSE(d.boxed());
  d.forgetTheRegionOfAnotherProgram("/shop/a.nc");  // the same program: kept
  EXPECT_EQ(d.first, 10);
  d.forgetTheRegionOfAnotherProgram("/shop/b.nc");
  EXPECT_EQ(d.first, 1);
  EXPECT_EQ(d.last, 1);
  EXPECT_FALSE(d.box);
}

TEST(optimiseDialog, SaysWhyTheLinesCannotBeOptimised) {
  OptimiseDialog d;
  EXPECT_EQ(d.rangeProblem(), "");
  d.first = 0;
  EXPECT_EQ(d.rangeProblem(), "the first line is line 1 or after");
  d.first = 5;
  d.last = 4;
  EXPECT_EQ(d.rangeProblem(), "the last line is before the first: no lines to optimise");
}

TEST(optimiseDialog, OffersToSaveWhereTheUserSavesNotInTheProgramsFolder) {
  OptimiseDialog d;
  d.offerSavePath("/mnt/cam-server/jobs/part.v2.nc", "");
  EXPECT_EQ(d.savePath, "./part.v2-optimized.nc");
  d.offerSavePath("/mnt/cam-server/jobs/part.v2.nc", "/home/me/out");
  EXPECT_EQ(d.savePath, "/home/me/out/part.v2-optimized.nc");  // not typed over: a new offer
  d.savePath = "/home/me/keep.nc";
  d.offerSavePath("/mnt/cam-server/jobs/part.v2.nc", "/home/me/out");
  EXPECT_EQ(d.savePath, "/home/me/keep.nc");  // typed for this program: kept
  d.offerSavePath("/mnt/cam-server/jobs/other.nc", "/home/me/out");
  EXPECT_EQ(d.savePath, "/home/me/out/other-optimized.nc");  // another program: offered anew
}
