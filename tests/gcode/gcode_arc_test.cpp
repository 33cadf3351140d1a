// Arcs: centre and radius formats in the three planes, full circles, helices, turns, tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isurface/gcode/arc.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "gcode_test_support.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

// The last move of a program that must interpret cleanly.
Move lastMove(const std::string& text, Vec3* start = nullptr) {
  const InterpretResult r = run(text);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].str());
  if (r.program.moves.empty()) return Move{};
  if (start) *start = r.program.startOf(r.program.moves.size() - 1);
  return r.program.moves.back();
}

// The point halfway along the arc.
Vec3 midpoint(const std::string& text) {
  Vec3 start;
  const Move m = lastMove(text, &start);
  return ArcGeometry::from(start, m).at(0.5);
}

}  // namespace

TEST(gcodeArc, CentreFormatXY) {
  Vec3 start;
  const Move m = lastMove("G0 X0 Y0\nG2 X10 Y0 I5 J0 F100\n", &start);
  EXPECT_EQ(m.kind, MoveKind::ArcCW);
  EXPECT_EQ(m.plane, Plane::XY);
  EXPECT_EQ(m.turns, 1);
  EXPECT_EQ(m.line, 2u);
  EXPECT_FLOAT_EQ(m.feed, 100.0f);
  expectNear(m.centre, Vec3(5, 0, 0));
  expectNear(m.end, Vec3(10, 0, 0));
  // Clockwise from the left of the centre goes over the top.
  expectNear(ArcGeometry::from(start, m).at(0.5), Vec3(5, 5, 0));
  expectNear(midpoint("G0 X0 Y0\nG3 X10 Y0 I5 J0 F100\n"), Vec3(5, -5, 0));
}

TEST(gcodeArc, CentreFormatXZ) {
  // G18: the plane's axes are Z then X; offsets K and I; the centre keeps the start's Y.
  const Move m = lastMove("G18 G0 X0 Y7 Z0\nG3 X10 Z0 I5 K0 F100\n");
  EXPECT_EQ(m.plane, Plane::ZX);
  EXPECT_EQ(m.kind, MoveKind::ArcCCW);
  expectNear(m.centre, Vec3(5, 7, 0));
  // Counter-clockwise about +Y turns Z towards X: from X0 it passes Z+5.
  expectNear(midpoint("G18 G0 X0 Y7 Z0\nG3 X10 Z0 I5 K0 F100\n"), Vec3(5, 7, 5));
  expectNear(midpoint("G18 G0 X0 Y7 Z0\nG2 X10 Z0 I5 F100\n"), Vec3(5, 7, -5));
}

TEST(gcodeArc, CentreFormatYZ) {
  const Move m = lastMove("G19 G0 X3 Y0 Z0\nG2 Y10 Z0 J5 K0 F100\n");
  EXPECT_EQ(m.plane, Plane::YZ);
  expectNear(m.centre, Vec3(3, 5, 0));
  expectNear(midpoint("G19 G0 X3 Y0 Z0\nG2 Y10 Z0 J5 K0 F100\n"), Vec3(3, 5, 5));
  expectNear(midpoint("G19 G0 X3 Y0 Z0\nG3 Y10 J5 F100\n"), Vec3(3, 5, -5));
}

TEST(gcodeArc, PlaneNormalOffsetIsAnError) {
  EXPECT_EQ(firstError("G2 X1 Y1 I1 K1 F100\n"), "t.ngc:1:13: k word given for arc in XY plane");
  EXPECT_EQ(firstError("G18 G2 X1 Z1 J1 F100\n"), "t.ngc:1:14: j word given for arc in XZ plane");
  EXPECT_EQ(firstError("G19 G2 Y1 Z1 I1 F100\n"), "t.ngc:1:14: i word given for arc in YZ plane");
}

