// isurface-cli sts: NC program, JSON report, paper table and bad options.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_support.h"

using namespace isurface::test;

TEST(stsCli, WritesProgramAndReport) {
  const std::string nc = (scratchDir() / "sinusoid.nc").string();
  const std::string report = (scratchDir() / "sinusoid.json").string();
  const CommandResult r = runCli("sts --surface sinusoid --discretise height --nodes nonuniform "
                                 "--interp spline --radius 10 -o " + nc + " --report " + report);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string program = readFile(nc);
  EXPECT_EQ(program.rfind("; slow tool servo turning tool path", 0), 0u);
  EXPECT_NE(program.find("\nN1 X10.000000 C0.000000 Z"), std::string::npos);
  EXPECT_NE(program.find("\nM30\n"), std::string::npos);
  const auto j = nlohmann::json::parse(readFile(report));
  EXPECT_EQ(j["surface"], "sinusoid");
  EXPECT_EQ(j["discretise"], "height");
  EXPECT_GT(j["contact_points"].get<int>(), 100);
  EXPECT_GT(j["interpolation_nodes"].get<int>(), j["contact_points"].get<int>());
  EXPECT_LT(j["spline_slope_disagreement_mm_per_rad"].get<double>(), 1e-9);
  EXPECT_EQ(j["interpolation_error"]["per_segment_max_mm"].size(),
            j["interpolation_nodes"].get<std::size_t>() - 1);
  EXPECT_GE(j["discrete_error"]["max_mm"].get<double>(), 0.0);
}

TEST(stsCli, ExpressionSurface) {
  const std::string report = (scratchDir() / "bowl.json").string();
  const CommandResult r = runCli("sts --surface '(x^2+y^2)/200' --discretise angle --nodes uniform "
                                 "--interp hermite --radius 5 --report " + report);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(readFile(report))["nodes"], "uniform");
}

TEST(stsCli, PaperTables) {
  const CommandResult r = runCli("sts --paper-tables");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("toric"), std::string::npos);
  EXPECT_NE(r.out.find("sinusoid"), std::string::npos);
}

TEST(stsCli, BadOptionsExitTwo) {
  const std::string nc = (scratchDir() / "bad.nc").string();
  for (const std::string args : {"--discretise spiral", "--nodes random", "--interp linear",
                                 "--surface 'x +'", "--surface 'sqrt(x-100)'", "--radius -1", "--feed 0", "--spindle-rpm 0"}) {
    const CommandResult r = runCli("sts " + args + " -o " + nc);
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_EQ(runCli("sts").exitCode, 2);  // nothing to write
  EXPECT_FALSE(fileExists(nc));
}

namespace {

// The tool path as a dump (one sample a node, errors as channels) and as a map.
TEST(stsCli, WritesTheToolPathAsADumpAndAMap) {
  const std::string dump = (isurface::test::scratchDir() / "path.biip").string();
  const std::string png = (isurface::test::scratchDir() / "path.png").string();
  const auto r = isurface::test::runCli("sts --surface toric --biip " + dump + " --png " + png + " --color discrete");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto info = isurface::test::runCli("info " + dump);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  for (const char* channel : {"\"discrete_error_um\"", "\"interpolation_error_um\"", "\"line\"", "\"t\""})
    EXPECT_NE(info.out.find(channel), std::string::npos) << channel;
  EXPECT_TRUE(isurface::test::fileExists(png));
  EXPECT_EQ(isurface::test::runCli("sts --surface toric --png " + png + "2 --color nonsense").exitCode, 2);
  // render shows the dump alone, coloured by either error channel.
  const std::string map = (isurface::test::scratchDir() / "render.png").string();
  const auto rendered = isurface::test::runCli("render " + dump + " --color interpolation_error_um --size 400x300 -o " + map);
  EXPECT_EQ(rendered.exitCode, 0) << rendered.err;
  EXPECT_TRUE(isurface::test::fileExists(map));
  EXPECT_EQ(isurface::test::runCli("render " + dump + " --color no_such_channel -o " + map + "2").exitCode, 2);
}

}  // namespace

// Values no spindle or surface can have are refused before anything is written: no `VX-inf`, no
// 300-digit times, no "error" of hundreds of kilometres from a surface that jumps.
TEST(stsCli, ImpossibleValuesAndADiscontinuousSurfaceAreRefusedAndNothingIsWritten) {
  const std::string nc = (scratchDir() / "impossible.nc").string(), report = (scratchDir() / "impossible.json").string();
  const struct {
    const char* args;
    const char* says;
  } cases[] = {{"--surface toric --spindle-rpm 1e308", "--spindle-rpm: 1e308 must be from 0.001 to 100000"},
               {"--surface toric --spindle-rpm 1e-300", "--spindle-rpm: 1e-300 must be from"},
               {"--surface toric --rho-max nan", "--rho-max: nan is not a finite number"},
               {"--surface toric --rho-max -1", "--rho-max: -1 must be from 0"},
               {"--surface 'x>0?1:0'", "not continuous or not smooth along the tool path"}};
  for (const auto& c : cases) {
    const CommandResult r = runCli(std::string("sts ") + c.args + " -o " + nc + " --report " + report);
    EXPECT_EQ(r.exitCode, 2) << c.args;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fileExists(nc)) << c.args;
    EXPECT_FALSE(fileExists(report)) << c.args;
  }
}
