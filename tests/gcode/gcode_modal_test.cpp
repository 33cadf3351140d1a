// Modal state: units, distance modes, feed modes, path control, stops, dwell, G28/G30.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "gcode_test_support.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

InterpretResult runOk(const std::string& text, InterpreterOptions options = {}) {
  InterpretResult r = run(text, options);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].str());
  return r;
}

}  // namespace

TEST(gcodeModal, InchProgramsAreConvertedToMillimetres) {
  const InterpretResult r = runOk("G20\nG0 X1 Y2 Z-0.5\nG1 X2 F10\nG4 P2\nG21\nG1 X1\n");
  ASSERT_EQ(r.program.moves.size(), 4u);
  expectNear(r.program.moves[0].end, Vec3(25.4, 50.8, -12.7));
  expectNear(r.program.moves[1].end, Vec3(50.8, 50.8, -12.7));
  EXPECT_FLOAT_EQ(r.program.moves[1].feed, 254.0f);
  EXPECT_EQ(r.program.moves[2].kind, MoveKind::Dwell);
  EXPECT_FLOAT_EQ(r.program.moves[2].feed, 2.0f);  // seconds are not lengths
  // Back in mm the feed keeps its speed (254 mm/min) and the coordinates are mm again.
  expectNear(r.program.moves[3].end, Vec3(1, 50.8, -12.7));
  EXPECT_FLOAT_EQ(r.program.moves[3].feed, 254.0f);
}

TEST(gcodeModal, FeedIsSetBeforeUnitsChangeInOneBlock) {
  // RS274/NGC order of execution (as in LinuxCNC): F, then G20/G21, then motion.
  const InterpretResult r = runOk("G20 G1 X1 F10\n");
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_NEAR(r.program.moves[0].end.x(), 25.4, 1e-12);
  EXPECT_FLOAT_EQ(r.program.moves[0].feed, 10.0f);
}

TEST(gcodeModal, IncrementalDistance) {
  const InterpretResult r = runOk("G0 X1 Y1\nG91 G0 X1 Y-2 Z0.5\nX1\nG90 X0\n");
  ASSERT_EQ(r.program.moves.size(), 4u);
  expectNear(r.program.moves[0].end, Vec3(1, 1, 0));
  expectNear(r.program.moves[1].end, Vec3(2, -1, 0.5));
  expectNear(r.program.moves[2].end, Vec3(3, -1, 0.5));
  expectNear(r.program.moves[3].end, Vec3(0, -1, 0.5));
}

TEST(gcodeModal, StartPositionOption) {
  InterpreterOptions options;
  options.startPosition = Vec3(1, 2, 3);
  const InterpretResult r = runOk("G91 G0 X1\n", options);
  EXPECT_EQ(r.program.start, Vec3(1, 2, 3));
  ASSERT_EQ(r.program.moves.size(), 1u);
  expectNear(r.program.moves[0].end, Vec3(2, 2, 3));
}

TEST(gcodeModal, ArcCentreDistanceModes) {
  // Default G91.1: I and J are offsets from the start.
  InterpretResult r = runOk("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F100\n");
  ASSERT_EQ(r.program.moves.size(), 2u);
  expectNear(r.program.moves[1].centre, Vec3(0, 0, 0));
  // G90.1: I and J are absolute.
  r = runOk("G0 X10 Y5\nG90.1 G3 X0 Y15 I0 J5 F100\nG91.1 G2 X10 Y5 I0 J-10\n");
  ASSERT_EQ(r.program.moves.size(), 3u);
  expectNear(r.program.moves[1].centre, Vec3(0, 5, 0));
  expectNear(r.program.moves[2].centre, Vec3(0, 5, 0));
}

TEST(gcodeModal, InverseTimeFeed) {
  InterpretResult r = runOk("G1 X0 F100\nG93 G1 X10 F2\nG1 X10 Y10 F0.5\n");
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_FLOAT_EQ(r.program.moves[1].feed, 20.0f);  // 10 mm in 1/2 minute
  EXPECT_FLOAT_EQ(r.program.moves[2].feed, 5.0f);   // 10 mm in 2 minutes

  // Arcs: the helical length over the time.
  r = runOk("G0 X10\nG93 G3 X-10 Y0 I-10 J0 F1\n");
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_NEAR(r.program.moves[1].feed, 10 * M_PI, 1e-4);

  EXPECT_EQ(firstError("G93\nG1 X10\n"), "t.ngc:2:1: F word missing with inverse time G1 move");
  EXPECT_EQ(firstError("G93\nG2 X10 I5 F1\nG3 X0 I-5\n"),
            "t.ngc:3:1: F word missing with inverse time arc move");
  // Leaving G93 forgets the feed rate: it must be given again.
  EXPECT_EQ(firstError("G93 G1 X10 F2\nG94\nG1 X20\n"),
            "t.ngc:3:1: Cannot do G1 with zero feed rate");
}

