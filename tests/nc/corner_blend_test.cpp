// The generic control's corner blends: tangent arcs within the deviation asked, in any plane.
#include <gtest/gtest.h>

#include <cmath>

#include "corner_blend.h"

namespace isurface {
namespace {

const Vec3 kCorner(10, -4, 2);

TEST(cornerBlend, isTangentToBothLinesAndEndsAtItsReachFromTheCorner) {
  // Two directions that span no principal plane.
  const Vec3 in = Vec3(1, 0.2, -0.1).normalized(), out = Vec3(0.9, 0.5, 0.25).normalized();
  const double reach = 0.3;
  const auto blend = CornerBlend::at(kCorner, in, out, reach);
  ASSERT_TRUE(blend);
  EXPECT_LT((blend->start() - (kCorner - reach * in)).norm(), 1e-12);
  EXPECT_LT((blend->end() - (kCorner + reach * out)).norm(), 1e-12);
  EXPECT_LT((blend->tangentAt(0) - in).norm(), 1e-12);
  EXPECT_LT((blend->tangentAt(blend->length()) - out).norm(), 1e-12);
  // Every point at its radius from one centre, in one plane, at arc length s.
  const Vec3 mid = blend->at(0.5 * blend->length());
  const Vec3 q = blend->at(0.25 * blend->length());
  EXPECT_NEAR((q - blend->start()).norm(), 2 * blend->radius() * std::sin(0.125 * blend->length() / blend->radius()), 1e-12);
  EXPECT_NEAR(blend->normal().dot(mid - blend->start()), 0, 1e-12);
  EXPECT_NEAR((mid - kCorner).norm(), blend->deviation(), 1e-12);
}

TEST(cornerBlend, reachesAsFarAsTheDeviationOrTheLinesAllow) {
  const Vec3 in = Vec3::UnitX();
  const Vec3 out = Vec3(std::cos(0.2), std::sin(0.2), 0);
  const double deviation = 0.004;
  const double reach = CornerBlend::reachFor(in, out, deviation, 1.0);
  const auto blend = CornerBlend::at(kCorner, in, out, reach);
  ASSERT_TRUE(blend);
  EXPECT_NEAR(blend->deviation(), deviation, 1e-12);
  // Lines shorter than that reach: the blend takes what they give and passes nearer the corner.
  const double shorter = CornerBlend::reachFor(in, out, deviation, 0.5 * reach);
  EXPECT_DOUBLE_EQ(shorter, 0.5 * reach);
  EXPECT_LT(CornerBlend::at(kCorner, in, out, shorter)->deviation(), deviation);
}

TEST(cornerBlend, noneWhereTheLinesGoStraightOnOrTurnSharply) {
  const Vec3 in = Vec3::UnitX();
  EXPECT_EQ(CornerBlend::reachFor(in, in, 0.01, 1.0), 0.0);
  EXPECT_FALSE(CornerBlend::at(kCorner, in, in, 0.1));
  EXPECT_EQ(CornerBlend::reachFor(in, -in, 0.01, 1.0), 0.0);
  EXPECT_FALSE(CornerBlend::at(kCorner, in, -in, 0.1));
  const Vec3 rightAngle = Vec3::UnitY();
  EXPECT_EQ(CornerBlend::reachFor(in, rightAngle, 0.01, 1.0), 0.0);
  EXPECT_EQ(CornerBlend::reachFor(in, Vec3(1, 0.1, 0).normalized(), 0.0, 1.0), 0.0);
  EXPECT_EQ(CornerBlend::reachFor(in, Vec3(1, 0.1, 0).normalized(), 0.01, 0.0), 0.0);
}

TEST(cornerBlend, aShortenedLineKeepsItsDirectionAndLosesItsEnds) {
  PathSegment line;
  line.start = Vec3(0, 0, 0);
  line.end = Vec3(3, 4, 0);
  line.length = 5;
  line.direction = Vec3(0.6, 0.8, 0);
  const PathSegment cut = shortenedLine(line, 1.0, 1.5);
  EXPECT_DOUBLE_EQ(cut.length, 2.5);
  EXPECT_LT((cut.start - Vec3(0.6, 0.8, 0)).norm(), 1e-12);
  EXPECT_LT((cut.end - Vec3(2.1, 2.8, 0)).norm(), 1e-12);
  EXPECT_EQ(shortenedLine(line, 3.0, 3.0).length, 0.0);
}

}  // namespace
}  // namespace isurface
