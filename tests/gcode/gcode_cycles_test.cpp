// Canned cycles expanded into moves, with G98/G99 retracts: drilling G81 G82 G83 G73, tapping
// G84 G74, boring G85 G86 G88 G89 (all of them also against rs274: tests/data/rs274/cycles.ngc).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "isurface/gcode/gcode_interpreter.h"
#include "gcode_test_support.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

struct Expected {
  char kind;  // 'R' rapid, 'F' feed, 'D' dwell
  double x, y, z;
};

// Compares the moves from `from` on with the expected list.
void expectMoves(const InterpretResult& r, std::size_t from, const std::vector<Expected>& expected) {
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), from + expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Move& m = r.program.moves[from + i];
    const Expected& e = expected[i];
    const char kind = m.kind == MoveKind::Rapid ? 'R' : m.kind == MoveKind::Linear ? 'F' : 'D';
    EXPECT_EQ(kind, e.kind) << "move " << from + i;
    EXPECT_NEAR(m.end.x(), e.x, 1e-9) << "move " << from + i;
    EXPECT_NEAR(m.end.y(), e.y, 1e-9) << "move " << from + i;
    EXPECT_NEAR(m.end.z(), e.z, 1e-9) << "move " << from + i;
    EXPECT_EQ(m.flags & kExactStop, kExactStop) << "cycles run in exact stop";
  }
}

}  // namespace

// Before any G98 / G99 a cycle retracts as the control powers on: LinuxCNC's rs274 to R (its
// output for this program), Fanuc to the initial level.
TEST(gcodeCycles, G81RetractsAsTheDialectPowersOn) {
  const std::string program = "G0 X0 Y0 Z10\nG81 X5 Y5 Z-3 R2 F100\nX10\n";
  const InterpretResult linuxcnc = run(program);
  expectMoves(linuxcnc, 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'R', 5, 5, 2},
               {'R', 10, 5, 2}, {'F', 10, 5, -3}, {'R', 10, 5, 2}});
  InterpreterOptions fanucOptions;
  fanucOptions.fanuc = true;
  const InterpretResult r = run(program, fanucOptions);
  expectMoves(r, 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'R', 5, 5, 10},
               {'R', 10, 5, 10}, {'R', 10, 5, 2}, {'F', 10, 5, -3}, {'R', 10, 5, 10}});
  EXPECT_EQ(r.program.moves[1].line, 2u);
  EXPECT_EQ(r.program.moves[5].line, 3u);
  EXPECT_FLOAT_EQ(r.program.moves[3].feed, 100.0f);
}

TEST(gcodeCycles, G98ReturnsToTheInitialLevel) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG98 G81 X5 Y5 Z-3 R2 F100\nX10\n");
  expectMoves(r, 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'R', 5, 5, 10},
               {'R', 10, 5, 10}, {'R', 10, 5, 2}, {'F', 10, 5, -3}, {'R', 10, 5, 10}});
}

TEST(gcodeCycles, G99ReturnsToR) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG99 G81 X5 Y5 Z-3 R2 F100\nX10\n");
  expectMoves(r, 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'R', 5, 5, 2},
               {'R', 10, 5, 2}, {'F', 10, 5, -3}, {'R', 10, 5, 2}});
}

TEST(gcodeCycles, StartBelowRGoesUpFirst) {
  const InterpretResult r = run("G0 X0 Y0 Z1\nG81 X5 Y5 Z-3 R2 F100\n");
  expectMoves(r, 1, {{'R', 0, 0, 2}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'R', 5, 5, 2}});
}

TEST(gcodeCycles, G82Dwells) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG98 G82 X5 Y5 Z-3 R2 P0.5 F100\nY6\n");
  expectMoves(r, 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'D', 5, 5, -3}, {'R', 5, 5, 10},
               {'R', 5, 6, 10}, {'R', 5, 6, 2}, {'F', 5, 6, -3}, {'D', 5, 6, -3}, {'R', 5, 6, 10}});
  EXPECT_DOUBLE_EQ(r.program.moves[4].dwellSeconds(), 0.5);
  EXPECT_DOUBLE_EQ(r.program.moves[9].dwellSeconds(), 0.5);  // P is kept for the next holes
}