TEST(gcodeModal, ExactStopFlag) {
  const InterpretResult r = runOk("G61 G1 X1 F100\nG64 X2\nG61.1 X3\nG0 X4\nG64 P0.01 Q0.01 X5\n");
  ASSERT_EQ(r.program.moves.size(), 5u);
  EXPECT_EQ(r.program.moves[0].flags & kExactStop, kExactStop);
  EXPECT_EQ(r.program.moves[1].flags & kExactStop, 0);
  EXPECT_EQ(r.program.moves[2].flags & kExactStop, kExactStop);
  EXPECT_EQ(r.program.moves[3].flags & kExactStop, kExactStop);
  EXPECT_EQ(r.program.moves[4].flags & kExactStop, 0);
}

TEST(gcodeModal, StopsAndProgramEnd) {
  const InterpretResult r = runOk(
      "G1 X1 F100\n"  // 1
      "M5\n"          // 2: spindle stop after move 0
      "G1 X2\n"       // 3
      "G1 X3 M3\n"    // 4: spindle start before this line's motion: after move 1
      "G1 X4 M0\n"    // 5: program stop after this line's motion
      "G1 X5 M8\n"    // 6: coolant: no stop
      "T2 M6\n"       // 7: tool change after move 4
      "G1 X6\n"       // 8
      "M30\n"         // 9: end
      "G1 X99\n");    // 10: not interpreted
  ASSERT_EQ(r.program.moves.size(), 6u);
  const std::uint8_t expected[] = {kStopAfter, kStopAfter, 0, kStopAfter, kStopAfter, kStopAfter};
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(r.program.moves[i].flags & kStopAfter, expected[i]) << "move " << i;
  EXPECT_EQ(r.program.lineCount, 10u);
}

TEST(gcodeModal, M2EndsTheProgram) {
  const InterpretResult r = runOk("G0 X1\nM2\nG0 X2 X3 (an error nobody reads)\n");
  EXPECT_EQ(r.program.moves.size(), 1u);
}

TEST(gcodeModal, Dwell) {
  const InterpretResult r = runOk("G1 X1 F100\nG4 P2.5\nG1 X2\n");
  ASSERT_EQ(r.program.moves.size(), 3u);
  const Move& d = r.program.moves[1];
  EXPECT_EQ(d.kind, MoveKind::Dwell);
  EXPECT_FALSE(d.isMotion());
  EXPECT_DOUBLE_EQ(d.dwellSeconds(), 2.5);
  EXPECT_EQ(d.end, Vec3(1, 0, 0));
  EXPECT_EQ(d.line, 2u);
  EXPECT_EQ(r.program.moves[2].end, Vec3(2, 0, 0));
  EXPECT_EQ(firstError("G4\n"), "t.ngc:1:1: Dwell time P word missing with G4");
  EXPECT_EQ(firstError("G4 P-1\n"), "t.ngc:1:4: Negative dwell time P word used with G4");
}

TEST(gcodeModal, HomeMoves) {
  InterpreterOptions options;
  options.g28Position = Vec3(0, 0, 50);
  options.g30Position = Vec3(100, 100, 60);
  // Without axis words, as rs274: a rapid where the tool is, then to the reference position.
  InterpretResult r = runOk("G0 X10 Y10 Z5\nG28\n", options);
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(10, 10, 5));
  EXPECT_EQ(r.program.moves[2].kind, MoveKind::Rapid);
  EXPECT_EQ(r.program.moves[2].end, Vec3(0, 0, 50));

  // Through the point on the line, then only the named axes go to the reference position.
  r = runOk("G0 X10 Y10 Z5\nG28 Z20\nG30 X20\nG91 G28 Z5\n", options);
  ASSERT_EQ(r.program.moves.size(), 7u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(10, 10, 20));
  EXPECT_EQ(r.program.moves[2].end, Vec3(10, 10, 50));
  EXPECT_EQ(r.program.moves[3].end, Vec3(20, 10, 50));
  EXPECT_EQ(r.program.moves[4].end, Vec3(100, 10, 50));
  EXPECT_EQ(r.program.moves[5].end, Vec3(100, 10, 55));
  EXPECT_EQ(r.program.moves[6].end, Vec3(100, 10, 50));
  for (const Move& m : r.program.moves) EXPECT_EQ(m.kind, MoveKind::Rapid);

  // G28.1 stores the current position.
  r = runOk("G0 X1 Y2 Z3\nG28.1\nG0 X0 Y0 Z0\nG28\n", options);
  ASSERT_EQ(r.program.moves.size(), 4u);
  EXPECT_EQ(r.program.moves[3].end, Vec3(1, 2, 3));

  EXPECT_EQ(firstError("G28 G1 X1 F100\n"),
            "t.ngc:1:5: Cannot use two G codes that both use axis values");
}

