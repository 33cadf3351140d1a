// The curve the generic control runs through CAM chords (chord_spline.h, chord_run.h): it has
// the circle's tangent and curvature at its points, passes within micrometres of the curve the
// chords sample, is straight between straight ends, and is fitted through points rounded to a
// program's four decimals without their noise.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "chord_run.h"
#include "chord_spline.h"

using namespace isurface;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 onCircle(double radius, double angle) { return Vec3(radius * std::cos(angle), radius * std::sin(angle), 0); }

double rounded(double v) { return std::round(v * 1e4) / 1e4; }

// Chords of `length` mm along a circle of `radius` mm, their points rounded to 0.1 um as a
// program writes them, fitted as one run; the chords' curves, in order.
std::vector<FittedChord> fittedCircle(double radius, double length, int chords) {
  ChordRun run(0.004);
  std::vector<FittedChord> out;
  Vec3 start = onCircle(radius, 0);
  for (int k = 1; k <= chords; ++k) {
    const Vec3 exact = onCircle(radius, k * length / radius);
    const Vec3 end(rounded(exact.x()), rounded(exact.y()), 0);
    Move move;
    move.end = end;
    move.feed = 3000;
    run.push(static_cast<std::uint32_t>(k), move, PathSegment::from(start, move));
    run.take(out);
    start = end;
  }
  run.end();
  run.take(out);
  return out;
}

}  // namespace

TEST(chordKnot, IsTheCircleThroughThePointAndItsNeighbours) {
  const double r = 7.0;
  const ChordKnot k = ChordKnot::through(onCircle(r, 0.1), onCircle(r, 0.2), onCircle(r, 0.35));
  EXPECT_NEAR(k.curvature.norm(), 1.0 / r, 1e-9);
  EXPECT_LT((k.curvature.normalized() + onCircle(1.0, 0.2)).norm(), 1e-9) << "towards the centre";
  EXPECT_NEAR(k.tangent.dot(Vec3(-std::sin(0.2), std::cos(0.2), 0)), 1.0, 1e-12) << "along the travel";
  const ChordKnot straight = ChordKnot::through(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2));
  EXPECT_EQ(straight.curvature, Vec3::Zero());
  EXPECT_NEAR(straight.tangent.dot(Vec3(1, 1, 1).normalized()), 1.0, 1e-12);
}

TEST(chordSpline, FollowsTheCircleItsKnotsComeFrom) {
  const double r = 5.0, a0 = 0.3, a1 = 0.42;  // a chord of 0.6 mm
  const ChordKnot k0 = ChordKnot::through(onCircle(r, a0 - 0.1), onCircle(r, a0), onCircle(r, a1));
  const ChordKnot k1 = ChordKnot::through(onCircle(r, a0), onCircle(r, a1), onCircle(r, a1 + 0.1));
  const ChordSpline curve(onCircle(r, a0), k0, onCircle(r, a1), k1);
  EXPECT_NEAR(curve.length(), r * (a1 - a0), 1e-6);
  EXPECT_NEAR(curve.shape().largestCurvature, 1.0 / r, 0.01 / r);
  EXPECT_TRUE(curve.shape().wellFormed);
  for (double s = 0; s <= curve.length(); s += curve.length() / 50) {
    EXPECT_NEAR(curve.at(s).norm(), r, 2e-7) << s;
    // Arc length: the point s along lies at the angle s / r.
    EXPECT_NEAR(std::atan2(curve.at(s).y(), curve.at(s).x()), a0 + s / r, 2e-6) << s;
  }
  // The sagitta of the chord: the curve bows out of it as the circle does.
  EXPECT_NEAR(curve.farthestFrom(onCircle(r, a0), onCircle(r, a1)), r * (1 - std::cos(0.5 * (a1 - a0))), 1e-6);
}

