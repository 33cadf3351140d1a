// Degenerate geometry must never turn into NaN or infinity: zero-length moves, repeated points,
// collinear runs and reversals, arcs of a nanometre (centre and radius format), full circles,
// helices of zero pitch, tiny and huge coordinates. Each program goes through interpretation,
// simulation, the Biip dump, passes, surface and every quantity (in process), and through every
// command that prints JSON (simulate, info, locate, analyze, intervals, fit, optimize): no
// value may be non-finite, and no JSON may carry "nan", "inf" or a null that stands for one.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "isurface/io/biip.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/surface/passes.h"
#include "isurface/analysis/quality_regions.h"
#include "isurface/analysis/quantities.h"
#include "isurface/nc/simulator.h"
#include "isurface/surface/surface_mesh.h"
#include "isurface/base/trajectory.h"
#include "test_support.h"

namespace fs = std::filesystem;
using isurface::test::runCli;
using isurface::test::scratchDir;

namespace isurface {
namespace {

// A raster of `passes` passes along X, `spacing` mm apart, each of `points` points `step` mm
// apart, from (x0, y0, z0), in plain G1 lines (what optimize re-optimises). `repeat` writes the
// middle point of each pass that many times (zero-length moves); `backtrack` steps back half a
// step there and forward again (a collinear reversal).
std::string raster(int passes, int points, double step, double x0 = 0, double y0 = 0, double z0 = 0,
                   int repeat = 1, bool backtrack = false, double spacing = 1) {
  std::ostringstream g;
  g << std::fixed << std::setprecision(12);
  g << "G0 X" << x0 << " Y" << y0 << " Z" << z0 + 1 << "\nG1 Z" << z0 << " F3000\n";
  for (int p = 0; p < passes; ++p) {
    const double y = y0 + p * spacing;
    const double direction = p % 2 == 0 ? 1 : -1;
    for (int i = 0; i < points; ++i) {
      const int k = direction > 0 ? i : points - 1 - i;
      const double x = x0 + k * step;
      const bool middle = i == points / 2;
      for (int r = 0; r < (middle ? repeat : 1); ++r) g << "G1 X" << x << " Y" << y << "\n";
      if (middle && backtrack) g << "G1 X" << x - direction * step / 2 << "\nG1 X" << x << "\n";
    }
  }
  return g.str();
}

struct DegenerateCase {
  std::string name;
  std::string gcode;
};

void PrintTo(const DegenerateCase& c, std::ostream* os) { *os << c.name; }

// Every case ends with an ordinary raster, so that passes, a surface and runs of G1 moves to
// re-optimise exist beside the degenerate moves.
DegenerateCase degenerate(std::string name, const std::string& moves) {
  return {std::move(name), "G21 G90 G17 G94\nG0 X0 Y0 Z1\nG1 Z0 F3000\n" + moves + raster(5, 16, 1.0, 0, 10) + "G0 Z5\nM2\n"};
}

std::vector<DegenerateCase> cases() {
  return {
      degenerate("ZeroLengthMoves", "G1 X0 Y0 Z0\nG0 X0 Y0 Z0\n" + raster(4, 12, 1.0, 0, 0, 0, 3)),
      degenerate("RepeatedPointsAndCollinearReversals", raster(4, 12, 1.0, 0, 0, 0, 2, true)),
      // Arcs whose chord is a nanometre on a 1 mm radius (centre and radius format); the
      // centre-format arc that ends a nanometre from its start (a full circle in LinuxCNC's
      // reading); an R-format arc whose radius is a nanometre (LinuxCNC has no lower limit).
      degenerate("NanometreArcs",
                 "G1 X10 Y0\nG2 X10.000000001 Y0 I0 J-1\nG3 X10.000000002 Y0 R1\nG2 X10.000000001 Y0 R1\n"
                 "G3 X10 Y0.000000001 I-1 J0\nG2 X10 Y0.000000003 R0.0000000015\nG1 X0 Y0\n"),
      degenerate("FullCirclesInEveryPlane",
                 "G1 X5 Y0\nG17 G2 X5 Y0 I-2 J0\nG3 X5 Y0 I-2 J0 P2\nG18 G2 X5 Z0 I-2 K0\n"
                 "G19 G3 Y0 Z0 J1 K0\nG17 G1 X0 Y0\n"),
      degenerate("ZeroPitchHelices",
                 "G1 X5 Y0\nG2 X5 Y0 Z0 I-2.5 J0 P3\nG3 X5 Y0 Z0.000000001 I-2.5 J0 P2\n"
                 "G2 X5 Y0 Z-1 I-2.5 J0 P2\nG1 X0 Y0 Z0\n"),
      degenerate("TinyCoordinates", raster(4, 12, 1e-6, 1e-9, 1e-9, 1e-9, 1, false, 1e-6)),
      degenerate("HugeCoordinates", raster(3, 10, 1.0, 2e4, -2e4, 1e3) + "G0 Z1\nG0 X0 Y10\n"),
  };
}

Program interpret(const DegenerateCase& c) {
  const InterpretResult r = interpretGcode(c.gcode, c.name + ".nc");
  std::string errors;
  for (const Diagnostic& d : r.errors) errors += d.str() + "\n";
  EXPECT_TRUE(r.ok()) << errors;
  return r.program;
}

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

template <typename Values>
std::size_t countNonFinite(const Values& values) {
  std::size_t n = 0;
  for (const auto v : values) n += !std::isfinite(double(v));
  return n;
}

class DegenerateGeometry : public ::testing::TestWithParam<DegenerateCase> {};

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

// Every number of a JSON document, with its key path, that is null where a number belongs.
// Nulls the commands print on purpose: an infinite curvature radius (a straight run) and the
// ratios at a section's ends, where there is no neighbour to compare with.
void collectNulls(const nlohmann::json& j, const std::string& path, std::vector<std::string>& out) {
  static const std::set<std::string> intended = {"radius_mm", "distance_ratio", "curvature_ratio"};
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!(it.value().is_null() && intended.count(it.key()))) collectNulls(it.value(), path + "/" + it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collectNulls(j[i], path + "/" + std::to_string(i), out);
  } else if (j.is_null()) {
    out.push_back(path);
  }
}

// Checks a command's JSON output: it parses, holds no nan/inf literal and no unexplained null.
void expectFiniteJson(const std::string& text, const std::string& what) {
  for (const char* word : {"nan", "inf\"", "inf,", "infinity", "-inf"})
    EXPECT_EQ(text.find(word), std::string::npos) << what << " prints " << word << ":\n" << text.substr(0, 2000);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << " is not JSON: " << e.what() << "\n" << text.substr(0, 2000);
    return;
  }
  std::vector<std::string> nulls;
  collectNulls(j, "", nulls);
  EXPECT_TRUE(nulls.empty()) << what << " has null (a non-finite value) at " << nulls.front();
}