TEST(gcodeModal, CutterCompensationWithoutAToolTableLeavesThePathAsProgrammed) {
  const InterpretResult r = runOk("G21 G41 D1 G1 X1 F100\nG40 X2\nG42 X3\nG40\nG41.1 D0 X4\n");
  ASSERT_EQ(r.program.moves.size(), 4u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(2, 0, 0));
  EXPECT_EQ(r.program.moves[3].end, Vec3(4, 0, 0));
  EXPECT_TRUE(r.program.warnings.empty());
  // Changing sides needs G40 between, as in LinuxCNC.
  EXPECT_EQ(firstError("G21 G41 D1 G1 X1 F100\nG42 X2\n"), "t.ngc:2:1: Cannot turn cutter radius comp on when already on");
}

TEST(gcodeModal, AcceptedCodesWithoutEffectOnCoordinates) {
  const InterpretResult r = runOk(
      "G17 G21 G40 G49 G80 G90 G94 G97 G98 G54\n"
      "G55 G0 X1\nG59.3 G0 X2\nG10 L2 P1 X5 Y5\nG43 H1 Z1\nG43.1 Z2\nG49 G53 G0 X3\n"
      "G53 G1 X4 F100\nG96 S100\nG97 S1000\n");
  // G43.1 Z2 is a tool length, not a move; G10 L2 P1 changes G54, not the G59.3 in effect.
  ASSERT_EQ(r.program.moves.size(), 5u);
  EXPECT_EQ(r.program.moves[2].end, Vec3(2, 0, 1));
  EXPECT_EQ(r.program.moves[4].end, Vec3(4, 0, 1));
  EXPECT_EQ(firstError("G53 G2 X1 I1\n"), "t.ngc:1:1: Must use G0 or G1 with G53");
  EXPECT_EQ(firstError("G91 G53 G0 X1\n"), "t.ngc:1:5: Cannot use G53 incremental");
}

TEST(gcodeModal, MotionCancelAndAxesWithoutMotion) {
  // A common header puts G0 and G80 together: the cycle is cancelled, G0 stays.
  InterpretResult r = runOk("G00 G17 G21 G40 G49 G80 G90\nX1\n");
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].kind, MoveKind::Rapid);
  const std::string withoutMotion = "Cannot use axis values without a g code that uses them";
  EXPECT_EQ(firstError("X1\n").rfind("t.ngc:1:1: " + withoutMotion, 0), 0u);
  EXPECT_EQ(firstError("G80 X1\n"), "t.ngc:1:1: Cannot use axis values with G80");
  EXPECT_EQ(firstError("G0 X1\nG80\nY1\n").rfind("t.ngc:3:1: " + withoutMotion, 0), 0u);
}

TEST(gcodeModal, ZeroLengthMovesAreKept) {
  const InterpretResult r = runOk("G0 X0 Y0 Z0\nG1 X0 F100\nG1 Z0\n");
  ASSERT_EQ(r.program.moves.size(), 3u);
  for (const Move& m : r.program.moves) EXPECT_EQ(m.end, Vec3::Zero());
}

// A, B and C are read with the moves (not ignored with a warning): a move of the rotary axes
// alone is a move, and each move knows where they end.
TEST(gcodeModal, RotaryWordsAreReadWithTheirMoves) {
  const InterpretResult r = runOk("G21 G0 X1 A90\nG0 B10 C5\n");
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(1, 0, 0));
  EXPECT_TRUE(r.program.warnings.empty());
  EXPECT_EQ(r.program.rotaryAt(0), (std::array<double, 3>{90, 0, 0}));
  EXPECT_EQ(r.program.rotaryAt(1), (std::array<double, 3>{90, 10, 5}));
}

TEST(gcodeModal, WordsWithoutACodeToUseThem) {
  EXPECT_EQ(firstError("G1 X1 I2 F100\n"), "t.ngc:1:7: i word with no G2 or G3 to use it");
  EXPECT_EQ(firstError("G0 X1 R2\n"), "t.ngc:1:7: R word with no g code that uses it");
  EXPECT_EQ(firstError("G1 F-1\n"), "t.ngc:1:4: Negative F word used");
}

TEST(gcodeModal, UnitsComeFromTheControlWhenTheProgramDoesNotSay) {
  // A Haas program that relies on the control's inch default, as its header says.
  InterpreterOptions inch;
  inch.inchAtPowerOn = true;
  InterpretResult r = run("(UNITS: INCH, SET AT THE CONTROL)\nG0 X1 Y2\nG1 Z-.5 F10.\n", inch);
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  EXPECT_EQ(r.program.moves[0].end, Vec3(25.4, 50.8, 0));
  EXPECT_FLOAT_EQ(r.program.moves[1].feed, 254.0f);
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_EQ(r.program.warnings[0].line, 2u);
  EXPECT_NE(r.program.warnings[0].message.find("power-on units (inch, G20)"), std::string::npos);
  // A program that says its units gets no warning and its own units.
  r = run("G21\nG0 X1\n", inch);
  EXPECT_TRUE(r.program.warnings.empty());
  EXPECT_EQ(r.program.moves[0].end, Vec3(1, 0, 0));
}

