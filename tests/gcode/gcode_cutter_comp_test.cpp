// Cutter radius compensation (G41 / G42 / G41.1 / G42.1 / G40): hand-worked offset paths, the
// tool's radius from the tool table or the program, the gouge checks and the codes it forbids.
// rs274_differential_test.cpp compares many generated contours with LinuxCNC's rs274.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gcode_test_support.h"
#include "isurface/gcode/gcode_stream.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

InterpreterOptions withTools(std::map<int, double> diameters) {
  InterpreterOptions options;
  options.toolDiameters = std::move(diameters);
  return options;
}

std::vector<Vec3> ends(const InterpretResult& r) {
  std::vector<Vec3> out;
  for (const Move& m : r.program.moves) out.push_back(m.end);
  return out;
}

// A 20 mm square run counter-clockwise from (0, 0), entered from (-10, -10).
std::string square(const std::string& comp) {
  return "G21 G17 G90\nG0 X-10 Y-10\nF100\n" + comp +
         "\nG1 X0 Y0\nG1 X20 Y0\nG1 X20 Y20\nG1 X0 Y20\nG1 X0 Y0\nG40\nG0 X-10 Y-10\nM2\n";
}

const double kHalfRoot2 = std::sqrt(0.5);

}  // namespace

TEST(CutterCompensation, LeftOfASquareRunsInsideItWithAnArcAroundTheOutsideCorner) {
  const InterpretResult r = run(square("G41 D1"), withTools({{1, 2.0}}));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  const std::vector<Vec3> e = ends(r);
  ASSERT_EQ(e.size(), 8u);
  // Entry: to the radius beside the first point, square to the entry move.
  expectNear(e[1], Vec3(-kHalfRoot2, kHalfRoot2, 0), 1e-12);
  // Turning right onto the first side is an outside corner for a tool on the left: an arc about
  // the programmed corner, clockwise, radius 1.
  EXPECT_EQ(r.program.moves[2].kind, MoveKind::ArcCW);
  expectNear(r.program.moves[2].centre, Vec3(0, 0, 0));
  expectNear(e[2], Vec3(0, 1, 0));
  // The square's corners are inside corners: the offset sides meet.
  expectNear(e[3], Vec3(19, 1, 0));
  expectNear(e[4], Vec3(19, 19, 0));
  expectNear(e[5], Vec3(1, 19, 0));
  // The last move before G40 ends beside its programmed end; the exit move leaves from there.
  expectNear(e[6], Vec3(1, 0, 0));
  expectNear(e[7], Vec3(-10, -10, 0));
  EXPECT_EQ(r.program.moves[2].line, 6u);  // the corner arc belongs to the move that turns
}

TEST(CutterCompensation, TheDiameterMayComeWithTheCodeOrFromTheToolInTheSpindle) {
  const std::vector<Vec3> fromTable = ends(run(square("G41 D1"), withTools({{1, 2.0}})));
  const InterpretResult dynamic = run(square("G41.1 D2"));
  ASSERT_TRUE(dynamic.ok());
  const InterpretResult spindle = run("T1 M6\n" + square("G41"), withTools({{1, 2.0}}));
  ASSERT_TRUE(spindle.ok()) << spindle.errors.front().str();
  ASSERT_EQ(ends(dynamic).size(), fromTable.size());
  for (std::size_t i = 0; i < fromTable.size(); ++i) {
    expectNear(ends(dynamic)[i], fromTable[i]);
    expectNear(ends(spindle)[i], fromTable[i]);
  }
  // G41.1 D is in program units: D0.07874 inch is 2 mm.
  const InterpretResult inch = run("G20\nG0 X-0.3937 Y-0.3937\nF4\nG41.1 D0.0787402\nG1 X0 Y0\nG1 X0.7874 Y0\nG40\n");
  ASSERT_TRUE(inch.ok());
  expectNear(inch.program.moves[3].end, Vec3(20, 1, 0), 1e-4);
}

TEST(CutterCompensation, WithoutAToolTableThePathIsTheProgrammedOne) {
  const InterpretResult r = run(square("G41 D1"));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.program.warnings.empty());
  const std::vector<Vec3> e = ends(r);
  ASSERT_EQ(e.size(), 7u);
  expectNear(e[1], Vec3(0, 0, 0));
  expectNear(e[3], Vec3(20, 20, 0));
  // D0 is no tool, whatever the table says.
  EXPECT_EQ(ends(run(square("G41 D0"), withTools({{1, 2.0}}))).size(), 7u);
}