TEST_P(DegenerateGeometry, CommandOutputsStayFinite) {
  const DegenerateCase& c = GetParam();
  const fs::path dir = scratchDir() / ("degenerate-" + c.name);
  fs::create_directories(dir);
  const std::string nc = (dir / "in.nc").string(), dump = (dir / "in.biip").string();
  std::ofstream(nc) << c.gcode;

  const auto run = [&](const std::string& args, const std::string& what) {
    const auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << what << ": " << r.err;
    return r;
  };
  expectFiniteJson(run("simulate " + nc + " -o " + dump + " --json", "simulate").out, "simulate --json");
  {
    const BiipReader reader(dump);
    std::vector<double> values(reader.recordCount());
    for (const BiipChannel& channel : reader.header().channels) {
      reader.copyChannel(channel.name, values.data(), 0, values.size());
      EXPECT_EQ(countNonFinite(values), 0u) << "channel " << channel.name << " of the dump";
    }
  }
  const auto info = run("info " + dump, "info");
  expectFiniteJson(info.out, "info");
  EXPECT_NE(info.out.find("\"non_finite_samples\": 0"), std::string::npos) << info.out;
  expectFiniteJson(run("locate " + dump + " --sample 5", "locate").out, "locate");

  const std::string report = (dir / "analyze.json").string();
  run("analyze " + nc + " " + dump + " -o " + report, "analyze");
  expectFiniteJson(isurface::test::readFile(report), "analyze");
  const std::string lines = " --lines 1-100000";
  expectFiniteJson(run("intervals " + nc + lines, "intervals").out, "intervals");
  expectFiniteJson(run("fit " + nc + lines, "fit").out, "fit");
  const std::string compared = (dir / "optimize.json").string();
  run("optimize " + nc + lines + " -o " + (dir / "new.nc").string() + " --report " + compared, "optimize");
  expectFiniteJson(isurface::test::readFile(compared), "optimize --report");
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
