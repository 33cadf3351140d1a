// Each G-code line's time and start from the samples, and finding text in the G-code.
#include <gtest/gtest.h>

#include "isurface/app_model/line_times.h"
#include "isurface/app_model/text_lines.h"
#include "scratch_files.h"

using namespace isurface;
using namespace isurface::app_model;

TEST(lineTimes, EachLinesTimeAddsItsRunsAndStartsAtItsFirst) {
  Trajectory t;
  t.hasLine = true;
  t.cycle = 0.001;
  // Lines 3 (2 samples), 5 (3), 3 again (1), none (1), 7 (1): a loop runs line 3 twice.
  t.line = std::vector<std::uint32_t>{3, 3, 5, 5, 5, 3, 0, 7};
  for (int i = 0; i < 8; ++i) t.x.push_back(i), t.y.push_back(0), t.z.push_back(0);
  t.startTime = 2.0;
  const LineTimes times(t);
  ASSERT_TRUE(times.of(3));
  EXPECT_NEAR(times.of(3)->seconds, 0.003, 1e-12);
  EXPECT_NEAR(times.of(3)->start, 0.0, 1e-12);
  EXPECT_NEAR(times.of(5)->seconds, 0.003, 1e-12);
  EXPECT_NEAR(times.of(5)->start, 0.002, 1e-12);
  EXPECT_NEAR(times.of(7)->seconds, 0.001, 1e-12);  // the last sample: one cycle
  EXPECT_NEAR(times.of(7)->start, 0.007, 1e-12);
  EXPECT_FALSE(times.of(4));
  EXPECT_FALSE(times.of(0));
  EXPECT_FALSE(LineTimes(Trajectory{}).of(3));
}

TEST(findLine, FindsTheNextLineHoldingTheTextRoundPastTheEnds) {
  const std::string path = test::writeScratch("find.nc", "G21\nG1 X1 F100\nG1 x2\n(comment)\nG1 X3\n");
  const TextLines text(path);
  EXPECT_EQ(findLine(text, "g1 x", 0), 2u);
  EXPECT_EQ(findLine(text, "g1 x", 2), 3u);
  EXPECT_EQ(findLine(text, "g1 x", 5), 2u);  // round past the end
  EXPECT_EQ(findLine(text, "g1 x", 2, true), 5u);  // back, round past the top
  EXPECT_EQ(findLine(text, "G21", 1), 1u);  // the only one: found again
  EXPECT_EQ(findLine(text, "M30", 1), std::nullopt);
  EXPECT_EQ(findLine(text, "", 1), std::nullopt);
}
