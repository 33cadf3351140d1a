// Five-axis kinematics: hand-worked poses of each structure, round trips, tool axes and the
// angles that give them, singular orientations, the shortest way of a wrapping axis, and the
// joints LinuxCNC 2.9's xyzbc-trt kinematics commanded in a recording.
#include <gtest/gtest.h>

#include "five_axis_recording.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>

#include "isurface/kinematics/five_axis.h"
#include "test_support.h"

namespace isurface {
namespace {

// LinuxCNC's xyzbc-trt as ../shared/tools/linuxcnc-sim-5axis sets it: C about Z through machine
// zero, carried by B about Y through (-20, 0, -15) mm, tool offset 0.
FiveAxisKinematics linuxcncTrt() {
  FiveAxisKinematics k;
  k.structure = KinematicStructure::TableTable;
  k.rotary[0] = RotaryAxis{'B', Vec3::UnitY(), Vec3(-20, 0, -15), -120, 120};
  k.rotary[1] = RotaryAxis{'C', Vec3::UnitZ(), Vec3::Zero(), -36000, 36000};
  return k;
}

// A head-head machine: C about Z carrying A about X, A turning about a point 50 mm above the
// gauge line, a 100 mm tool.
FiveAxisKinematics headHead() {
  FiveAxisKinematics k;
  k.structure = KinematicStructure::HeadHead;
  k.rotary[0] = RotaryAxis{'C', Vec3::UnitZ(), Vec3::Zero()};
  k.rotary[1] = RotaryAxis{'A', Vec3::UnitX(), Vec3(0, 0, 50)};
  k.toolLength = 100;
  return k;
}

// A head-table machine: B in the head (about Y, 80 mm above the gauge line), C table about Z
// through (100, 50, 0).
FiveAxisKinematics headTable() {
  FiveAxisKinematics k;
  k.structure = KinematicStructure::HeadTable;
  k.rotary[0] = RotaryAxis{'B', Vec3::UnitY(), Vec3(0, 0, 80)};
  k.rotary[1] = RotaryAxis{'C', Vec3::UnitZ(), Vec3(100, 50, 0)};
  k.toolLength = 120;
  return k;
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-9) {
  EXPECT_NEAR((a - b).norm(), 0, tolerance) << "(" << a.transpose() << ") against (" << b.transpose() << ")";
}

TEST(fiveAxisKinematics, HandWorkedPosesOfATableTableMachine) {
  const FiveAxisKinematics k = linuxcncTrt();
  // Both axes at 0: the part's frame is the machine's.
  expectNear(jointsFor(k, {Vec3(12, -7, 3), {0, 0}}).linear, Vec3(12, -7, 3));
  // C +90: the point 10 mm along X of the table turns to +Y.
  expectNear(jointsFor(k, {Vec3(10, 0, 0), {0, 90}}).linear, Vec3(0, 10, 0));
  // B +90 about (-20, 0, -15): the table's origin is 20 mm along X and 15 mm along Z from the
  // pivot; a right-handed quarter turn about Y takes (20, 15) in (x, z) to (15, -20).
  expectNear(jointsFor(k, {Vec3(0, 0, 0), {90, 0}}).linear, Vec3(-5, 0, -35));
  // The tool axis in the part's frame: tilted by -B about Y, then by -C about Z.
  expectNear(toolAxis(k, {90, 0}), Vec3(-1, 0, 0));
  expectNear(toolAxis(k, {90, 90}), Vec3(0, 1, 0));
}

TEST(fiveAxisKinematics, HandWorkedPosesOfHeadMachines) {
  const FiveAxisKinematics hh = headHead();
  // A +90 about X through 50 mm above the gauge line: the tip, 150 mm below that point, swings
  // to +Y... a right-handed quarter turn about X takes -Z to +Y.
  const JointPosition j = jointsFor(hh, {Vec3(0, 0, 0), {0, 90}});
  expectNear(j.linear, Vec3(0, -150, -50));
  expectNear(toolAxis(hh, {0, 90}), Vec3(0, -1, 0));
  expectNear(toolAxis(hh, {90, 90}), Vec3(1, 0, 0));  // C +90 turns -Y to +X
  const FiveAxisKinematics ht = headTable();
  // B +90 in the head turns the tool axis to +X; C +90 of the table turns the part under it.
  expectNear(toolAxis(ht, {90, 0}), Vec3(1, 0, 0));
  expectNear(toolAxis(ht, {90, 90}), Vec3(0, -1, 0));
  // Tip at the C centre, B 0: the gauge line 120 mm above the centre.
  expectNear(jointsFor(ht, {Vec3(100, 50, 0), {0, 37}}).linear, Vec3(100, 50, 120));
}

TEST(fiveAxisKinematics, ForwardUndoesInverseOnEveryStructure) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> length(-200, 200), angle(-170, 170);
  for (const FiveAxisKinematics& k : {linuxcncTrt(), headHead(), headTable()}) {
    for (int n = 0; n < 200; ++n) {
      const TipPose pose{Vec3(length(random), length(random), length(random)), {angle(random), angle(random)}};
      const TipPose back = tipOf(k, jointsFor(k, pose));
      expectNear(back.tip, pose.tip, 1e-9);
      EXPECT_EQ(back.rotary, pose.rotary);
    }
  }
}

TEST(fiveAxisKinematics, TheAnglesOfAToolAxisGiveThatAxis) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-170, 170);
  for (const FiveAxisKinematics& k : {linuxcncTrt(), headHead(), headTable()}) {
    for (int n = 0; n < 200; ++n) {
      const std::array<double, 2> set = {angle(random), angle(random)};
      const Vec3 axis = toolAxis(k, set);
      const auto solutions = rotaryFor(k, axis);
      ASSERT_FALSE(solutions.empty());
      bool same = false;
      for (const auto& s : solutions) {
        expectNear(toolAxis(k, s), axis, 1e-9);
        same |= std::fabs(s[0] - set[0]) < 1e-6 && std::fabs(s[1] - set[1]) < 1e-6;
      }
      EXPECT_TRUE(same) << "the angles set are among the solutions";
    }
  }
  // A table-table B/C machine reaches every tool axis tilted by less than its B range; the
  // vertical axis by B 0 (any C: C loses its effect, 0 is given).
  const auto vertical = rotaryFor(linuxcncTrt(), Vec3(0, 0, 5));
  ASSERT_EQ(vertical.size(), 1u);
  EXPECT_NEAR(vertical[0][0], 0, 1e-9);
  EXPECT_NEAR(vertical[0][1], 0, 1e-9);
  // A tool axis tilted 30 deg from Z towards -X: B 30 with C 0, or B -30 with C 180.
  const auto tilted = rotaryFor(linuxcncTrt(), Vec3(-std::sin(kPi / 6), 0, std::cos(kPi / 6)));
  ASSERT_EQ(tilted.size(), 2u);
  bool plain = false, flipped = false;
  for (const auto& s : tilted) {
    plain |= std::fabs(s[0] - 30) < 1e-9 && std::fabs(s[1]) < 1e-9;
    flipped |= std::fabs(s[0] + 30) < 1e-9 && std::fabs(std::fabs(s[1]) - 180) < 1e-9;
  }
  EXPECT_TRUE(plain && flipped);
}

