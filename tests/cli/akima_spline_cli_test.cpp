// isurface-cli fit: the Akima spline through a range of lines, reported as JSON.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace isurface {
namespace {

TEST(akimaSpline, cliFitsALineRange) {
  const std::string path = (test::scratchDir() / "fit.ngc").string();
  std::ofstream(path) << "G21 G90\nG0 X0 Y0 Z0\nG1 X10 F600\nG3 X15 Y5 I0 J5\nG1 Y12\nX14 Y13\nM2\n";
  const test::CommandResult r = test::runCli("fit " + path + " --lines 3-6 --tolerance 0.001");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["segments"].size(), j["points"].get<std::size_t>() - 1);
  EXPECT_GE(j["resampled_points"].get<std::size_t>(), j["points"].get<std::size_t>());
  EXPECT_LE(j["max_point_deviation_mm"].get<double>(), 0.001);
  EXPECT_LE(j["max_join_angle_deg"].get<double>(), 1e-6);
  // 10 mm line + 7.854 mm arc + 7 mm line + 1.414 mm line, as chords.
  EXPECT_NEAR(j["parameter_length_mm"].get<double>(), 10 + 7.854 + 7 + 1.4142, 0.01);
  for (const char* args : {"", "--lines 6-3", "--lines 3-", "--lines 1-2", "--lines 3-6 --tolerance 0"}) {
    const test::CommandResult bad = test::runCli("fit " + path + " " + args);
    EXPECT_NE(bad.exitCode, 0) << args;  // without --lines: CLI11's own usage error
    if (std::string(args).size() > 0) {
      EXPECT_EQ(bad.exitCode, 2) << args;
    }
  }
}

}  // namespace
}  // namespace isurface
