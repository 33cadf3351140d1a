// The numbers the window shows beside a curve or a picked sample.
#include "isurface/app_model/readable_value.h"

#include <gtest/gtest.h>

#include <limits>

using isurface::app_model::readableValue;

TEST(readableValue, DifferencingNoiseReadsAsZero) {
  // An acceleration on a straight, left by differencing positions, read to 0.01 mm/s^2.
  EXPECT_EQ(readableValue(1.3e-12, 0.01), "0");
  EXPECT_EQ(readableValue(-4e-3, 0.01), "0");
  EXPECT_EQ(readableValue(0.02, 0.01), "0.02");
}

TEST(readableValue, SmallValuesWithoutAResolutionKeepTheirDigits) {
  // A following error in mm is small and means something.
  EXPECT_EQ(readableValue(0.00012345), "0.00012345");
  EXPECT_EQ(readableValue(0.0), "0");
}

TEST(readableValue, LargeValuesHaveNoExponent) {
  EXPECT_EQ(readableValue(2500.0), "2500");
  EXPECT_EQ(readableValue(12345.67), "12346");
  EXPECT_EQ(readableValue(153456.2), "153456");
  EXPECT_EQ(readableValue(-60144.0, 1.0), "-60144");
}

TEST(readableValue, NotANumberIsADash) {
  EXPECT_EQ(readableValue(std::numeric_limits<double>::quiet_NaN()), "-");
  EXPECT_EQ(readableValue(std::numeric_limits<double>::infinity()), "-");
}
