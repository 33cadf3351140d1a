// Akima spline in the chord-length parameter (equations 2-6), batch and incremental.
#include "isurface/fitting/akima_spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace isurface {
namespace {

// Points along a 3D curve with uneven spacing, a kink in curvature and a straight stretch.
std::vector<Vec3> samplePoints() {
  std::vector<Vec3> p;
  for (int i = 0; i < 12; ++i) {
    const double t = 0.45 * i + 0.05 * (i % 3);
    p.push_back(Vec3(5 * std::cos(t), 5 * std::sin(t), 0.3 * t));
  }
  for (int i = 1; i <= 4; ++i) p.push_back(p.back() + Vec3(0.8, -0.2, 0.1));
  return p;
}

// Eq. 5 written out directly, independent of the library, for one point of a 3D sequence.
Vec3 directTangent(const std::vector<Vec3>& p, long i) {
  const long n = static_cast<long>(p.size());
  std::vector<Vec3> m;  // m[k + 2] = m_k, k = -2 .. n
  m.resize(n + 3);
  for (long k = 0; k + 1 < n; ++k) {
    const Vec3 d = p[k + 1] - p[k];
    m[k + 2] = d / d.norm();
  }
  m[1] = 2 * m[2] - m[3];
  m[0] = 2 * m[1] - m[2];
  m[n + 1] = 2 * m[n] - m[n - 1];
  m[n + 2] = 2 * m[n + 1] - m[n];
  Vec3 s;
  for (int a = 0; a < 3; ++a) {
    const double mm2 = m[i][a], mm1 = m[i + 1][a], m0 = m[i + 2][a], mp1 = m[i + 3][a];
    const double wA = std::abs(mp1 - m0), wB = std::abs(mm1 - mm2);
    s[a] = wA + wB == 0 ? (mm1 + m0) / 2 : (wA * mm1 + wB * m0) / (wA + wB);
  }
  return s;
}

TEST(akimaSpline, interpolatesEveryPointAndIsG1) {
  const std::vector<Vec3> p = samplePoints();
  const PiecewiseCubicCurve c = fitAkimaSpline(p);
  const auto& seg = c.segments();
  ASSERT_EQ(seg.size(), p.size() - 1);
  for (std::size_t i = 0; i < seg.size(); ++i) {
    EXPECT_LE((seg[i].position(0) - p[i]).norm(), 1e-12) << i;
    EXPECT_LE((seg[i].endPoint() - p[i + 1]).norm(), 1e-12) << i;
    EXPECT_NEAR(seg[i].length, (p[i + 1] - p[i]).norm(), 1e-15);
  }
  for (std::size_t i = 0; i + 1 < seg.size(); ++i) {
    EXPECT_LE((seg[i].endPoint() - seg[i + 1].position(0)).norm(), 1e-12) << i;
    EXPECT_LE((seg[i].derivative(seg[i].length) - seg[i + 1].derivative(0)).norm(), 1e-9) << i;
    EXPECT_NEAR(seg[i].start + seg[i].length, seg[i + 1].start, 1e-12);
  }
}

TEST(akimaSpline, derivativeAtDataPointsIsEquationFive) {
  const std::vector<Vec3> p = samplePoints();
  const PiecewiseCubicCurve c = fitAkimaSpline(p);
  double l = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i > 0) l += (p[i] - p[i - 1]).norm();
    const Vec3 s = directTangent(p, static_cast<long>(i));
    // At an interior point the spline's derivative comes from the segment starting there.
    const Vec3 d = i + 1 < p.size() ? c.segments()[i].derivative(0) : c.segments().back().derivative(c.segments().back().length);
    EXPECT_LE((d - s).norm(), 1e-9) << i;
    EXPECT_LE((c.position(l) - p[i]).norm(), 1e-12) << i;
  }
}

TEST(akimaSpline, incrementalEqualsBatchAndEmitsOnceEndTangentIsKnown) {
  const std::vector<Vec3> p = samplePoints();
  IncrementalAkimaFitter fitter;
  std::vector<CubicSegment> emitted;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto s = fitter.add(p[i]);
    // Segment i - 3 completes with point i (its end tangent needs two points beyond its end).
    EXPECT_EQ(s.has_value(), i >= 3) << i;
    if (s) emitted.push_back(*s);
  }
  for (const CubicSegment& s : fitter.finish()) emitted.push_back(s);
  const PiecewiseCubicCurve batchCurve = fitAkimaSpline(p);
  const auto& batch = batchCurve.segments();
  ASSERT_EQ(emitted.size(), batch.size());
  ASSERT_EQ(fitter.segments().size(), batch.size());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    EXPECT_NEAR(emitted[i].start, batch[i].start, 1e-12);
    EXPECT_LE((emitted[i].a - batch[i].a).norm(), 1e-12);
    EXPECT_LE((emitted[i].b - batch[i].b).norm(), 1e-12);
    EXPECT_LE((emitted[i].c - batch[i].c).norm(), 1e-11);
    EXPECT_LE((emitted[i].d - batch[i].d).norm(), 1e-11);
  }
  // The start tangent of each segment is exactly the previous one's end tangent, reused.
  for (std::size_t i = 0; i + 1 < emitted.size(); ++i)
    EXPECT_LE((emitted[i].derivative(emitted[i].length) - emitted[i + 1].b).norm(), 1e-12);
}