TEST(CutterCompensation, AnArcIsOffsetByTheRadiusOnTheToolsSide) {
  // A half circle of radius 10 about (10, 0), counter-clockwise: the tool on the left is inside.
  const std::string text = "G21 G17\nG0 X0 Y-10\nF100\nG41 D1\nG1 X0 Y0\nG3 X20 Y0 I10 J0\nG40\n";
  const InterpretResult left = run(text, withTools({{1, 2.0}}));
  ASSERT_TRUE(left.ok()) << left.errors.front().str();
  const Move& arc = left.program.moves.back();
  EXPECT_EQ(arc.kind, MoveKind::ArcCCW);
  expectNear(arc.centre, Vec3(10, 0, 0));
  expectNear(arc.end, Vec3(19, 0, 0));  // radius 9
  std::string right = text;
  right.replace(right.find("G41"), 3, "G42");
  expectNear(run(right, withTools({{1, 2.0}})).program.moves.back().end, Vec3(21, 0, 0), 1e-9);  // radius 11
}

TEST(CutterCompensation, APlungeAfterTheEntryMovesWithTheCornerItWaitsFor) {
  // The plunge has no motion in the plane: when the next corner is an inside one, it moves too.
  const InterpretResult r =
      run("G21 G17\nG0 X-10 Y1 Z5\nF100\nG41 D1\nG1 X0 Y0\nG1 Z-1\nG1 X0 Y20\nG40\n", withTools({{1, 2.0}}));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  const std::vector<Move>& m = r.program.moves;
  ASSERT_EQ(m.size(), 4u);
  EXPECT_NEAR(m[1].end.x(), m[2].end.x(), 1e-12);
  EXPECT_NEAR(m[1].end.y(), m[2].end.y(), 1e-12);
  EXPECT_NEAR(m[2].end.z(), -1, 1e-12);
  EXPECT_NEAR(m[3].end.x(), -1, 1e-12);  // the side runs left of x = 0
  EXPECT_NEAR(m[2].end.x(), -1, 1e-12);  // and the plunge was moved onto it with the corner
}

TEST(CutterCompensation, StreamingDeliversTheCornersAsTheWholeProgramHasThem) {
  struct Collect : MoveSink {
    std::vector<Move> moves;
    void consume(const Move* m, std::size_t n, std::uint64_t) override { moves.insert(moves.end(), m, m + n); }
  };
  const std::string text = "G21\nG0 X-10 Y1 Z5\nF100\nG41 D1\nG1 X0 Y0\nG1 Z-1\nG4 P0.5\nG1 Z-2\nG1 X0 Y20\n"
                           "G1 X20 Y20\nG2 X20 Y0 R10\nG1 X0 Y0\nG40\nG0 X-10\n";
  const InterpretResult whole = run(text, withTools({{1, 2.0}}));
  ASSERT_TRUE(whole.ok()) << whole.errors.front().str();
  for (std::size_t chunk : {1u, 2u, 3u}) {
    Collect sink;
    const StreamedInterpretation s = interpretGcodeStream(text, "t.ngc", sink, withTools({{1, 2.0}}), chunk);
    ASSERT_TRUE(s.ok());
    ASSERT_EQ(sink.moves.size(), whole.program.moves.size());
    for (std::size_t i = 0; i < sink.moves.size(); ++i) expectNear(sink.moves[i].end, whole.program.moves[i].end, 0);
  }
}

TEST(CutterCompensation, ARapidGoesAroundAnOutsideCornerInTwoStraightTraverses) {
  const InterpretResult r =
      run("G21\nG0 X-10 Y-10\nF100\nG41 D1\nG1 X0 Y0\nG0 X20 Y0\nG40\n", withTools({{1, 2.0}}));
  ASSERT_TRUE(r.ok());
  const std::vector<Move>& m = r.program.moves;
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[2].kind, MoveKind::Rapid);
  expectNear(m[2].end, Vec3(0, 1, 0));
  expectNear(m[3].end, Vec3(20, 1, 0));
}

