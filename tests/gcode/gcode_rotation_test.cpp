// G68 / G69 coordinate rotation (Fanuc): hand-worked moves, and any program under G68 equals the
// same program turned afterwards.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gcode_test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

TEST(gcodeRotation, WordsAreReadInTheTurnedFrame) {
  const InterpretResult r = run(
      "G21 G90 G17 F100\nG0 X0 Y0\nG68 X10 Y0 R90\nG1 X20 Y0\nY5\nG91 X1\nG90 G2 X16 Y5 I-2.5 J0\nG69\nG1 X0 Y0\n");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  const std::vector<Move>& m = r.program.moves;
  ASSERT_EQ(m.size(), 6u);
  expectNear(m[1].end, Vec3(10, 10, 0));  // (20, 0) turned a quarter about (10, 0)
  expectNear(m[2].end, Vec3(5, 10, 0));   // Y5 keeps X20 of the turned frame
  expectNear(m[3].end, Vec3(5, 11, 0));   // G91 X1 runs along the turned X
  EXPECT_EQ(m[4].kind, MoveKind::ArcCW);
  expectNear(m[4].centre, Vec3(5, 8.5, 0));  // I turns with the frame
  expectNear(m[4].end, Vec3(5, 6, 0));
  expectNear(m[5].end, Vec3(0, 0, 0));  // after G69, as written
}

TEST(gcodeRotation, AProgramUnderG68IsTheSameProgramTurned) {
  const std::string body = "G1 X12 Y3 F300\nG3 X2 Y13 R10\nG91 G1 X-4 Y-2 Z-1\nG2 X6 Y0 I3 J0\nG90 G1 X0 Y0\n";
  const InterpretResult plain = run("G21 G17 G90\nG0 X0 Y0 Z0\n" + body);
  ASSERT_TRUE(plain.ok());
  for (const double degrees : {-135.0, 17.5, 90.0, 200.0}) {
    SCOPED_TRACE(degrees);
    const Vec3 pivot(3, -4, 0);
    const InterpretResult turned =
        run("G21 G17 G90\nG0 X0 Y0 Z0\nG68 X3 Y-4 R" + std::to_string(degrees) + "\n" + body);
    ASSERT_TRUE(turned.ok()) << turned.errors.front().str();
    ASSERT_EQ(turned.program.moves.size(), plain.program.moves.size());
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(degrees * kPi / 180, Vec3::UnitZ()).toRotationMatrix();
    // The first move (before G68) is not turned.
    for (std::size_t i = 1; i < plain.program.moves.size(); ++i) {
      const Move& a = plain.program.moves[i];
      const Move& b = turned.program.moves[i];
      expectNear(b.end, pivot + turn * (a.end - pivot), 1e-9);
      if (a.isArc()) expectNear(b.centre, pivot + turn * (a.centre - pivot), 1e-9);
      EXPECT_EQ(a.kind, b.kind);
    }
  }
}

TEST(gcodeRotation, IncrementalRAddsToTheRotationAndMistakesAreErrors) {
  const InterpretResult r = run("G21 G17 F100\nG68 X0 Y0 R30\nG91 G68 R60\nG90 G1 X10 Y0\n");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  expectNear(r.program.moves.back().end, Vec3(0, 10, 0), 1e-9);
  EXPECT_EQ(firstError("G21 G17\nG68 X1 Y1\n"), "t.ngc:2:1: G68 needs an R word: the angle of rotation, in degrees");
  EXPECT_EQ(firstError("G21 G17\nG68 R30 Z1\n"), "t.ngc:2:9: Z word with G68: the centre of rotation is in the plane");
  EXPECT_EQ(firstError("G21 G17 F100\nG68 R30\nG81 X1 Y1 Z-1 R1\n"),
            "t.ngc:3:1: Canned cycles under G68 coordinate rotation are not supported");
}