TEST(gcodeArc, RadiusFormat) {
  const double h = std::sqrt(100.0 - 25.0);
  // Positive R: the shorter arc. G2 puts the centre right of the chord.
  Vec3 start;
  Move m = lastMove("G0 X0 Y0\nG2 X10 Y0 R10 F100\n", &start);
  expectNear(m.centre, Vec3(5, -h, 0));
  EXPECT_NEAR(std::abs(ArcGeometry::from(start, m).sweep), 2 * std::asin(0.5), 1e-12);
  m = lastMove("G0 X0 Y0\nG3 X10 Y0 R10 F100\n");
  expectNear(m.centre, Vec3(5, h, 0));
  // Negative R: more than half a circle.
  m = lastMove("G0 X0 Y0\nG2 X10 Y0 R-10 F100\n", &start);
  expectNear(m.centre, Vec3(5, h, 0));
  EXPECT_NEAR(ArcGeometry::from(start, m).sweep, -(2 * M_PI - 2 * std::asin(0.5)), 1e-12);
  // A semicircle, and one whose radius is a hair short of it (taken as a semicircle).
  expectNear(lastMove("G0 X0 Y0\nG2 X10 Y0 R5 F100\n").centre, Vec3(5, 0, 0), 1e-6);
  expectNear(lastMove("G0 X0 Y0\nG2 X10 Y0 R4.9995 F100\n").centre, Vec3(5, 0, 0), 1e-6);
  // In other planes.
  m = lastMove("G18 G0 X0 Y2 Z0\nG2 X10 R5 F100\n");
  expectNear(m.centre, Vec3(5, 2, 0), 1e-6);
}

TEST(gcodeArc, RadiusFormatErrors) {
  EXPECT_EQ(firstError("G0 X0 Y0\nG2 X10 Y0 R4 F100\n"),
            "t.ngc:2:11: Arc radius too small to reach end point");
  EXPECT_EQ(firstError("G0 X0 Y0\nG2 X0 Y0 R5 F100\n"),
            "t.ngc:2:10: Current point same as end point of arc");
  EXPECT_EQ(firstError("G2 X10 Y0 I5 R5 F100\n"), "t.ngc:1:14: Mixed radius-ijk format for arc");
  EXPECT_EQ(firstError("G2 X10 Y0 F100\n"), "t.ngc:1:1: R, I or J word missing for arc in XY plane");
  EXPECT_EQ(firstError("G18 G2 X10 F100\n"),
            "t.ngc:1:5: R, I or K word missing for arc in XZ plane");
  // Without an end point, a radius does not say which circle (a centre does: a full circle).
  EXPECT_EQ(firstError("G2 Z-1 R5 F100\n"), "t.ngc:1:1: X and Y words missing for arc in XY plane");
  EXPECT_EQ(firstError("G19 G3 X1 R5 F100\n"),
            "t.ngc:1:5: Y and Z words missing for arc in YZ plane");
}

TEST(gcodeArc, ACentreWithoutAnEndPointIsAFullCircle) {
  // As rs274 reads `G2 I.5 J.5`: ARC_FEED(1, 0, 1.5, 0.5, -1, 0) from (1, 0).
  Vec3 start;
  Move m = lastMove("G0 X1 Y0\nG2 I.5 J.5 F100\n", &start);
  expectNear(m.end, start);
  expectNear(m.centre, Vec3(1.5, 0.5, 0));
  EXPECT_NEAR(ArcGeometry::from(start, m).sweep, -2 * M_PI, 1e-12);
  // A helix: one turn down to Z-1 about (6, 0).
  m = lastMove("G0 X1 Y0\nG2 Z-1 I5 F100\n", &start);
  expectNear(m.end, Vec3(1, 0, -1));
  expectNear(m.centre, Vec3(6, 0, 0));
}