TEST(gcodeCycles, TappingFeedsInStopsAndFeedsOut) {
  // As rs274 runs G84: feed to Z, reverse the spindle (the motion stops there), feed back out
  // to the retract level (not to R first).
  const InterpretResult r = run("G0 X0 Y0 Z10\nS500 M3\nM29 S175\nG98 G84 X5 Y5 Z-3 R2 F100\n");
  expectMoves(r, 1, {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'F', 5, 5, 10}});
  EXPECT_NE(r.program.moves[3].flags & kStopAfter, 0);
  const InterpretResult left = run("G0 X0 Y0 Z10\nS500 M4\nG99 G74 X5 Y5 Z-3 R2 P0.2 F100\n");
  expectMoves(left, 1, {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'D', 5, 5, -3}, {'F', 5, 5, 2}});
}

TEST(gcodeCycles, BoringCycles) {
  expectMoves(run("G0 X0 Y0 Z10\nG98 G85 X5 Y5 Z-3 R2 F100\n"), 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'F', 5, 5, 2}, {'R', 5, 5, 10}});
  expectMoves(run("G0 X0 Y0 Z10\nG98 G86 X5 Y5 Z-3 R2 P1 F100\n"), 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'D', 5, 5, -3}, {'R', 5, 5, 10}});
  expectMoves(run("G0 X0 Y0 Z10\nG98 G89 X5 Y5 Z-3 R2 P1 F100\n"), 1,
              {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'D', 5, 5, -3}, {'F', 5, 5, 10}});
  // G88 stops at the bottom for the operator to retract by hand.
  const InterpretResult r = run("G0 X0 Y0 Z10\nG98 G88 X5 Y5 Z-3 R2 P1 F100\n");
  expectMoves(r, 1, {{'R', 5, 5, 10}, {'R', 5, 5, 2}, {'F', 5, 5, -3}, {'D', 5, 5, -3}});
  EXPECT_NE(r.program.moves.back().flags & kStopAfter, 0);
  EXPECT_EQ(firstError("G0 Z10\nG86 X5 Y5 Z-3 R2 F100\n"), "t.ngc:2:1: Dwell time P word missing with G86");
}

TEST(gcodeCycles, FanucLookAheadIsAcceptedOnce) {
  const InterpretResult r = run("G08 P1\nG21 G0 X1\nG08 P0\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_NE(r.program.warnings[0].message.find("look-ahead"), std::string::npos);
  EXPECT_EQ(firstError("G8 X1\n"), "t.ngc:1:1: G8 is not supported");  // LinuxCNC's lathe radius mode
}

TEST(gcodeCycles, G83PecksBackToR) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG98 G83 X0 Y0 Z-5 R1 Q2 F100\n");
  expectMoves(r, 1,
              {{'R', 0, 0, 10}, {'R', 0, 0, 1},
               {'F', 0, 0, -1}, {'R', 0, 0, 1}, {'R', 0, 0, -0.746},
               {'F', 0, 0, -3}, {'R', 0, 0, 1}, {'R', 0, 0, -2.746},
               {'F', 0, 0, -5}, {'R', 0, 0, 10}});
}

TEST(gcodeCycles, G73BreaksChips) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG98 G73 X0 Y0 Z-5 R1 Q2 F100\n");
  expectMoves(r, 1,
              {{'R', 0, 0, 10}, {'R', 0, 0, 1}, {'F', 0, 0, -1}, {'R', 0, 0, -0.746},
               {'F', 0, 0, -3}, {'R', 0, 0, -2.746}, {'F', 0, 0, -5}, {'R', 0, 0, 10}});
}

TEST(gcodeCycles, IncrementalWithRepeats) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG91 G98 G81 X5 Y0 Z-4 R-8 L3 F100\n");
  expectMoves(r, 1,
              {{'R', 5, 0, 10}, {'R', 5, 0, 2}, {'F', 5, 0, -2}, {'R', 5, 0, 10},
               {'R', 10, 0, 10}, {'R', 10, 0, 2}, {'F', 10, 0, -2}, {'R', 10, 0, 10},
               {'R', 15, 0, 10}, {'R', 15, 0, 2}, {'F', 15, 0, -2}, {'R', 15, 0, 10}});
}

