// Quantities per sample and per vertex: motion parameters, inconsistency between passes,
// deviation of the feedback surface.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "surface_fixtures.h"
#include "isurface/base/diagnostic.h"
#include "isurface/analysis/kinematics.h"
#include "isurface/analysis/quantities.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(quantities, TableNamesLabelsUnits) {
  const std::vector<std::string> names = {"speed", "accel", "accel_mag", "jerk", "vx", "vy", "vz",
                                          "ax", "ay", "az", "jx", "jy", "jz", "following_error",
                                          "line", "time", "feed", "speed_inconsistency",
                                          "accel_inconsistency", "deviation", "joint_speed", "joint_vx",
                                          "joint_vy", "joint_vz", "joint_ax", "joint_ay", "joint_az", "joint_jx",
                                          "joint_jy", "joint_jz", "joint_va", "joint_vb", "joint_vc", "joint_aa",
                                          "joint_ab", "joint_ac", "joint_ja", "joint_jb", "joint_jc"};
  ASSERT_EQ(quantityInfos().size(), names.size());
  std::set<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const QuantityInfo& info = quantityInfos()[i];
    EXPECT_EQ(info.name, names[i]);
    EXPECT_TRUE(seen.insert(info.name).second);
    EXPECT_GT(std::string(info.label).size(), 0u);
    const auto parsed = parseQuantity(info.name);
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, info.quantity);
    EXPECT_EQ(std::string(quantityInfo(info.quantity).name), info.name);
  }
  EXPECT_FALSE(parseQuantity("colour").has_value());
  EXPECT_EQ(parseQuantity("SPEED"), Quantity::Speed);
  EXPECT_STREQ(quantityInfo(Quantity::Speed).unit, "mm/min");
  EXPECT_STREQ(quantityInfo(Quantity::Jerk).unit, "mm/s^3");
  EXPECT_STREQ(quantityInfo(Quantity::Deviation).unit, "\u00b5m");
  EXPECT_TRUE(quantityInfo(Quantity::Deviation).needsFeedback && quantityInfo(Quantity::Deviation).onSurface);
  EXPECT_TRUE(quantityInfo(Quantity::FollowingError).needsFeedback);
  EXPECT_TRUE(quantityInfo(Quantity::SpeedInconsistency).onSurface);
  EXPECT_FALSE(quantityInfo(Quantity::Speed).onSurface);
}

// A path whose speed changes smoothly, long enough to span several derivation chunks.
Trajectory wavyPath(std::size_t n) {
  Trajectory t;
  t.cycle = 0.001;
  t.source = "wavy";
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 0.001 * double(i);
    t.time.push_back(s);
    t.x.push_back(20 * std::sin(0.3 * s) + s);
    t.y.push_back(5 * std::cos(0.7 * s));
    t.z.push_back(0.1 * s * s);
    t.line.push_back(static_cast<std::uint32_t>(1 + i / 1000));
  }
  return t;
}

