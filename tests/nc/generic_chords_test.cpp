// The generic control with a jerk limit (the default machine) runs a run of CAM chords as the
// curve they sample: a circle written as chords takes the time the same circle written as one
// arc takes, within the machine's tolerance and limits. A control without a compressor
// ("chord_smoothing": false) brakes at every chord junction instead.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/simulator.h"
#include "motion_checks.h"

using namespace isurface;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Circle {
  double radius, chord, feed;  // mm, mm, mm/min
};

// A lead-in, one turn of radius r (chords of about `chord` mm, points in four decimals as a CAM
// system writes them, or one G3), and a lead-out.
Program circleProgram(const Circle& c, bool asChords) {
  std::string text = fmt::format("G21 G90 G17 G94\nG0 X0 Y0 Z0\nG1 X{:.4f} Y0 F{:g}\n", c.radius, c.feed);
  if (asChords) {
    const int n = static_cast<int>(std::lround(2 * kPi * c.radius / c.chord));
    for (int k = 1; k <= n; ++k)
      text += fmt::format("G1 X{:.4f} Y{:.4f}\n", c.radius * std::cos(2 * kPi * k / n), c.radius * std::sin(2 * kPi * k / n));
  } else {
    text += fmt::format("G3 X{:.4f} Y0 I{:.4f} J0\n", c.radius, -c.radius);
  }
  text += fmt::format("G1 X{:.4f} Y0\nM2\n", c.radius + 10);
  const InterpretResult read = interpretGcode(text, asChords ? "chords.ngc" : "arc.ngc");
  EXPECT_TRUE(read.ok());
  return read.program;
}

test::MotionExtremes run(const Program& program, const Machine& machine) {
  test::MotionChecker checker(program, machine, 0);
  simulate(program, machine, checker);
  return checker.finish();
}

const Circle kCircles[] = {{3, 0.1, 2000}, {5, 0.2, 3000}, {10, 0.5, 3000}, {30, 1.0, 6000}};

}  // namespace

TEST(genericControlChords, ChordsOfACircleRunAsTheArcItself) {
  const Machine machine = defaultMachine();
  ASSERT_TRUE(machine.jerkLimited());
  for (const Circle& c : kCircles) {
    SCOPED_TRACE(fmt::format("radius {} mm, chords of {} mm, F{}", c.radius, c.chord, c.feed));
    const test::MotionExtremes chords = run(circleProgram(c, true), machine);
    const test::MotionExtremes arc = run(circleProgram(c, false), machine);
    EXPECT_NEAR(chords.duration / arc.duration, 1.0, 0.02) << chords.duration << " s against " << arc.duration << " s";
    test::expectWithinLimits(chords, machine);
  }
}

TEST(genericControlChords, WithoutACompressorTheControlBrakesAtEveryJunction) {
  Machine machine = defaultMachine();
  machine.control.chordSmoothing = false;
  const Circle c{30, 1.0, 6000};
  const test::MotionExtremes chords = run(circleProgram(c, true), machine);
  const test::MotionExtremes arc = run(circleProgram(c, false), machine);
  EXPECT_GT(chords.duration, 1.2 * arc.duration);
  test::expectWithinLimits(chords, machine);
}