TEST(gcodeModal, FanucCyclesLeaveG0ToG3AsTheyWere) {
  const std::string text = "G21 G0 X0 Y0 Z10\nG99 G81 X5 Y5 Z-3 R2 F100\nG80\nZ20\nX1\n";
  // RS274/NGC refuses it, and says which machine reads it as the program's author meant.
  const std::string refused = firstError(text);
  EXPECT_EQ(refused.rfind("t.ngc:4:1: Cannot use axis values without a g code that uses them", 0), 0u) << refused;
  EXPECT_NE(refused.find("\"dialect\": \"fanuc\""), std::string::npos) << refused;
  EXPECT_NE(refused.find("--machine resources/machines/fanuc-inch.json"), std::string::npos) << refused;
  InterpreterOptions fanuc;
  fanuc.fanuc = true;
  const InterpretResult r = run(text, fanuc);
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_GE(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[r.program.moves.size() - 2].kind, MoveKind::Rapid);  // G0 from line 1 goes on
  EXPECT_EQ(r.program.moves.back().end, Vec3(1, 5, 20));
}

// A Haas program that never says G20 but whose header speaks of inches: read in the control's
// power-on millimetres, with one line saying which machine reads it in inches.
TEST(gcodeModal, AProgramWhoseCommentsSpeakOfInchesWithoutG20IsNamedInTheUnitsWarning) {
  const InterpretResult r = run("%\nO1000 (PART 12 - UNITS: INCHES)\nG90 G0 X1. Y1.\nM30\n%\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.warnings.size(), 1u);
  const std::string warning = r.program.warnings[0].str();
  EXPECT_NE(warning.find("power-on units (mm, G21) are used, though its comments speak of inches"), std::string::npos)
      << warning;
  EXPECT_NE(warning.find("fanuc-inch.json"), std::string::npos) << warning;
  // Without such a comment the warning says nothing of inches.
  const InterpretResult plain = run("%\nO1000 (PART 12)\nG90 G0 X1. Y1.\nM30\n%\n");
  ASSERT_EQ(plain.program.warnings.size(), 1u);
  EXPECT_EQ(plain.program.warnings[0].str().find("inches"), std::string::npos);
}

TEST(gcodeModal, ExtendedWorkOffsetsAreRecordedLikeG54) {
  // Haas and Fanuc "G54.1 P3": like G54-G59, the moves stay in the program's coordinates.
  const InterpretResult r = run("G21 G90\nG54.1 P3 G0 X1\nG0 X2\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(2, 0, 0));
}

TEST(gcodeModal, TheControlsPowerOnPlaneAndDistanceModeAreUsedAndNamedWhenRelyingOnThem) {
  InterpreterOptions options;
  options.planeAtPowerOn = Plane::ZX;
  options.incrementalAtPowerOn = true;
  options.powerOnModesNamed = true;
  const InterpretResult r = run("G21 F100\nG1 X1 Z1\nG1 X1\nG2 X2 Z0 R1\n", options);
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  EXPECT_EQ(r.program.moves[1].end, Vec3(2, 0, 1));  // incremental
  EXPECT_EQ(r.program.moves[2].plane, Plane::ZX);
  ASSERT_EQ(r.program.warnings.size(), 2u);
  EXPECT_NE(r.program.warnings[0].message.find("power-on distance mode (G91, incremental)"), std::string::npos);
  EXPECT_NE(r.program.warnings[1].message.find("power-on plane (G18)"), std::string::npos);
  // A program that states its modes gets no warning.
  EXPECT_TRUE(run("G21 G90 G18 F100\nG1 X1 Z1\nG2 X2 Z0 R1\n", options).program.warnings.empty());
}

TEST(gcodeModal, TheProgramSaysWhetherItIsWrittenInInches) {
  EXPECT_TRUE(runOk("G20\nG0 X1\nG21\nG0 X2\n").program.inch);  // the first G20/G21 decides
  EXPECT_FALSE(runOk("G21\nG0 X1\nG20\nG0 X2\n").program.inch);
  EXPECT_TRUE(run("G0 Z0.1\nG20\nG1 X1 F10\n").program.inch);  // a move before the units does not hide them
  EXPECT_FALSE(run("G0 X1\n").program.inch);
  InterpreterOptions inchControl;
  inchControl.inchAtPowerOn = true;
  EXPECT_TRUE(run("G0 X1\n", inchControl).program.inch);
}
