// Loading samples from Biip dumps and from simulations into channel arrays.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "isurface/io/biip.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/interpolator.h"
#include "isurface/nc/simulator.h"
#include "isurface/base/trajectory.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/io/trajectory_writing.h"
#include "isurface/nc/sample_trajectory.h"
#include "test_support.h"

using namespace isurface;
using isurface::test::scratchDir;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Writes a dump whose channel i of record r holds value(name, r).
std::string writeDump(const std::string& name, const std::vector<std::pair<std::string, BiipType>>& channels,
                      std::size_t records, const std::function<double(const std::string&, std::size_t)>& value,
                      const std::string& metadata = "{}", double cycle = 0.002, double t0 = 1.5) {
  const std::string path = (scratchDir() / name).string();
  BiipWriter writer(path, BiipWriter::layout(channels), cycle, metadata, t0);
  std::vector<unsigned char> record(writer.recordBytes());
  for (std::size_t r = 0; r < records; ++r) {
    std::fill(record.begin(), record.end(), 0);
    for (const BiipChannel& c : writer.channels()) biipStore(record.data(), c, value(c.name, r));
    writer.append(record.data());
  }
  writer.commit();
  return path;
}

TEST(trajectory, LoadsEveryChannel) {
  const std::size_t n = 2500;
  const auto value = [](const std::string& name, std::size_t r) -> double {
    const double i = double(r);
    if (name == "line") return 10 + r / 100;
    if (name == "block") return r / 50;
    if (name == "x") return i * 0.01;
    if (name == "y") return -i * 0.02;
    if (name == "z") return std::sin(i);
    if (name == "fb_x") return i * 0.01 - 0.001;
    if (name == "fb_y") return -i * 0.02 + 0.001;
    if (name == "fb_z") return std::sin(i) + 0.0005;
    if (name == "feed") return 3000;
    if (name == "spindle") return 12000 + i;
    return 0;
  };
  const std::string path = writeDump("all.biip",
                                     {{"line", BiipType::U32}, {"block", BiipType::U32}, {"x", BiipType::F64},
                                      {"y", BiipType::F64}, {"z", BiipType::F64}, {"fb_x", BiipType::F64},
                                      {"fb_y", BiipType::F64}, {"fb_z", BiipType::F64}, {"feed", BiipType::F64},
                                      {"spindle", BiipType::F32}},
                                     n, value, R"({"machine": {"rapid_mm_min": 24000}})");
  const BiipReader reader(path);
  const Trajectory t = loadTrajectory(reader);
  EXPECT_EQ(t.source, path);
  EXPECT_DOUBLE_EQ(t.cycle, 0.002);
  ASSERT_EQ(t.size(), n);
  EXPECT_TRUE(t.hasLine);
  EXPECT_TRUE(t.hasFeedback());
  EXPECT_TRUE(t.hasFeed());
  EXPECT_FALSE(t.irregularTime);
  EXPECT_TRUE(t.time.empty()) << "a dump without a t channel keeps no times: the cycle gives them";
  EXPECT_DOUBLE_EQ(t.rapidFeed, 24000);
  ASSERT_EQ(t.block.size(), n);
  ASSERT_EQ(t.extra.size(), 1u);
  EXPECT_EQ(t.extra[0].first, "spindle");
  ASSERT_NE(t.extraChannel("spindle"), nullptr);
  EXPECT_EQ(t.extraChannel("nope"), nullptr);
  for (std::size_t r = 0; r < n; r += 7) {
    EXPECT_EQ(t.line[r], 10 + r / 100);
    EXPECT_EQ(t.block[r], r / 50);
    EXPECT_DOUBLE_EQ(t.timeAt(r), 1.5 + 0.002 * double(r));
    EXPECT_DOUBLE_EQ(t.x[r], value("x", r));
    EXPECT_DOUBLE_EQ(t.y[r], value("y", r));
    EXPECT_DOUBLE_EQ(t.z[r], value("z", r));
    // Feedback is held as a float offset from the commanded position: to 1e-7 of the lag.
    EXPECT_NEAR(t.feedback(r).x(), value("fb_x", r), 1e-10);
    EXPECT_NEAR(t.feedback(r).z(), value("fb_z", r), 1e-10);
    EXPECT_DOUBLE_EQ(t.feed[r], 3000);
    EXPECT_FLOAT_EQ(static_cast<float>(t.extra[0].second[r]), static_cast<float>(value("spindle", r)));
  }
}

