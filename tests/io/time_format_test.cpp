// Machining times as people read them: minutes and seconds, hours from an hour on.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/base/time_format.h"

using isurface::formatDuration;

TEST(timeFormat, MinutesUnderAnHourAndHoursFromAnHourOn) {
  EXPECT_EQ(formatDuration(4.541), "0:04.541");
  EXPECT_EQ(formatDuration(3599.9994), "59:59.999");
  EXPECT_EQ(formatDuration(3600), "1:00:00.000");
  EXPECT_EQ(formatDuration(6212.305), "1:43:32.305");  // not 103:32.305
  EXPECT_EQ(formatDuration(std::nan("")), "0:00.000");
  EXPECT_EQ(formatDuration(-3), "0:00.000");
}
