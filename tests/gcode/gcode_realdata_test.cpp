// Real CAM output from shared/realdata/: every file interprets cleanly, with known facts checked.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isurface/gcode/arc.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "test_support.h"

using namespace isurface;

namespace {

InterpretResult load(const std::string& name) {
  InterpretResult r = interpretGcodeFile(test::realdataPath(name));
  EXPECT_TRUE(r.ok()) << name << ": " << (r.errors.empty() ? "" : r.errors[0].str());
  EXPECT_TRUE(r.program.warnings.empty()) << name << ": " << r.program.warnings[0].str();
  return r;
}

std::size_t countArcs(const Program& p) {
  std::size_t n = 0;
  for (const Move& m : p.moves) n += m.isArc() ? 1 : 0;
  return n;
}

// Largest difference between an arc's start and end radius, mm.
double worstRadiusMismatch(const Program& p) {
  double worst = 0;
  for (std::size_t i = 0; i < p.moves.size(); ++i) {
    if (!p.moves[i].isArc()) continue;
    const ArcGeometry g = ArcGeometry::from(p.startOf(i), p.moves[i]);
    worst = std::max(worst, std::abs(g.startRadius - g.endRadius));
  }
  return worst;
}

}  // namespace

#define REQUIRE_REALDATA(name) ISURFACE_SKIP_WITHOUT_REALDATA(test::realdataPath(name))

TEST(gcodeRealdata, Cameo) {
  REQUIRE_REALDATA("cameo.nc");
  const InterpretResult r = load("cameo.nc");
  const Program& p = r.program;
  EXPECT_EQ(p.lineCount, 35288u);
  ASSERT_GT(p.moves.size(), 35000u);
  EXPECT_EQ(countArcs(p), 0u);
  // The first feed move is block N5 (physical line 6: the file opens with a blank line):
  // "N5 G01 Z-6. F300".
  std::size_t first = 0;
  while (first < p.moves.size() && p.moves[first].kind != MoveKind::Linear) ++first;
  ASSERT_LT(first, p.moves.size());
  const Move& m = p.moves[first];
  EXPECT_EQ(m.line, 6u);
  EXPECT_EQ(m.end, Vec3(-75, -93.703, -6));
  EXPECT_FLOAT_EQ(m.feed, 300.0f);
  // "N6 X75." continues G1.
  EXPECT_EQ(p.moves[first + 1].end, Vec3(75, -93.703, -6));
  EXPECT_EQ(p.moves[first + 1].line, 7u);
  // "N35285 M05": the spindle stops after the last move, a rapid up to Z2.
  EXPECT_EQ(p.moves.back().end.z(), 2);
  EXPECT_EQ(p.moves.back().flags & kStopAfter, kStopAfter);
}

TEST(gcodeRealdata, Communicator) {
  REQUIRE_REALDATA("communicator.nc");
  const InterpretResult r = load("communicator.nc");
  const Program& p = r.program;
  EXPECT_EQ(p.lineCount, 7221u);
  const std::size_t arcs = countArcs(p);
  EXPECT_GT(arcs, 4200u);
  EXPECT_LT(arcs, 4400u);
  EXPECT_LT(worstRadiusMismatch(p), 0.001);  // CamBam's 4 decimals
  // Line 14: "G2 X0.5411 Y26.0931 I0.1247 J0.0689" from (0.5567, 26.0488).
  bool found = false;
  for (const Move& m : p.moves) {
    if (m.line != 14) continue;
    found = true;
    EXPECT_EQ(m.kind, MoveKind::ArcCW);
    EXPECT_NEAR(m.centre.x(), 0.5567 + 0.1247, 1e-12);
    EXPECT_NEAR(m.centre.y(), 26.0488 + 0.0689, 1e-12);
    EXPECT_NEAR(m.centre.z(), -1.0, 1e-12);
    EXPECT_FLOAT_EQ(m.feed, 2000.0f);
  }
  EXPECT_TRUE(found);
}

TEST(gcodeRealdata, Stellabee) {
  REQUIRE_REALDATA("stellabee1.ngc");
  const InterpretResult r = load("stellabee1.ngc");
  const Program& p = r.program;
  EXPECT_EQ(p.lineCount, 169220u);
  ASSERT_GT(p.moves.size(), 169000u);
  // Inch: "G0 Z0.0120" on line 2.
  EXPECT_EQ(p.moves[0].line, 2u);
  EXPECT_NEAR(p.moves[0].end.z(), 0.012 * 25.4, 1e-12);
  // "G0 X3.3390 Y4.8580" then the first arc, in G18, keeps the pass's Y.
  EXPECT_NEAR(p.moves[1].end.x(), 3.339 * 25.4, 1e-12);
  std::size_t arcs = 0;
  for (const Move& m : p.moves) {
    if (!m.isArc()) continue;
    ++arcs;
    EXPECT_EQ(m.plane, Plane::ZX);
    if (m.plane != Plane::ZX) break;
  }
  EXPECT_GT(arcs, 9000u);
  const Move* firstArc = nullptr;
  for (const Move& m : p.moves)
    if (m.isArc()) { firstArc = &m; break; }
  ASSERT_NE(firstArc, nullptr);
  EXPECT_EQ(firstArc->line, 13u);
  EXPECT_NEAR(firstArc->centre.y(), 4.858 * 25.4, 1e-9);
  EXPECT_NEAR(firstArc->feed, 999 * 25.4, 0.01);
  // The worst end-radius mismatch is a few microns: well inside LinuxCNC's tolerance.
  EXPECT_LT(worstRadiusMismatch(p), 0.01);
}

TEST(gcodeRealdata, LinuxcncTest) {
  REQUIRE_REALDATA("linuxcnc_test.ngc");
  const InterpretResult r = load("linuxcnc_test.ngc");
  const Program& p = r.program;
  EXPECT_EQ(countArcs(p), 6u);
  // The full circle "G2 X80 Y0 I-10 J0" and the helix "G3 X70 Y-10 Z-1 I-10 J0".
  const Move* circle = nullptr;
  const Move* helix = nullptr;
  for (std::size_t i = 0; i < p.moves.size(); ++i) {
    const Move& m = p.moves[i];
    if (!m.isArc()) continue;
    if (m.end == p.startOf(i)) circle = &m;
    if (m.end.z() == -1) helix = &m;
  }
  ASSERT_NE(circle, nullptr);
  EXPECT_EQ(circle->centre, Vec3(70, 0, 0));
  ASSERT_NE(helix, nullptr);
  EXPECT_EQ(helix->kind, MoveKind::ArcCCW);
  EXPECT_EQ(helix->centre, Vec3(70, 0, 0));
  EXPECT_EQ(p.moves.back().line, 258u);  // "G0 X0 Y0" before M2
}