TEST(gcodeCycles, G80EndsTheCycle) {
  const InterpretResult r = run("G0 X0 Y0 Z10\nG81 X5 Y5 Z-3 R2 F100\nG80\nG0 Z20\nX1\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 7u);
  EXPECT_EQ(r.program.moves[5].end, Vec3(5, 5, 20));
  EXPECT_EQ(r.program.moves[6].end, Vec3(1, 5, 20));
  EXPECT_EQ(r.program.moves[6].kind, MoveKind::Rapid);
}

TEST(gcodeCycles, InchCycle) {
  const InterpretResult r = run("G20\nG0 X0 Y0 Z1\nG99 G81 X1 Y1 Z-0.1 R0.1 F10\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 5u);
  EXPECT_NEAR(r.program.moves[3].end.z(), -2.54, 1e-12);
  EXPECT_NEAR(r.program.moves[4].end.z(), 2.54, 1e-12);
  EXPECT_FLOAT_EQ(r.program.moves[3].feed, 254.0f);
}

// In G18 the cycle drills along Y (positions X and Z), in G19 along X (positions Y and Z).
TEST(gcodeCycles, OtherPlanes) {
  Program p = interpret("G21 G18 G0 Y5\nG98 G81 X1 Z2 Y-1 R1 F100\n");
  ASSERT_EQ(p.moves.size(), 5u);
  EXPECT_EQ(p.moves[1].end, Vec3(1, 5, 2));   // over the hole at the initial level
  EXPECT_EQ(p.moves[2].end, Vec3(1, 1, 2));   // down to R
  EXPECT_EQ(p.moves[3].end, Vec3(1, -1, 2));  // feed to the bottom
  EXPECT_EQ(p.moves[4].end, Vec3(1, 5, 2));   // back (G98)
  p = interpret("G21 G19 G0 X5\nG99 G81 Y1 Z2 X-1 R1 F100\n");
  ASSERT_EQ(p.moves.size(), 5u);
  EXPECT_EQ(p.moves[3].end, Vec3(-1, 1, 2));
  EXPECT_EQ(p.moves[4].end, Vec3(1, 1, 2));  // G99: back to R
}

// LinuxCNC 2.9's G84 / G74 in G18 and G19 swaps the coordinates of its two feed moves; the
// points are rs274's. The moves after the cycle are computed from the hole, as LinuxCNC does.
TEST(gcodeCycles, TappingInG18AndG19AsLinuxcncRunsIt) {
  InterpretResult r = run("G21 G18 G0 X0 Y2 Z0\nS100 M3\nG98 G84 X1 Z1 Y-1 R1 F100\nG91 X2 Z3 L2\nG90 G80 G0 X5\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 13u);
  r.program.moves.pop_back();
  expectMoves(r, 1,
              {{'R', 1, 2, 1}, {'R', 1, 1, 1}, {'F', -1, 1, 1}, {'F', 2, 1, 1},
               {'R', 1, 3, 1}, {'R', 3, 3, 4}, {'F', 2, 4, 3}, {'F', 3, 4, 3},
               {'R', 5, 3, 7}, {'F', 2, 7, 5}, {'F', 3, 7, 5}});
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_NE(r.program.warnings[0].message.find("G84 in the XZ plane is expanded as LinuxCNC 2.9 runs it, not along Y"),
            std::string::npos) << r.program.warnings[0].str();
  EXPECT_EQ(run("G21 G18 G0 X0 Y2 Z0\nS100 M3\nG98 G84 X1 Z1 Y-1 R1 F100\nG90 G80 G0 X5\n").program.moves.back().end,
            Vec3(5, 2, 1));

  r = run("G21 G19 G0 X2 Y0 Z0\nS100 M4\nG99 G74 Y1 Z3 X-1 R1 P0.5 F100\n");
  expectMoves(r, 1, {{'R', 2, 1, 3}, {'R', 1, 1, 3}, {'F', 3, -1, 1}, {'D', 3, -1, 1}, {'F', 3, 1, 1}});
  ASSERT_EQ(r.program.warnings.size(), 1u);
  EXPECT_NE(r.program.warnings[0].message.find("G74 in the YZ plane"), std::string::npos);

  // A G92 offset applies after the swap.
  r = run("G21 G18 G0 X0 Y2 Z0\nG92 X10 Y20 Z30\nS100 M3\nG98 G84 X11 Z31 Y19 R21 F100\n");
  expectMoves(r, 1, {{'R', 0, 3, 0}, {'R', 1, 3, 1}, {'F', 9, 13, -19}, {'F', 11, 13, -19}});
}

TEST(gcodeCycles, ArcRightAfterALinuxcncSideTapIsRefused) {
  const std::string tap = "G21 G18 G0 X0 Y2 Z0\nS100 M3\nG98 G84 X1 Z1 Y-1 R1 F100\nG80\n";
  EXPECT_EQ(firstError(tap + "G2 X3 Z1 I1 K0\n"),
            "t.ngc:5:1: Arc right after a G84 / G74 in G18 or G19: LinuxCNC starts it where the tap's last feed "
            "ended, not over the hole; put a G0 or G1 between them");
  EXPECT_TRUE(run(tap + "G0 Y2\nG2 X3 Z1 I1 K0\n").ok());
}

// A Fanuc control taps along the drilling axis of G18 and G19, as it drills there.
TEST(gcodeCycles, FanucTapsAlongTheDrillingAxisInG18AndG19) {
  InterpreterOptions fanuc;
  fanuc.fanuc = true;
  InterpretResult r = run("G21 G18 G0 X0 Y2 Z0\nS100 M3\nG98 G84 X1 Z1 Y-1 R1 F100\n", fanuc);
  expectMoves(r, 1, {{'R', 1, 2, 1}, {'R', 1, 1, 1}, {'F', 1, -1, 1}, {'F', 1, 2, 1}});
  EXPECT_TRUE(r.program.warnings.empty());
  r = run("G21 G19 G0 X2 Y0 Z0\nS100 M4\nG99 G74 Y1 Z3 X-1 R1 F100\n", fanuc);
  expectMoves(r, 1, {{'R', 2, 1, 3}, {'R', 1, 1, 3}, {'F', -1, 1, 3}, {'F', 1, 1, 3}});
}

TEST(gcodeCycles, Errors) {
  EXPECT_EQ(firstError("G18 G81 X1 Z1 R1 F100\n"),
            "t.ngc:1:5: Y value unspecified in XZ plane canned cycle");
  EXPECT_EQ(firstError("G19 G81 Y1 X3 R2 F100\n"), "t.ngc:1:5: R less than X in canned cycle in YZ plane");
  EXPECT_EQ(firstError("G81 X1 Y1 Z-1 F100\n"),
            "t.ngc:1:1: R clearance plane unspecified in canned cycle");
  EXPECT_EQ(firstError("G81 X1 Y1 R1 F100\n"),
            "t.ngc:1:1: Z value unspecified in XY plane canned cycle");
  EXPECT_EQ(firstError("G83 X1 Y1 Z-1 R1 F100\n"), "t.ngc:1:1: Q word missing with G83");
  EXPECT_EQ(firstError("G73 X1 Y1 Z-1 R1 Q-1 F100\n"), "t.ngc:1:18: Negative or zero Q value used");
  EXPECT_EQ(firstError("G82 X1 Y1 Z-1 R1 F100\n"), "t.ngc:1:1: Dwell time P word missing with G82");
  EXPECT_EQ(firstError("G81 X1 Z1 R0 F100\n"), "t.ngc:1:1: R less than Z in canned cycle in XY plane");
  EXPECT_EQ(firstError("G81 X1 Y1 Z-1 R1\n"), "t.ngc:1:1: Cannot do G81 with zero feed rate");
  EXPECT_EQ(firstError("G83 X1 Y1 Z-100 R1 Q0.0001 F100\n"),
            "t.ngc:1:20: Q value too small: over 100000 pecks");
  EXPECT_EQ(firstError("G81 X1 Y1 Z-1 R1 L1e5 F100\n"),
            "t.ngc:1:20: Unknown word starting with E");
  EXPECT_EQ(firstError("G81 X1 Y1 Z-1 R1 L2.5 F100\n"),
            "t.ngc:1:18: L word must be a whole number, zero or more");
}

TEST(gcodeCycles, BadCycleBlockLeavesNoMovesWithKeepGoing) {
  InterpreterOptions options;
  options.keepGoing = true;
  // The second block fails after some of its holes would have been drilled.
  const InterpretResult r =
      run("G0 X0 Y0 Z10\nG98 G81 X5 Y5 Z-3 R2 F100\nG18 X6\nG17 X7\n", options);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].line, 3u);
  ASSERT_EQ(r.program.moves.size(), 9u);
  EXPECT_EQ(r.program.moves[5].end, Vec3(7, 5, 10));
}