TEST(trajectory, MinimalDumpAndPartialFeedback) {
  // Only x, y, z and one feedback axis: no feedback, no lines; fb_x kept as an extra channel.
  const std::string path = writeDump(
      "minimal.biip", {{"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}, {"fb_x", BiipType::F64}}, 10,
      [](const std::string& name, std::size_t r) { return name == "fb_x" ? 5.0 : double(r); });
  const Trajectory t = loadTrajectory(BiipReader(path));
  ASSERT_EQ(t.size(), 10u);
  EXPECT_FALSE(t.hasLine);
  EXPECT_FALSE(t.hasFeedback());
  EXPECT_FALSE(t.hasFeed());
  EXPECT_TRUE(t.block.empty());
  EXPECT_DOUBLE_EQ(t.rapidFeed, 0);
  ASSERT_EQ(t.line.size(), 10u);
  for (const std::uint32_t l : t.line.toVector()) EXPECT_EQ(l, 0u);
  ASSERT_NE(t.extraChannel("fb_x"), nullptr);
  EXPECT_DOUBLE_EQ((*t.extraChannel("fb_x"))[3], 5.0);
}

TEST(trajectory, TimeChannelAndIrregularSampling) {
  const std::string regular = writeDump(
      "regular.biip", {{"t", BiipType::F64}, {"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}}, 100,
      [](const std::string& name, std::size_t r) { return name == "t" ? 0.002 * double(r) : 0.0; });
  const Trajectory a = loadTrajectory(BiipReader(regular));
  EXPECT_FALSE(a.irregularTime);
  EXPECT_DOUBLE_EQ(a.timeAt(10), 0.02);
  EXPECT_TRUE(a.extra.empty());  // `t` is the time, not an extra channel

  const std::string jittered = writeDump(
      "jittered.biip", {{"t", BiipType::F64}, {"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}}, 100,
      [](const std::string& name, std::size_t r) {
        return name == "t" ? 0.002 * double(r) + (r % 3 == 0 ? 0.0003 : 0.0) : 0.0;
      });
  const Trajectory b = loadTrajectory(BiipReader(jittered));
  EXPECT_TRUE(b.irregularTime);
  EXPECT_DOUBLE_EQ(b.timeAt(3), 0.0063);
}

TEST(trajectory, NonFiniteSamplesAreKept) {
  const std::string path = writeDump(
      "nan.biip", {{"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}}, 20,
      [](const std::string& name, std::size_t r) { return r == 7 && name == "y" ? kNaN : double(r); });
  const Trajectory t = loadTrajectory(BiipReader(path));
  ASSERT_EQ(t.size(), 20u);
  EXPECT_TRUE(std::isnan(t.y[7]));
  EXPECT_DOUBLE_EQ(t.y[8], 8.0);
}

TEST(trajectory, ProgressIsReportedAsRecordsAreCopied) {
  const std::size_t n = 2'500'000;
  const std::string path = writeDump("large.biip", {{"x", BiipType::F32}, {"y", BiipType::F32}, {"z", BiipType::F32}},
                                     n, [](const std::string&, std::size_t r) { return double(r % 1000); });
  std::vector<double> reports;
  const Trajectory t = loadTrajectory(BiipReader(path), [&](double f) { reports.push_back(f); });
  ASSERT_EQ(t.size(), n);
  EXPECT_DOUBLE_EQ(t.x[n - 1], double((n - 1) % 1000));
  // About every million records, then the end.
  ASSERT_GE(reports.size(), 3u);
  EXPECT_LE(reports.size(), 4u);
  EXPECT_DOUBLE_EQ(reports.back(), 1.0);
  for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GE(reports[i], reports[i - 1]);
}

TEST(trajectory, FromSimulationSamples) {
  std::vector<SimSample> samples(5);
  for (std::size_t i = 0; i < samples.size(); ++i)
    samples[i] = SimSample{std::uint32_t(3 + i), std::uint32_t(i / 2), double(i), 2.0 * double(i), -1.0, double(i) - 0.1,
                           2.0 * double(i), -1.0, 1500};
  const Trajectory t = trajectoryFromSamples(samples, 0.004, "sim.nc");
  EXPECT_EQ(t.source, "sim.nc");
  EXPECT_DOUBLE_EQ(t.cycle, 0.004);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_TRUE(t.hasLine);
  EXPECT_TRUE(t.hasFeedback());
  EXPECT_EQ(t.line[4], 7u);
  EXPECT_EQ(t.block[3], 1u);
  EXPECT_DOUBLE_EQ(t.timeAt(4), 0.016);
  EXPECT_NEAR(t.feedback(2).x(), 1.9, 1e-7);
  EXPECT_DOUBLE_EQ(t.feed[0], 1500);
  EXPECT_EQ(t.commanded(2), Vec3(2, 4, -1));
}

// Without feedback the servo is not simulated, and the commanded samples are the same.
TEST(trajectory, ASimulationWithoutFeedbackCommandsTheSame) {
  const InterpretResult program = interpretGcode("G21 G90 G64\nG1 X10 Y2 F1200\nG2 X20 Y2 R5\nG1 Z-1\n", "sim.nc");
  ASSERT_TRUE(program.ok());
  const Machine machine = defaultMachine();
  TrajectorySink withServo(machine.cycle, "sim.nc", true), without(machine.cycle, "sim.nc", false);
  simulate(program.program, machine, withServo);
  simulate(program.program, machine, without);
  const Trajectory a = withServo.take(), b = without.take();
  EXPECT_TRUE(a.hasFeedback());
  EXPECT_FALSE(b.hasFeedback());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.line, b.line);
  EXPECT_EQ(a.feed, b.feed);
}

TEST(trajectory, RapidRateFromMetadata) {
  EXPECT_DOUBLE_EQ(rapidFeedFromMetadata(R"({"machine": {"rapid_mm_min": 30000}})"), 30000);
  EXPECT_DOUBLE_EQ(rapidFeedFromMetadata(R"({"machine": {}})"), 0);
  EXPECT_DOUBLE_EQ(rapidFeedFromMetadata("not json"), 0);
  EXPECT_DOUBLE_EQ(rapidFeedFromMetadata(""), 0);
  EXPECT_DOUBLE_EQ(rapidFeedFromMetadata(R"({"machine": {"rapid_mm_min": -5}})"), 0);
}

TEST(trajectory, IrregularTimeCheck) {
  const std::vector<double> regular = {0, 0.001, 0.002, 0.003};
  const std::vector<double> late = {0, 0.001, 0.0025, 0.003};
  EXPECT_FALSE(timeIsIrregular(regular.data(), regular.size(), 0.001));
  EXPECT_TRUE(timeIsIrregular(late.data(), late.size(), 0.001));
  EXPECT_FALSE(timeIsIrregular(nullptr, 0, 0.001));
}

// Written back, regular samples take their start and cycle to the header (no t channel), and
// recorded times stay as they were.
TEST(trajectory, WrittenTimesReadBackTheSame) {
  Trajectory regular;
  regular.cycle = 0.004;
  regular.startTime = 2.5;
  for (int i = 0; i < 5; ++i) regular.x.push_back(i), regular.y.push_back(0), regular.z.push_back(0), regular.line.push_back(1);
  Trajectory recorded = regular;
  recorded.time = {0, 0.004, 0.009, 0.012, 0.016};
  for (const Trajectory* written : {&regular, &recorded}) {
    const std::string path = (scratchDir() / "written-times.biip").string();
    writeTrajectoryBiip(*written, path);
    const BiipReader reader(path);
    EXPECT_EQ(reader.hasChannel("t"), !written->time.empty());
    const Trajectory back = loadTrajectory(reader);
    ASSERT_EQ(back.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(back.timeAt(i), written->timeAt(i));
  }
  EXPECT_DOUBLE_EQ(regular.timeAt(4), 2.516);
}

}  // namespace