TEST(chordSpline, IsStraightBetweenStraightEnds) {
  const Vec3 a(1, 2, 3), b(1.3, 2.4, 2.9);
  const ChordSpline line(a, ChordKnot::straight(a, b), b, ChordKnot::straight(a, b));
  EXPECT_NEAR(line.length(), (b - a).norm(), 1e-12);
  EXPECT_LT(line.farthestFrom(a, b), 1e-12);
  EXPECT_LT(line.shape().largestCurvature, 1e-9);
  EXPECT_LT((line.at(0.5 * line.length()) - 0.5 * (a + b)).norm(), 1e-12);
}

TEST(chordSpline, KnotsThatTurnBackMakeNoCurve) {
  // Ends whose directions run against the chord: the quintic would loop.
  ChordKnot back;
  back.tangent = Vec3(-1, 0, 0);
  ChordKnot ahead;
  ahead.tangent = Vec3(1, 0, 0);
  EXPECT_FALSE(ChordSpline(Vec3::Zero(), back, Vec3(0.5, 0, 0), ahead).shape().wellFormed);
}

TEST(chordRun, FitsRoundedPointsWithoutTheirNoise) {
  // Chords of 0.05 mm on a circle of 18 mm rounded to 0.1 um: the circle through three of the
  // points is off by a third of the curvature at places; the fitted curve is not.
  const double r = 18.0, h = 0.05;
  const std::vector<FittedChord> chords = fittedCircle(r, h, 400);
  ASSERT_EQ(chords.size(), 400u);
  double worstThreePoint = 0, worstFitted = 0;
  for (std::size_t k = 1; k + 1 < chords.size(); ++k) {
    ASSERT_TRUE(chords[k].start && chords[k].end) << k;
    const double threePoint =
        ChordKnot::through(chords[k - 1].seg.start, chords[k].seg.start, chords[k].seg.end).curvature.norm();
    worstThreePoint = std::max(worstThreePoint, std::abs(threePoint * r - 1));
    if (k > 20 && k + 20 < chords.size())
      worstFitted = std::max(worstFitted, std::abs(chords[k].start->knot.curvature.norm() * r - 1));
  }
  EXPECT_GT(worstThreePoint, 0.3);
  EXPECT_LT(worstFitted, 0.05);
  // One curve: each chord's curve starts where the one before ends, the run's ends are its
  // points, straight along their chords.
  for (std::size_t k = 1; k < chords.size(); ++k) {
    const Vec3 end = chords[k - 1].seg.end + chords[k - 1].end->offset;
    const Vec3 start = chords[k].seg.start + chords[k].start->offset;
    EXPECT_EQ(end, start) << k;
    EXPECT_EQ(chords[k - 1].end->knot.tangent, chords[k].start->knot.tangent) << k;
  }
  EXPECT_EQ(chords.front().start->offset, Vec3::Zero());
  EXPECT_EQ(chords.back().end->offset, Vec3::Zero());
  EXPECT_EQ(chords.back().end->knot.curvature, Vec3::Zero());
}

TEST(chordRun, ALoneChordIsItsLine) {
  const std::vector<FittedChord> chords = fittedCircle(10.0, 0.5, 1);
  ASSERT_EQ(chords.size(), 1u);
  EXPECT_FALSE(chords[0].start.has_value());
  EXPECT_FALSE(chords[0].end.has_value());
}

TEST(chordRun, PackedEndsGiveTheSameCurve) {
  const std::vector<FittedChord> chords = fittedCircle(6.0, 0.4, 30);
  const FittedChord& c = chords[10];
  const std::array<float, 18> packed = packCurve(*c.start, *c.end);
  const CurveEnd start = unpackCurveEnd(packed, false), end = unpackCurveEnd(packed, true);
  EXPECT_LT((start.knot.tangent - c.start->knot.tangent).norm(), 1e-6);
  EXPECT_LT((end.knot.curvature - c.end->knot.curvature).norm(), 1e-6);
  EXPECT_LT((end.offset - c.end->offset).norm(), 1e-9);
  const ChordSpline curve = curveOf(c.seg, packed);
  EXPECT_NEAR(curve.at(0.5 * curve.length()).norm(), 6.0, 1e-4);
}