TEST(fiveAxisKinematics, EverySingularOrientationIsNamed) {
  // Table-table B/C: B 0 puts the tool along C, whatever C is.
  for (const double c : {0.0, 73.0, -150.0}) {
    const auto s = singularityNear(linuxcncTrt(), {0.0, c}, 1.0);
    ASSERT_TRUE(s.has_value()) << c;
    EXPECT_EQ(s->axis, 'C');
    EXPECT_NEAR(s->distance, 0, 1e-6);
    EXPECT_NE(s->description.find("C axis"), std::string::npos);
  }
  const auto near = singularityNear(linuxcncTrt(), {0.5, 10.0}, 1.0);
  ASSERT_TRUE(near.has_value());
  EXPECT_NEAR(near->distance, 0.5, 1e-3);
  EXPECT_FALSE(singularityNear(linuxcncTrt(), {15.0, 10.0}, 1.0).has_value());
  // Head-head C/A: A 0 puts the tool along C.
  const auto head = singularityNear(headHead(), {40.0, 0.0}, 1.0);
  ASSERT_TRUE(head.has_value());
  EXPECT_EQ(head->axis, 'C');
  // Head-table B/C: the tool along C at B 0, and B 180.
  EXPECT_EQ(singularityNear(headTable(), {0.0, 10.0}, 1.0)->axis, 'C');
  EXPECT_EQ(singularityNear(headTable(), {180.0, 10.0}, 1.0)->axis, 'C');
  EXPECT_FALSE(singularityNear(headTable(), {45.0, 10.0}, 1.0).has_value());
}

TEST(fiveAxisKinematics, AWrappingAxisTakesTheShortestWay) {
  EXPECT_DOUBLE_EQ(shortestWay(350, 10), 370);
  EXPECT_DOUBLE_EQ(shortestWay(10, 350), -10);
  EXPECT_DOUBLE_EQ(shortestWay(720, 90), 810);
  EXPECT_DOUBLE_EQ(shortestWay(0, 180), 180);
  EXPECT_DOUBLE_EQ(shortestWay(0, -180), 180);  // a half turn goes positive
  EXPECT_DOUBLE_EQ(shortestWay(-90, 100), -260);
}

// LinuxCNC commands each joint as its kinematics of the axis position two servo cycles before:
// our inverse kinematics of that row gives its joints to the recording's 6 decimals.
TEST(fiveAxisKinematics, TheJointsLinuxCncCommanded) {
  const FiveAxisKinematics k = linuxcncTrt();
  const std::filesystem::path folder = std::filesystem::path(test::sourceDir()) / "tests/data/linuxcnc-2.9-xyzbc-trt";
  std::size_t recordings = 0;
  for (const std::string& name : test::recordingNames(folder)) {
    const std::string path = (folder / (name + ".halsampler.txt.gz")).string();
    ++recordings;
    const std::vector<test::FiveAxisRow> rows = test::readFiveAxisRecording(path);
    ASSERT_GT(rows.size(), 1000u) << path;
    double worstLength = 0, worstAngle = 0;
    for (std::size_t i = 2; i < rows.size(); ++i) {
      const auto& a = rows[i - 2].axes;
      const auto& joints = rows[i].joints;
      const JointPosition j = jointsFor(k, {Vec3(a[0], a[1], a[2]), {a[3], a[4]}});
      for (int c = 0; c < 3; ++c) worstLength = std::max(worstLength, std::fabs(j.linear[c] - joints[std::size_t(c)]));
      worstAngle = std::max({worstAngle, std::fabs(j.rotary[0] - joints[3]), std::fabs(j.rotary[1] - joints[4])});
    }
    EXPECT_LT(worstLength, 0.001) << name;  // mm: the recording's 6 decimals, and its smoothing
    EXPECT_LT(worstAngle, 0.001) << name;   // deg
  }
  EXPECT_GE(recordings, 4u);
}

}  // namespace
}  // namespace isurface
