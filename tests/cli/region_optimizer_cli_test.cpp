// isurface-cli optimize: the re-optimised program and its comparison report, bad ranges refused,
// and --auto on the transition sample meeting the paper's acceptance.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_support.h"

using namespace isurface::test;

TEST(regionOptimizer, CommandWritesTheProgramAndTheComparison) {
  const std::string out = (scratchDir() / "optimized.nc").string(), report = (scratchDir() / "cmp.json").string();
  const CommandResult r = runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 105-400 -o " +
                                 out + " --report " + report);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json cmp = nlohmann::json::parse(readFile(report));
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
  EXPECT_GE(cmp["passes"].size(), 3u);
  for (const char* key : {"speed_fluctuation_mm_min", "max_speed_inconsistency_mm_min", "max_jerk_mm_s3", "time_s"})
    EXPECT_TRUE(cmp["region"]["after"].contains(key)) << key;
  EXPECT_EQ(runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 9-1 -o " + out).exitCode, 2);
  EXPECT_EQ(runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --lines 1-5 --auto -o " + out).exitCode, 2);
}

// The acceptance of the paper's loop on the bundled transition sample: in the worst region the
// analysis finds, the speed fluctuation and the largest speed difference between neighbouring
// passes fall by at least half, the machining time does not grow, and the new path stays within
// 0.01 mm of the old one.
TEST(regionOptimizer, AutoOnTheTransitionSampleHalvesFluctuationAndInconsistency) {
  const std::string out = (scratchDir() / "transition-auto.nc").string(), report = (scratchDir() / "auto.json").string();
  const CommandResult r =
      runCli("optimize " + sourcePath("samples/transition-surface.nc") + " --auto -o " + out + " --report " + report);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json cmp = nlohmann::json::parse(readFile(report));
  const nlohmann::json& before = cmp["region"]["before"];
  const nlohmann::json& after = cmp["region"]["after"];
  EXPECT_GT(before["samples"].get<double>(), 1000);
  EXPECT_GT(after["samples"].get<double>(), 1000);
  EXPECT_LE(after["speed_fluctuation_mm_min"].get<double>(), 0.5 * before["speed_fluctuation_mm_min"].get<double>());
  EXPECT_LE(after["max_speed_inconsistency_mm_min"].get<double>(),
            0.5 * before["max_speed_inconsistency_mm_min"].get<double>());
  EXPECT_LE(cmp["machining_time_s"]["after"].get<double>(), cmp["machining_time_s"]["before"].get<double>());
  EXPECT_LT(cmp["max_path_distance_mm"].get<double>(), 0.01);
  // The region is inside the passes (the transition), not where they start and end.
  EXPECT_GT(cmp["compared_box_mm"]["min"][0].get<double>(), 5.0);
  EXPECT_LT(cmp["compared_box_mm"]["max"][0].get<double>(), 75.0);
}
