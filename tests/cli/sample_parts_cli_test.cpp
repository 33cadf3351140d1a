// isurface-cli sample: an unknown sample name is refused, by the generator and by the command.
#include <gtest/gtest.h>

#include "isurface/gcode/sample_parts.h"
#include "test_support.h"

using namespace isurface;

TEST(SampleParts, UnknownNameIsRefused) {
  EXPECT_THROW(generateSamplePart("no-such-part"), std::invalid_argument);
  const test::CommandResult r = test::runCli("sample no-such-part -o /tmp/never.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unknown sample 'no-such-part'"), std::string::npos);
  EXPECT_FALSE(test::fileExists("/tmp/never.nc"));
}