TEST(CutterCompensation, WhereTheToolCannotFollowThePathTheBlockIsAnError) {
  const InterpreterOptions tools = withTools({{1, 2.0}, {2, 30.0}});
  auto error = [&](const std::string& text) {
    const InterpretResult r = run(text, tools);
    return r.errors.empty() ? std::string("<no error>") : r.errors.front().str();
  };
  EXPECT_NE(error("G21\nF100\nG41 D1\nG1 X0.5 Y0\n").find(
                "t.ngc:4:1: Length of cutter compensation entry move (0.5000 mm) is not greater than the tool radius"),
            std::string::npos);
  EXPECT_NE(error("G21\nG0 X-40 Y0\nF100\nG41 D2\nG1 X0 Y0\nG3 X20 Y0 I10 J0\n").find("t.ngc:6:1: Tool radius (15.0000 mm) not less than arc radius"),
            std::string::npos);
  // A side of 1 mm between two inside corners is shorter than a tool of radius 1 can turn in.
  EXPECT_NE(error("G21\nG0 X-10 Y-10\nF100\nG41 D1\nG1 X0 Y0\nG1 X20 Y0\nG1 X20 Y1\nG1 X0 Y1\n").find("too short for the tool"),
            std::string::npos);
  EXPECT_NE(error("G21\nF100\nG41 D5\n").find("t.ngc:3:5: Tool 5 is not in the tool table"), std::string::npos);
  EXPECT_NE(error("G21\nF100\nG41 D1\nG42 D1\n").find("t.ngc:4:1: Cannot turn cutter radius comp on when already on"),
            std::string::npos);
  EXPECT_NE(error("G21\nG0 X-10\nF100\nG41 D1\nG1 X0 Y0\nG18\n").find("t.ngc:6:1: Cannot change plane with cutter radius comp on"),
            std::string::npos);
  EXPECT_NE(error("G21\nG0 X-10\nF100\nG41 D1\nG1 X0 Y0\nG28\n").find("Cannot use G28 or G30 with cutter radius comp"),
            std::string::npos);
  EXPECT_NE(error("G21\nG19\nF100\nG41 D1\n").find("only possible in the XY (G17) and XZ (G18) planes"), std::string::npos);
  EXPECT_NE(error("G21\nF100\nG41 D1\nG3 X5 Y5 R5\n").find("entry move must be a straight move"), std::string::npos);
  EXPECT_NE(error("G21\nF100\nG41.1\n").find("need a D word"), std::string::npos);
  // With a radius of 0 nothing is offset, so nothing is refused.
  EXPECT_EQ(error("G21\nF100\nG41 D0\nG1 X0.5 Y0\nG40\n"), "<no error>");
}

TEST(CutterCompensation, ABadBlockSkippedWithKeepGoingLeavesTheCompensatedPathAsIfItWereNotThere) {
  InterpreterOptions tools = withTools({{1, 2.0}});
  const InterpretResult clean = run(square("G41 D1"), tools);
  tools.keepGoing = true;
  // The bad block makes a move (an inside corner that moves the open move's end) and then fails.
  std::string text = square("G41 D1");
  text.insert(text.find("G1 X20 Y20"), "G1 X20 Y20 I5\nG1 X5 Y30 J1\n");
  const InterpretResult skipped = run(text, tools);
  ASSERT_EQ(skipped.errors.size(), 2u);
  ASSERT_EQ(skipped.program.moves.size(), clean.program.moves.size());
  for (std::size_t i = 0; i < clean.program.moves.size(); ++i) expectNear(skipped.program.moves[i].end, clean.program.moves[i].end, 0);
}

TEST(CutterCompensation, ADwellStaysWhereTheToolIs) {
  const InterpretResult r =
      run("G21\nG0 X-10 Y-10\nF100\nG41 D1\nG1 X0 Y0\nG1 X20 Y0\nG4 P0.5\nG1 X20 Y20\nG40\n", withTools({{1, 2.0}}));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  const std::vector<Move>& m = r.program.moves;
  ASSERT_EQ(m[4].kind, MoveKind::Dwell);
  // The inside corner at (20, 0) moved the side's end, and the dwell with it.
  expectNear(m[3].end, Vec3(19, 1, 0));
  expectNear(m[4].end, Vec3(19, 1, 0));
  expectNear(m[5].end, Vec3(19, 20, 0));
}
