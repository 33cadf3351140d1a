// isurface-cli locate: samples found by line, index and point in a simulated dump, and the
// motion printed at a sample; the dump read in memory agrees with the trajectory loaded from it.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "isurface/io/biip.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/analysis/kinematics.h"
#include "isurface/analysis/locate.h"
#include "isurface/workflow/locate_in_dump.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

// A small raster program simulated once into the scratch folder.
const std::string& simulatedDump() {
  static const std::string path = [] {
    const std::string program = (scratchDir() / "raster.nc").string();
    std::string text = "G21 G90 G17\nG0 Z5\nG0 X0 Y0\nG1 Z0 F600\n";
    for (int k = 0; k < 6; ++k) {
      if (k > 0) text += "G1 Y" + std::to_string(0.5 * k) + " F2000\n";
      text += std::string("G1 X") + (k % 2 == 0 ? "20" : "0") + " Z" + std::to_string(0.1 * k) + " F2000\n";
    }
    text += "G0 Z5\nM30\n";
    std::ofstream(program) << text;
    const std::string dump = (scratchDir() / "raster.biip").string();
    const CommandResult r = runCli("simulate " + program + " -o " + dump);
    if (r.exitCode != 0) throw std::runtime_error("simulate failed: " + r.err);
    return dump;
  }();
  return path;
}

nlohmann::json locate(const std::string& args) {
  const CommandResult r = runCli("locate " + simulatedDump() + " " + args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(locate, ReaderAndTrajectoryAgree) {
  const BiipReader reader(simulatedDump());
  const Trajectory t = loadTrajectory(reader);
  for (const std::uint32_t line : {4u, 5u, 9u, 14u, 99u}) EXPECT_EQ(firstSampleOfLine(reader, line), firstSampleOfLine(t, line));
  for (const Vec3& p : {Vec3(3, 0.2, 0), Vec3(10, 2.4, 0.3), Vec3(-5, 7, 2)}) EXPECT_EQ(nearestSample(reader, p), nearestSample(t, p));
}

TEST(locate, MotionAtOneSampleIsTheWholeDerivation) {
  const BiipReader reader(simulatedDump());
  const Trajectory t = loadTrajectory(reader);
  const std::size_t n = t.size();
  const Kinematics k = deriveKinematics(t.x.data(), t.y.data(), t.z.data(), nullptr, n, t.cycle, true);
  for (const std::size_t i : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(3), n / 3, n / 2, n - 3, n - 2, n - 1}) {
    for (const SampleMotion& m : {motionAtSample(t, i), motionAtSample(reader, i)}) {
      EXPECT_EQ(m.speed, k.speed[i]) << i;
      EXPECT_EQ(m.accel, k.accel[i]) << i;
      EXPECT_EQ(m.accelMagnitude, k.accelMagnitude[i]) << i;
      EXPECT_EQ(m.jerk, k.jerk[i]) << i;
      for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(m.velocity[a], k.axisVel[a][i]) << i;
        EXPECT_EQ(m.acceleration[a], k.axisAcc[a][i]) << i;
        EXPECT_EQ(m.jerkAxes[a], k.axisJerk[a][i]) << i;
      }
    }
  }
}

