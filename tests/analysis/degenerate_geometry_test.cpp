// Degenerate geometry must never turn into NaN or infinity: zero-length moves, repeated points,
// collinear runs and reversals, arcs of a nanometre (centre and radius format), full circles,
// helices of zero pitch, tiny and huge coordinates. Each program goes through interpretation,
// simulation, passes, surface and every quantity, in process: no value may be non-finite. (The
// commands that print JSON are swept in tests/cli/degenerate_geometry_cli_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "degenerate_cases.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/surface/passes.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/analysis/quantities.h"
#include "isurface/nc/simulator.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/base/trajectory.h"
#include "isurface/nc/sample_trajectory.h"

namespace isurface {
namespace {

using test::cases;
using test::countNonFinite;
using test::DegenerateCase;
using test::DegenerateGeometry;

Program interpret(const DegenerateCase& c) {
  const InterpretResult r = interpretGcode(c.gcode, c.name + ".nc");
  std::string errors;
  for (const Diagnostic& d : r.errors) errors += d.str() + "\n";
  EXPECT_TRUE(r.ok()) << errors;
  return r.program;
}

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

TEST_P(DegenerateGeometry, InProcessPipelineStaysFinite) {
  const Program program = interpret(GetParam());
  for (const Move& m : program.moves) {
    ASSERT_TRUE(finite(m.end)) << "line " << m.line;
    ASSERT_TRUE(finite(m.centre)) << "line " << m.line;
  }
  const Machine machine = defaultMachine();
  SampleBuffer buffer;
  const SimulationReport report = simulate(program, machine, buffer);
  EXPECT_TRUE(std::isfinite(report.machiningTime) && std::isfinite(report.pathLength));
  ASSERT_GT(buffer.data.size(), 10u);
  for (std::size_t i = 0; i < buffer.data.size(); ++i) {
    const SimSample& s = buffer.data[i];
    ASSERT_TRUE(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z) && std::isfinite(s.fbX) &&
                std::isfinite(s.fbY) && std::isfinite(s.fbZ) && std::isfinite(s.feed))
        << "sample " << i << " line " << s.line;
  }

  const Trajectory samples = trajectoryFromSamples(buffer.data, machine.cycle, GetParam().name);
  PassOptions passOptions;
  passOptions.program = &program;
  const PassSet passes = splitPasses(samples, passOptions);
  const SurfaceMesh mesh = buildSurfaceMesh(samples, passes);
  ASSERT_FALSE(mesh.triangles.empty()) << "the raster after the degenerate moves makes a surface";
  const std::vector<Vec3> positions = meshPositions(samples, mesh);
  const std::vector<Vec3> normals = vertexNormals(positions, mesh);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    ASSERT_TRUE(finite(positions[v])) << "vertex " << v;
    ASSERT_TRUE(finite(normals[v])) << "vertex " << v;
  }
  for (const QuantityInfo& info : quantityInfos()) {
    if (info.needsJoints) continue;  // a five-axis run's: these samples have no joints
    if (!info.onSurface) {
      EXPECT_EQ(countNonFinite(sampleQuantity(info.quantity, samples)), 0u) << info.name;
    }
    const std::vector<float> values = vertexQuantity(info.quantity, samples, mesh);
    ASSERT_EQ(values.size(), positions.size()) << info.name;
    for (std::size_t v = 0; v < values.size(); ++v) {
      // The deviation of a vertex without a normal (no triangle) is NaN by design: nothing to
      // measure along. Everywhere else a NaN is a defect.
      if (info.quantity == Quantity::Deviation && normals[v].isZero()) continue;
      ASSERT_TRUE(std::isfinite(values[v])) << info.name << " at vertex " << v << " of " << values.size();
    }
  }
  const QualityReport quality = findQualityRegions(samples, mesh);
  for (const QualityRegion& r : quality.regions) {
    EXPECT_TRUE(std::isfinite(r.severity) && std::isfinite(r.area) && finite(r.centroid) && finite(r.lower) &&
                finite(r.upper) && std::isfinite(r.maxSpeedInconsistency) &&
                std::isfinite(r.maxAccelInconsistency) && std::isfinite(r.maxJerk) && std::isfinite(r.maxDeviation));
  }
}

INSTANTIATE_TEST_SUITE_P(Sweep, DegenerateGeometry, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

// A centre-format arc whose radius is a nanometre is below LinuxCNC's radius tolerance: the
// interpreter refuses it on its line.
TEST(DegenerateGeometry, NanometreRadiusCentreFormatArcIsRefusedOnItsLine) {
  const InterpretResult r =
      interpretGcode("G21 G90 G17\nG0 X0 Y0 Z0\nG1 F3000\nG2 X0.000000002 Y0 I0.000000001 J0\n", "tiny.nc");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors.front().line, 4u);
  EXPECT_NE(r.errors.front().message.find("radius"), std::string::npos) << r.errors.front().str();
}

}  // namespace
}  // namespace isurface