TEST(akimaSpline, straightLineStaysStraight) {
  std::vector<Vec3> p;
  for (double x : {0.0, 0.5, 2.0, 2.2, 5.0, 7.5}) p.push_back(Vec3(1, 2, 3) + x * Vec3(2, -1, 2) / 3.0);
  const PiecewiseCubicCurve c = fitAkimaSpline(p);
  for (double l = 0; l <= c.parameterLength(); l += 0.05) {
    const Vec3 q = c.position(l) - Vec3(1, 2, 3);
    EXPECT_LE(q.cross(Vec3(2, -1, 2) / 3.0).norm(), 1e-12);
    EXPECT_NEAR(c.curvature(l), 0.0, 1e-9);
  }
  EXPECT_NEAR(c.arcLength(), 7.5, 1e-12);
  EXPECT_EQ(c.resample(0.001).size(), p.size());  // no subdivision needed
}

TEST(akimaSpline, duplicatesTwoAndThreePoints) {
  EXPECT_TRUE(fitAkimaSpline({}).empty());
  EXPECT_TRUE(fitAkimaSpline({Vec3(1, 1, 1), Vec3(1, 1, 1)}).empty());
  const PiecewiseCubicCurve two = fitAkimaSpline({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(3, 4, 0)});
  ASSERT_EQ(two.segments().size(), 1u);
  EXPECT_LE((two.position(2.5) - Vec3(1.5, 2, 0)).norm(), 1e-12);
  const std::vector<Vec3> three = {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 0), Vec3(2, 0, 0)};
  const PiecewiseCubicCurve c = fitAkimaSpline(three);
  ASSERT_EQ(c.segments().size(), 2u);
  EXPECT_LE((c.position(std::sqrt(2.0)) - Vec3(1, 1, 0)).norm(), 1e-12);
  // Symmetric data: the tangent at the apex is horizontal.
  EXPECT_NEAR(c.segments()[1].b.y(), 0.0, 1e-12);
  IncrementalAkimaFitter fitter;
  for (const Vec3& q : three) EXPECT_FALSE(fitter.add(q).has_value());
  EXPECT_EQ(fitter.finish().size(), 2u);
  for (int i = 0; i < 2; ++i)
    EXPECT_LE((fitter.segments()[i].c - c.segments()[i].c).norm(), 1e-12);
}

TEST(akimaSpline, resamplingStaysWithinTolerance) {
  const std::vector<Vec3> p = samplePoints();
  const PiecewiseCubicCurve c = fitAkimaSpline(p);
  for (double tolerance : {0.01, 0.001}) {
    const std::vector<Vec3> q = c.resample(tolerance);
    ASSERT_GE(q.size(), p.size());
    EXPECT_LE((q.front() - p.front()).norm(), 1e-12);
    EXPECT_LE((q.back() - p.back()).norm(), 1e-12);
    // Densely along the spline, the distance to the resampled polyline stays within tolerance.
    double worst = 0;
    for (double l = 0; l <= c.parameterLength(); l += c.parameterLength() / 20000) {
      const Vec3 x = c.position(l);
      double best = 1e9;
      for (std::size_t k = 0; k + 1 < q.size(); ++k) {
        const Vec3 ab = q[k + 1] - q[k];
        const double t = std::clamp((x - q[k]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (x - q[k] - t * ab).norm());
      }
      worst = std::max(worst, best);
    }
    EXPECT_LE(worst, tolerance * 1.01) << tolerance;
  }
}

TEST(akimaSpline, curvatureOfAFinelySampledCircle) {
  std::vector<Vec3> p;
  for (int i = 0; i <= 40; ++i) p.push_back(Vec3(10 * std::cos(i * 0.05), 10 * std::sin(i * 0.05), 0));
  const PiecewiseCubicCurve c = fitAkimaSpline(p);
  EXPECT_NEAR(c.curvature(0.5 * c.parameterLength()), 0.1, 0.002);
  EXPECT_NEAR(c.arcLength(), 10 * 2.0, 1e-4);
}

}  // namespace
}  // namespace isurface