TEST(gcodeArc, FullCircleHelixAndTurns) {
  Vec3 start;
  Move m = lastMove("G0 X10 Y0\nG3 X10 Y0 I-10 J0 F100\n", &start);
  expectNear(m.centre, Vec3(0, 0, 0));
  EXPECT_NEAR(ArcGeometry::from(start, m).sweep, 2 * M_PI, 1e-12);

  // Helix: the end leaves the plane; the centre keeps the start's Z.
  m = lastMove("G0 X10 Y0 Z1\nG3 X-10 Y0 Z-2 I-10 J0 F100\n", &start);
  expectNear(m.centre, Vec3(0, 0, 1));
  expectNear(m.end, Vec3(-10, 0, -2));
  const ArcGeometry g = ArcGeometry::from(start, m);
  EXPECT_NEAR(g.length(), std::hypot(10 * M_PI, 3.0), 1e-9);

  // P: number of turns.
  m = lastMove("G0 X10\nG2 X10 Y0 Z-3 I-10 P3 F100\n", &start);
  EXPECT_EQ(m.turns, 3);
  EXPECT_NEAR(ArcGeometry::from(start, m).sweep, -6 * M_PI, 1e-9);
  EXPECT_EQ(firstError("G2 X1 I1 P1.5 F100\n"), "t.ngc:1:10: P value not an integer with G2 or G3");
  EXPECT_EQ(firstError("G2 X1 I1 P0 F100\n"), "t.ngc:1:10: P value must be at least 1 with G2 or G3");
}

TEST(gcodeArc, RadiusMismatchTolerance) {
  // 0.01 mm off: accepted (LinuxCNC accepts up to 0.0283 mm).
  Move m = lastMove("G0 X10 Y0\nG3 X0 Y10.01 I-10 J0 F100\n");
  expectNear(m.centre, Vec3(0, 0, 0));
  // On a large radius a relative error under 0.1% is accepted too.
  lastMove("G0 X100 Y0\nG3 X0 Y100.05 I-100 J0 F100\n");
  // Gross mismatches are errors, with LinuxCNC's message.
  EXPECT_EQ(firstError("G0 X1 Y0\nG2 X14 Y0 I-1 J0 F100\n"),
            "t.ngc:2:1: Radius to end of arc differs from radius to start: start=(X1.0000,Y0.0000) "
            "center=(X0.0000,Y0.0000) end=(X14.0000,Y0.0000) r1=1.0000 r2=14.0000 abs_err=13 "
            "rel_err=92.8571%");
  EXPECT_NE(firstError("G0 X100 Y0\nG3 X0 Y100.5 I-100 J0 F100\n").find("differs"), std::string::npos);
  // In other planes the message names their axes.
  EXPECT_NE(firstError("G18 G0 X1\nG2 X3 I-1 F100\n")
                .find("start=(Z0.0000,X1.0000) center=(Z0.0000,X0.0000) end=(Z0.0000,X3.0000)"),
            std::string::npos);
  // Inch programs get LinuxCNC's inch tolerance (0.002828 inch).
  EXPECT_NE(firstError("G0 X1 Y0\nG3 X0 Y1.05 I-1 F100\n").find("differs"), std::string::npos);
  lastMove("G20 G0 X0.03937 Y0\nG3 X0 Y0.04134 I-0.03937 F100\n");  // 0.05 mm off, in inch
  // A zero radius is an error.
  EXPECT_EQ(firstError("G2 X0 Y0 I0 J0 F100\n").substr(0, 26), "t.ngc:1:1: Zero-radius arc");
}

TEST(gcodeArc, ModalArcLines) {
  // Coordinate-only lines continue G2/G3 with their own centre words.
  const InterpretResult r = run("G0 X10 Y0\nG3 X0 Y10 I-10 F100\nX-10 Y0 J-10\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_EQ(r.program.moves[2].kind, MoveKind::ArcCCW);
  expectNear(r.program.moves[2].centre, Vec3(0, 0, 0));
}

TEST(gcodeArc, ArcFeedErrors) {
  EXPECT_EQ(firstError("G2 X10 Y0 I5\n"), "t.ngc:1:1: Cannot make arc with zero feed rate");
}

TEST(gcodeArc, InchArcWithConstantYInXZ) {
  // As in stellabee1.ngc: G18 arcs that also carry the pass's Y.
  const Move m =
      lastMove("G20\nG18\nF999.0000\nG0 X3.3390 Y4.8580\nG1 Z-0.0319\nG3 X3.214000 Z-0.156892 R0.125000\n"
               "G3 X3.234 Y4.8580 Z-0.136892 I0 K0.02\n");
  EXPECT_EQ(m.plane, Plane::ZX);
  EXPECT_NEAR(m.centre.y(), 4.858 * 25.4, 1e-9);
  EXPECT_NEAR(m.feed, 999 * 25.4, 1e-2);
}