TEST(quantities, SampleValuesAreTheWholeDerivation) {
  const Trajectory t = wavyPath(200'000);
  const Kinematics k = deriveKinematics(t.x.data(), t.y.data(), t.z.data(), nullptr, t.size(), t.cycle, true);
  // Speeds are shown in mm/min, everything else in the unit it is derived in.
  const struct {
    Quantity q;
    const std::vector<double>* expected;
    double toDisplay;
  } cases[] = {{Quantity::Speed, &k.speed, 60},          {Quantity::Acceleration, &k.accel, 1},
               {Quantity::AccelerationMagnitude, &k.accelMagnitude, 1}, {Quantity::Jerk, &k.jerk, 1},
               {Quantity::VelocityY, &k.axisVel[1], 60}, {Quantity::AccelerationZ, &k.axisAcc[2], 1},
               {Quantity::JerkX, &k.axisJerk[0], 1}};
  for (const auto& c : cases) {
    const std::vector<double> v = sampleQuantity(c.q, t);
    ASSERT_EQ(v.size(), t.size());
    if (c.toDisplay == 60) {
      ASSERT_STREQ(quantityInfo(c.q).unit, "mm/min");
    }
    for (std::size_t i = 0; i < v.size(); ++i)
      ASSERT_EQ(v[i], c.toDisplay * (*c.expected)[i]) << quantityInfo(c.q).name << " " << i;
  }
  const std::vector<double> lines = sampleQuantity(Quantity::Line, t);
  EXPECT_EQ(lines[123456], 124.0);
  EXPECT_DOUBLE_EQ(sampleQuantity(Quantity::Time, t)[5000], 5.0);
}

// Several quantities at once (the figures take speed and jerk together) are each the values
// sampleQuantity gives, whether derived, per axis or read as they are.
TEST(quantities, SeveralAtOnceAreEachTheSameValues) {
  Trajectory t = wavyPath(140'000);
  const Kinematics k = deriveKinematics(t.x.data(), t.y.data(), t.z.data(), nullptr, t.size(), t.cycle, true);
  const std::vector<Quantity> asked = {Quantity::Jerk, Quantity::Line, Quantity::Speed, Quantity::VelocityX, Quantity::Time};
  for (const bool storedJerk : {false, true}) {
    if (storedJerk) t.extra.emplace_back("jerk", std::vector<double>(t.size(), 7.5));
    const std::vector<std::vector<double>> together = sampleQuantities(asked, t);
    ASSERT_EQ(together.size(), asked.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      ASSERT_EQ(together[0][i], storedJerk ? 7.5 : k.jerk[i]) << i;
      ASSERT_EQ(together[1][i], double(t.line[i])) << i;
      ASSERT_EQ(together[2][i], 60 * k.speed[i]) << i;
      ASSERT_EQ(together[3][i], 60 * k.axisVel[0][i]) << i;
      ASSERT_EQ(together[4][i], t.timeAt(i)) << i;
    }
  }
  EXPECT_THROW(sampleQuantities({Quantity::Speed, Quantity::FollowingError}, t), InputError);
}

// A view of part of a run (the app's curves) gets exactly the values of the whole derivation,
// at the run's ends and across the derivation's internal pieces too.
TEST(quantities, RangeValuesAreTheWholeRunsValues) {
  Trajectory t = wavyPath(150'000);
  for (const bool irregular : {false, true}) {
    if (irregular) {
      for (std::size_t i = 0; i < t.size(); ++i) t.time[i] += (i % 3 ? 0.0001 : 0.0);
      t.irregularTime = true;
    }
    for (Quantity q : {Quantity::Speed, Quantity::Acceleration, Quantity::Jerk, Quantity::VelocityZ, Quantity::Line}) {
      const std::vector<double> whole = sampleQuantity(q, t);
      const std::pair<std::size_t, std::size_t> ranges[] = {
          {0, 1}, {0, 7}, {65530, 65542}, {3, 140'003}, {t.size() - 2, t.size()}, {t.size() - 5, t.size() + 10}, {42, 42}};
      for (const auto& [first, last] : ranges) {
        std::vector<float> part(last - first, -1.0f);
        sampleQuantityRange(q, t, first, last, part.data());
        for (std::size_t i = first; i < std::min(last, t.size()); ++i)
          ASSERT_EQ(part[i - first], static_cast<float>(whole[i])) << quantityInfo(q).name << " " << i << " irregular " << irregular;
        for (std::size_t i = std::max(first, t.size()); i < last; ++i) ASSERT_EQ(part[i - first], -1.0f);  // left alone
      }
    }
  }
}

TEST(quantities, IrregularTimeUsesDividedDifferences) {
  Trajectory t = wavyPath(1000);
  for (std::size_t i = 0; i < t.size(); ++i) t.time[i] += (i % 2 ? 0.0002 : 0.0);
  t.irregularTime = true;
  const Kinematics k = deriveKinematics(t.x.data(), t.y.data(), t.z.data(), t.time.data(), t.size(), t.cycle, false);
  const std::vector<double> v = sampleQuantity(Quantity::Speed, t);
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], 60 * k.speed[i]);  // mm/s -> mm/min
}

TEST(quantities, VertexValuesAreTheSamples) {
  const Trajectory s = zigZagRaster(8, 40.0, 0.5, 3000, [](double x, double y) { return 0.1 * x + 0.05 * y * y; }, 81);
  const PassSet passes = splitPasses(s);
  ASSERT_EQ(passes.passes.size(), 8u);
  MeshOptions options;
  options.stride = 3;
  const SurfaceMesh mesh = buildSurfaceMesh(s, passes, options);
  for (const Quantity q : {Quantity::Speed, Quantity::Jerk, Quantity::AccelerationX, Quantity::Time, Quantity::Line}) {
    const std::vector<double> all = sampleQuantity(q, s);
    const std::vector<float> at = vertexQuantity(q, s, mesh);
    ASSERT_EQ(at.size(), mesh.vertexSample.size());
    for (std::size_t v = 0; v < at.size(); ++v) ASSERT_EQ(at[v], static_cast<float>(all[mesh.vertexSample[v]]));
  }
}

TEST(quantities, SpeedInconsistencyBetweenTwoPasses) {
  // Two passes one way along X, 0.5 mm apart: 3000 mm/min, then 2000 mm/min.
  PathSampler path(Vec3(0, 0, 0));
  path.lineTo(Vec3(30, 0, 0), 3000);
  const std::size_t firstEnd = path.size();
  path.lineTo(Vec3(0, 0.5, 0), 20000);
  const std::size_t secondBegin = path.size();
  path.lineTo(Vec3(30, 0.5, 0), 2000);
  const Trajectory s = path.take();
  // The passes leave out the samples whose stencils reach into the return move.
  PassSet passes;
  passes.pattern = PathPattern::DirectionParallel;
  passes.passes = {{3, firstEnd - 3}, {secondBegin + 3, s.size() - 3}};
  const SurfaceMesh mesh = buildSurfaceMesh(s, passes);
  ASSERT_GT(mesh.triangles.size(), 100u);
  const std::vector<float> speed = vertexQuantity(Quantity::Speed, s, mesh);
  const std::vector<float> jump = vertexQuantity(Quantity::SpeedInconsistency, s, mesh);
  std::size_t matched = 0;
  for (std::size_t v = 0; v < jump.size(); ++v) {
    EXPECT_NEAR(speed[v], mesh.vertexPass[v] == 0 ? 3000 : 2000, 1e-3);
    const bool hasNeighbour = mesh.previousPassNeighbour[v] != kNoVertex || mesh.nextPassNeighbour[v] != kNoVertex;
    if (hasNeighbour) {
      ++matched;
      EXPECT_NEAR(jump[v], 1000, 1e-3) << v;
    } else {
      EXPECT_EQ(jump[v], 0.0f) << v;
    }
  }
  EXPECT_EQ(matched, jump.size());
  // Constant speeds: no acceleration anywhere, so none between the passes either.
  for (const float a : vertexQuantity(Quantity::AccelerationInconsistency, s, mesh)) EXPECT_NEAR(a, 0, 1e-3);
}

TEST(quantities, InconsistencyIsZeroWithoutNeighbours) {
  const Trajectory s = zigZagRaster(1, 40.0, 0.5, 3000);
  const PassSet passes = splitPasses(s);
  const SurfaceMesh mesh = buildSurfaceMesh(s, passes);
  ASSERT_GT(mesh.vertexSample.size(), 0u);
  for (const float v : vertexQuantity(Quantity::SpeedInconsistency, s, mesh)) EXPECT_EQ(v, 0.0f);
}

TEST(quantities, DeviationAlongTheNormal) {
  const auto tilted = [](double x, double y) { return 0.3 * x - 0.2 * y; };
  const Vec3 normal = Vec3(-0.3, 0.2, 1).normalized();
  for (const double offset_um : {5.0, -5.0}) {
    PathSampler path(Vec3(0, 0, 0));
    path.withFeedback([&](const Vec3&) { return normal * (offset_um / 1000.0); });
    for (int k = 0; k < 6; ++k) {
      const double y = 0.5 * k;
      if (k > 0) path.lineTo(Vec3(path.position().x(), y, tilted(path.position().x(), y)), 3000);
      const double x = k % 2 == 0 ? 20.0 : 0.0;
      path.lineTo(Vec3(x, y, tilted(x, y)), 3000);
    }
    const Trajectory s = path.take();
    const PassSet passes = splitPasses(s);
    ASSERT_EQ(passes.passes.size(), 6u);
    const SurfaceMesh mesh = buildSurfaceMesh(s, passes);
    const std::vector<float> deviation = vertexQuantity(Quantity::Deviation, s, mesh);
    const std::vector<Vec3> normals = vertexNormals(meshPositions(s, mesh), mesh);
    for (std::size_t v = 0; v < deviation.size(); ++v) {
      if (normals[v].squaredNorm() == 0) {
        EXPECT_TRUE(std::isnan(deviation[v]));
      } else {
        EXPECT_NEAR(deviation[v], offset_um, 1e-4) << v;
      }
    }
    // The following error is the offset's size.
    for (const float e : vertexQuantity(Quantity::FollowingError, s, mesh)) EXPECT_NEAR(e, std::fabs(offset_um), 1e-4);
  }
}

TEST(quantities, MissingChannelsAreInputErrors) {
  const Trajectory s = zigZagRaster(3, 20.0, 0.5, 3000);  // no feedback, no feed
  const SurfaceMesh mesh = buildSurfaceMesh(s, splitPasses(s));
  for (const Quantity q : {Quantity::FollowingError, Quantity::Feed}) {
    try {
      sampleQuantity(q, s);
      ADD_FAILURE() << quantityInfo(q).name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.diagnostic().file, "synthetic");
    }
  }
  EXPECT_THROW(vertexQuantity(Quantity::Deviation, s, mesh), InputError);
  EXPECT_THROW(vertexQuantity(Quantity::FollowingError, s, mesh), InputError);
  EXPECT_THROW(sampleQuantity(Quantity::SpeedInconsistency, s), std::invalid_argument);
}

TEST(quantities, NonFiniteSamplesGiveNaN) {
  Trajectory s = wavyPath(100);
  s.x[50] = kNaN;
  const std::vector<double> speed = sampleQuantity(Quantity::Speed, s);
  EXPECT_TRUE(std::isnan(speed[49]) && std::isnan(speed[50]) && std::isnan(speed[51]));
  EXPECT_TRUE(std::isfinite(speed[48]) && std::isfinite(speed[52]));
  const std::vector<double> jerk = sampleQuantity(Quantity::Jerk, s);
  EXPECT_TRUE(std::isnan(jerk[48]) && std::isnan(jerk[52]));
  EXPECT_TRUE(std::isfinite(jerk[47]) && std::isfinite(jerk[53]));
}

TEST(quantities, ExtraChannelsPerVertex) {
  Trajectory s = zigZagRaster(3, 20.0, 0.5, 3000);
  std::vector<double> spindle(s.size());
  for (std::size_t i = 0; i < spindle.size(); ++i) spindle[i] = 12000 + double(i);
  s.extra.emplace_back("spindle", spindle);
  const SurfaceMesh mesh = buildSurfaceMesh(s, splitPasses(s));
  const auto values = vertexExtraChannel(s, mesh, "spindle");
  ASSERT_TRUE(values.has_value());
  for (std::size_t v = 0; v < values->size(); ++v) EXPECT_EQ((*values)[v], static_cast<float>(spindle[mesh.vertexSample[v]]));
  EXPECT_FALSE(vertexExtraChannel(s, mesh, "nothing").has_value());
}

}  // namespace

namespace {

// A writer that stored its own speed ("v", mm/min) is believed, not derived again.
TEST(quantities, StoredChannelsArePreferredToDerivedOnes) {
  Trajectory t;
  t.source = "stored.biip";
  for (int i = 0; i < 50; ++i) {
    t.x.push_back(0.05 * i);
    t.y.push_back(0);
    t.z.push_back(0);
    t.time.push_back(0.001 * i);
    t.line.push_back(1);
  }
  const std::vector<double> derived = sampleQuantity(Quantity::Speed, t);
  EXPECT_NEAR(derived[25], 3000.0, 1e-6);  // 0.05 mm a millisecond
  t.extra.emplace_back("v", std::vector<double>(50, 1234.0));
  const std::vector<double> stored = sampleQuantity(Quantity::Speed, t);
  EXPECT_EQ(stored[25], 1234.0);
  EXPECT_NEAR(sampleQuantity(Quantity::Jerk, t)[25], 0.0, 1e-3);  // no "jerk" channel: derived
}

}  // namespace
