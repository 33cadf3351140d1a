// Five-axis motion on the linuxcnc-2.9 control, worked by hand: inverse-time feeds, the shortest
// way of a wrapping axis, a rotary axis's range, tool-centre-point control on and off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/simulator.h"
#include "test_locations.h"

namespace isurface {
namespace {

Machine trtMachine() { return loadMachine(std::string(test::sourceDir()) + "/resources/machines/linuxcnc-xyzbc-trt.json"); }

Trajectory run(const std::string& gcode, const Machine& machine) {
  const InterpretResult read = interpretGcode(gcode, "hand.ngc");
  EXPECT_TRUE(read.ok());
  TrajectorySink sink(machine.cycle, "hand.ngc", false);
  sink.keepJointsOf(*machine.kinematics);
  simulate(read.program, machine, sink);
  return sink.take();
}

// s during which the samples of `line` move (the tip or the rotary axes).
double secondsOfLine(const Trajectory& t, unsigned line) {
  const std::vector<double>* b = t.extraChannel("b");
  const std::vector<double>* c = t.extraChannel("c");
  std::size_t cycles = 0;
  for (std::size_t i = 1; i < t.size(); ++i)
    cycles += t.line[i] == line && (t.commanded(i) != t.commanded(i - 1) || (*b)[i] != (*b)[i - 1] || (*c)[i] != (*c)[i - 1]);
  return double(cycles) * t.cycle;
}

const std::vector<double>& channel(const Trajectory& t, const char* name) {
  const std::vector<double>* c = t.extraChannel(name);
  if (!c) throw std::runtime_error(std::string("no channel ") + name);
  return *c;
}

// G93: F moves per minute. A turn of C alone by 90 deg at F2 takes half a minute (the feed is
// along A B C, 180 deg/min); a move of X by 10 mm with C by 45 deg at F6 takes 10 s.
TEST(fiveAxisMotion, InverseTimeFeedsTakeTheTimeTheyAskFor) {
  const Trajectory t = run("G21 G90 G94 G64\nG0 X0 Y0 Z0\nG93 G1 C90 F2\nG1 X10 C135 F6\nG94\nM2\n", trtMachine());
  EXPECT_NEAR(secondsOfLine(t, 3), 30.0, 0.02);
  EXPECT_NEAR(secondsOfLine(t, 4), 10.0, 0.02);
  EXPECT_NEAR(channel(t, "c").back(), 135.0, 1e-9);
}

// An endless C table reaches C10 from C340 by turning +30 deg, not -330 (and C340 from C170 by
// +170); an axis with an end turns the whole way.
TEST(fiveAxisMotion, AWrappingAxisTurnsTheShortestWay) {
  Machine endless = trtMachine();
  endless.kinematics->rotary[1].wraps = true;
  const std::string program = "G21 G90 G94 G64\nG0 X0 Y0 Z0\nG0 C170\nG0 C340\nG1 C10 F3600\nM2\n";
  const Trajectory shortWay = run(program, endless);
  const std::vector<double>& c = channel(shortWay, "c");
  for (std::size_t i = 1; i < c.size(); ++i) ASSERT_GE(c[i], c[i - 1] - 1e-9) << i;
  EXPECT_NEAR(c.back(), 370.0, 1e-9);
  // 60 deg/s, and the ramps add 60 / 450 s: under G64 LinuxCNC keeps half of the 900 deg/s^2
  // for a parabolic blend with the next move.
  EXPECT_NEAR(secondsOfLine(shortWay, 5), 30.0 / 60.0 + 60.0 / 450.0, 0.002);
  const Trajectory longWay = run(program, trtMachine());
  EXPECT_NEAR(channel(longWay, "c").back(), 10.0, 1e-9);
  EXPECT_NEAR(secondsOfLine(longWay, 5), 330.0 / 60.0 + 60.0 / 450.0, 0.002);
}

// B past its range (+-120 deg) is refused with the line, before any motion is made.
TEST(fiveAxisMotion, ARotaryAxisPastItsRangeIsRefusedWithItsLine) {
  const InterpretResult read = interpretGcode("G21 G90\nG0 X0 Y0 Z0\nG1 B130 F1000\nM2\n", "range.ngc");
  ASSERT_TRUE(read.ok());
  const Machine machine = trtMachine();
  TrajectorySink sink(machine.cycle, "range.ngc", false);
  sink.keepJointsOf(*machine.kinematics);
  try {
    simulate(read.program, machine, sink);
    FAIL() << "B130 was simulated";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().line, 3u);
    EXPECT_NE(std::string(e.what()).find("B 130 deg is past the machine's range of B (-120 to 120 deg)"),
              std::string::npos)
        << e.what();
  }
}

// With tool-centre-point control the tip stays at X10 while C turns half a revolution: the
// machine's X joint carries the table's point round to X -10 and back, the tip never moves.
// Without it, X Y Z are the joints: X stays at 10 and the tip (the part's point under the tool)
// turns with the table to X -10 in the part's frame.
TEST(fiveAxisMotion, ToolCentrePointControlOnAndOff) {
  const std::string program = "G21 G90 G94 G64\nG0 X10 Y0 Z0\nG1 C180 F3600\nM2\n";
  const Trajectory on = run(program, trtMachine());
  for (std::size_t i = 0; i < on.size(); ++i)
    if (on.line[i] >= 3) ASSERT_NEAR(on.x[i], 10.0, 1e-9) << i;
  EXPECT_NEAR(channel(on, "joint_x").back(), -10.0, 1e-9);
  EXPECT_NEAR(channel(on, "joint_y").back(), 0.0, 1e-9);
  EXPECT_NEAR(secondsOfLine(on, 3), 3.0 + 60.0 / 450.0, 0.002);  // 60 deg/s: the feed is along C alone

  Machine off = trtMachine();
  off.kinematics->toolCentrePoint = false;
  const Trajectory without = run(program, off);
  const std::vector<double>& jointX = channel(without, "joint_x");
  for (std::size_t i = 0; i < jointX.size(); ++i)
    if (without.line[i] >= 3) ASSERT_NEAR(jointX[i], 10.0, 1e-9) << i;
  EXPECT_NEAR(without.x.back(), -10.0, 1e-9);
  EXPECT_NEAR(without.y.back(), 0.0, 1e-9);
  // Halfway, C at 90 deg: the tool is over the part's point on its Y axis.
  std::size_t half = 0;
  const std::vector<double>& c = channel(without, "c");
  while (half < c.size() && c[half] < 90.0) ++half;
  EXPECT_NEAR(std::hypot(without.x[half], without.y[half]), 10.0, 1e-6);
  EXPECT_NEAR(std::abs(without.y[half]), 10.0, 0.1);
}

// C turning at 90 deg/s under a tip 80 mm from its centre drives the X and Y slides round at up
// to 80 * pi / 2 = 125.7 mm/s, past their 100 mm/s: LinuxCNC runs it so, and the run says which
// joints and where. At 10 mm from the centre (15.7 mm/s) nothing is said.
TEST(fiveAxisMotion, JointsPastTheirLimitsAreNamedWithTheirLines) {
  const Machine machine = trtMachine();
  auto warningsOf = [&](const std::string& gcode) {
    const InterpretResult read = interpretGcode(gcode, "far.ngc");
    EXPECT_TRUE(read.ok());
    TrajectorySink sink(machine.cycle, "far.ngc", false);
    sink.keepJointsOf(*machine.kinematics);
    std::string all;
    for (const Diagnostic& d : simulate(read.program, machine, sink).warnings) all += d.str() + "\n";
    return all;
  };
  const std::string far = warningsOf("G21 G90 G94 G61\nG0 X80 Y0 Z0\nG1 C90 F5400\nM2\n");
  for (const char* joint : {"joint X reaches ", "joint Y reaches "}) {
    const std::size_t at = far.find(joint);
    ASSERT_NE(at, std::string::npos) << far;
    const double speed = std::stod(far.substr(at + std::string(joint).size()));
    EXPECT_GT(speed, 120.0) << far;
    EXPECT_LT(speed, 80 * 3.14159265358979 / 2 + 0.1) << far;
  }
  EXPECT_NE(far.find("far.ngc:3: joint"), std::string::npos) << far;
  EXPECT_NE(far.find("on lines 3 "), std::string::npos) << far;
  EXPECT_EQ(warningsOf("G21 G90 G94 G61\nG0 X10 Y0 Z0\nG1 C90 F5400\nM2\n"), "");
}

}  // namespace
}  // namespace isurface
