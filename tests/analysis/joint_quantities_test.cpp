// A five-axis run's joint quantities, worked by hand: the table turning under a tip that stands
// still moves the machine's slides.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isurface/analysis/quantities.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/simulator.h"
#include "test_locations.h"

namespace isurface {
namespace {

constexpr double kPi = 3.14159265358979323846;

Trajectory turningTable() {
  const Machine machine = loadMachine(std::string(test::sourceDir()) + "/resources/machines/linuxcnc-xyzbc-trt.json");
  const InterpretResult read = interpretGcode("G21 G90 G94 G64\nG0 X10 Y0 Z0\nG1 C180 F3600\nM2\n", "turn.ngc");
  EXPECT_TRUE(read.ok());
  TrajectorySink sink(machine.cycle, "turn.ngc", false);
  sink.keepJointsOf(*machine.kinematics);
  simulate(read.program, machine, sink);
  return sink.take();
}

// C turns at 60 deg/s with the tip at X10 on the table: the tip stands still, the X Y slides
// carry the point round a circle of 10 mm at 10 * pi / 3 mm/s (628.3 mm/min); at C 90 deg the X
// slide moves at all of it and the Y slide at none; C itself at 60 deg/s.
TEST(jointQuantities, TheSlidesMoveWhereTheTableTurnsUnderAStillTip) {
  const Trajectory t = turningTable();
  const std::vector<double>& c = *t.extraChannel("c");
  std::size_t half = 0;
  while (half < c.size() && c[half] < 90.0) ++half;
  ASSERT_LT(half, c.size());
  const double slideSpeed = 10 * kPi / 3 * 60;  // mm/min
  EXPECT_NEAR(sampleQuantity(Quantity::Speed, t)[half], 0.0, 1e-6);
  EXPECT_NEAR(sampleQuantity(Quantity::JointSpeed, t)[half], slideSpeed, 0.5);
  EXPECT_NEAR(std::abs(sampleQuantity(Quantity::JointVelocityX, t)[half]), slideSpeed, 0.5);
  EXPECT_NEAR(sampleQuantity(Quantity::JointVelocityY, t)[half], 0.0, 0.5);
  EXPECT_NEAR(sampleQuantity(Quantity::JointVelocityC, t)[half], 60.0, 0.01);
  // The centripetal acceleration of the slides: 10 mm * (pi/3 /s)^2, along Y at C 90 deg.
  EXPECT_NEAR(std::abs(sampleQuantity(Quantity::JointAccelerationY, t)[half]), 10 * std::pow(kPi / 3, 2), 0.05);
  EXPECT_TRUE(quantityAvailable(Quantity::JointVelocityC, t));
  EXPECT_FALSE(quantityAvailable(Quantity::JointVelocityA, t));
  // A joint the machine lacks is not read as standing still.
  EXPECT_THROW(sampleQuantity(Quantity::JointVelocityA, t), InputError);
}

// A run without joints offers none, and asking for one says what is missing.
TEST(jointQuantities, ARunWithoutJointsSaysSo) {
  Trajectory t = turningTable();
  t.extra.clear();
  EXPECT_FALSE(quantityAvailable(Quantity::JointSpeed, t));
  try {
    sampleQuantity(Quantity::JointSpeed, t);
    FAIL() << "joint speed of a run without joints";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no joints"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isurface