TEST(locate, CommandRoundTrip) {
  const Trajectory t = loadTrajectory(BiipReader(simulatedDump()));
  const std::size_t n = t.size();
  for (const std::size_t k : {n / 7, n / 3, n / 2, 2 * n / 3, 6 * n / 7}) {
    const nlohmann::json bySample = locate("--sample " + std::to_string(k));
    EXPECT_EQ(bySample["sample"], k);
    EXPECT_EQ(bySample["file"], simulatedDump());
    const std::uint32_t line = bySample["line"];
    EXPECT_EQ(line, t.line[k]);
    // The first sample of that line: at or before K, on the line, and no earlier one is.
    const nlohmann::json byLine = locate("--line " + std::to_string(line));
    const std::size_t first = byLine["sample"];
    EXPECT_LE(first, k);
    EXPECT_EQ(byLine["line"], line);
    for (std::size_t i = 0; i < first; ++i) ASSERT_NE(t.line[i], line);
    // The nearest sample to a sample's position is that sample.
    const auto& p = bySample["position"];
    char point[128];
    std::snprintf(point, sizeof point, "%.17g,%.17g,%.17g", p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    const nlohmann::json byPoint = locate(std::string("--point ") + point);
    EXPECT_EQ(byPoint["sample"], k);
    EXPECT_DOUBLE_EQ(byPoint["distance_mm"].get<double>(), 0.0);
  }
}

TEST(locate, CommandPrintsTheMotion) {
  const BiipReader reader(simulatedDump());
  const Trajectory t = loadTrajectory(reader);
  const std::size_t k = t.size() / 2;
  const nlohmann::json j = locate("--sample " + std::to_string(k));
  const SampleMotion m = motionAtSample(t, k);
  EXPECT_DOUBLE_EQ(j["speed_mm_min"].get<double>(), 60 * m.speed);  // mm/s inside, mm/min in the report
  EXPECT_DOUBLE_EQ(j["accel_mm_s2"].get<double>(), m.accel);
  EXPECT_DOUBLE_EQ(j["jerk_mm_s3"].get<double>(), m.jerk);
  EXPECT_DOUBLE_EQ(j["velocity_mm_min"][0].get<double>(), 60 * m.velocity.x());
  EXPECT_DOUBLE_EQ(j["acceleration_mm_s2"][2].get<double>(), m.acceleration.z());
  EXPECT_DOUBLE_EQ(j["jerk_axes_mm_s3"][1].get<double>(), m.jerkAxes.y());
  EXPECT_DOUBLE_EQ(j["time_s"].get<double>(), t.timeAt(k));
  EXPECT_DOUBLE_EQ(j["feed_mm_min"].get<double>(), t.feed[k]);
  // The window holds feedback as float offsets from the commanded position (1e-7 of the lag).
  EXPECT_NEAR(j["feedback"][0].get<double>(), t.feedback(k).x(), 1e-9);
  EXPECT_NEAR(j["following_error_um"].get<double>(), 1000.0 * t.feedbackOffset(k).norm(), 1e-6);
  for (const char* key : {"file", "sample", "line", "time_s", "position", "feedback", "feed_mm_min", "speed_mm_min",
                          "accel_mm_s2", "jerk_mm_s3", "velocity_mm_min", "acceleration_mm_s2", "jerk_axes_mm_s3",
                          "following_error_um"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j.contains("distance_mm"));
}

TEST(locate, CommandWithoutFeedbackOrLines) {
  const std::string path = (scratchDir() / "bare.biip").string();
  {
    BiipWriter writer(path, BiipWriter::layout({{"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}}),
                      0.001, "{}");
    for (int i = 0; i < 50; ++i) {
      const double r[3] = {0.05 * i, 0, 0};
      writer.append(r);
    }
    writer.commit();
  }
  const CommandResult r = runCli("locate " + path + " --sample 10");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["feedback"].is_null());
  EXPECT_TRUE(j["line"].is_null());
  EXPECT_TRUE(j["feed_mm_min"].is_null());
  EXPECT_TRUE(j["following_error_um"].is_null());
  EXPECT_NEAR(j["speed_mm_min"].get<double>(), 3000, 1e-6);
  const CommandResult byLine = runCli("locate " + path + " --line 3");
  EXPECT_EQ(byLine.exitCode, 2);
  EXPECT_NE(byLine.err.find("no line channel"), std::string::npos) << byLine.err;
}

TEST(locate, CommandRejectsBadInput) {
  const std::string dump = simulatedDump();
  const struct {
    std::string args, message;
  } cases[] = {
      {"locate " + dump, "exactly one of"},
      {"locate " + dump + " --line 3 --sample 4", "exactly one of"},
      {"locate " + dump + " --point 1,2", "--point needs X,Y,Z"},
      {"locate " + dump + " --point 1,2,zz", "--point needs X,Y,Z"},
      {"locate " + dump + " --point 1,2,3,4", "--point needs X,Y,Z"},
      {"locate " + dump + " --sample 999999999", "out of range"},
      {"locate " + dump + " --sample -1", "out of range"},
      {"locate " + dump + " --line 1", "line 1 produced no samples"},
      {"locate " + dump + " --line 4000", "line 4000 produced no samples"},
      {"locate " + (scratchDir() / "missing.biip").string() + " --sample 0", "cannot read"},
      {"locate " + sourcePath("samples/wuzhishan.nc") + " --sample 0", "not a Biip file"},
      {"locate " + dump + " --line abc", ""},
  };
  for (const auto& c : cases) {
    const CommandResult r = runCli(c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args;
    EXPECT_TRUE(r.out.empty()) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
}

}  // namespace
