// Passes further apart than the default gap of 2 mm (a finishing raster with a 3 mm step-over):
// every command that makes a surface takes --gap-limit, and none judges or reports on a
// surface that has no triangles.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "test_support.h"

using namespace isurface::test;

namespace {

std::string scratch(const std::string& name) { return (scratchDir() / name).string(); }

// A zig-zag raster over a bump, 12 passes 3 mm apart of 0.4 mm moves at F3000.
std::string wideRaster() {
  const std::string path = scratch("wide-raster.nc");
  std::ofstream out(path);
  out << "G21 G90 G17 G94\nG0 Z5\nG0 X0 Y0\nG1 Z0 F3000\n";
  for (int pass = 0; pass < 12; ++pass)
    for (int i = 0; i <= 100; ++i) {
      const double x = 0.4 * (pass % 2 == 0 ? i : 100 - i);
      out << fmt::format("G1 X{:.4f} Y{:.4f} Z{:.4f}\n", x, 3.0 * pass, 3.0 * std::exp(-std::pow((x - 20) / 6, 2)));
    }
  out << "G0 Z5\nM30\n";
  return path;
}

// Passes 1 mm apart over Y 0-5, then 5 mm apart over Y 10-25: joined in the first part only.
std::string partlyJoinedRaster() {
  const std::string path = scratch("partly-joined.nc");
  std::ofstream out(path);
  out << "G21 G90 G17 G94\nG0 Z5\nG0 X0 Y0\nG1 Z0 F3000\n";
  const double ys[] = {0, 1, 2, 3, 4, 5, 10, 15, 20, 25};
  for (int pass = 0; pass < 10; ++pass)
    for (int i = 0; i <= 100; ++i) {
      const double x = 0.4 * (pass % 2 == 0 ? i : 100 - i);
      out << fmt::format("G1 X{:.4f} Y{:.4f} Z{:.4f}\n", x, ys[pass], 3.0 * std::exp(-std::pow((x - 20) / 6, 2)));
    }
  out << "G0 Z5\nM30\n";
  return path;
}

void expectRefusedForItsGap(const CommandResult& r, const std::string& output) {
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("too far apart to make a surface (gap limit 2 mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--gap-limit"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(output)) << output;
}

}  // namespace

TEST(gapLimitCli, OptimizeRefusesPassesTooFarApartInsteadOfJudgingNothing) {
  const std::string program = wideRaster(), out = scratch("wide-refused.nc");
  for (const char* mode : {"--all", "--auto", "--lines 6-500"})
    expectRefusedForItsGap(runCli("optimize " + program + " " + mode + " -o " + out), out);
}

TEST(gapLimitCli, OptimizeWithTheGapRaisedMeasuresBetweenThePasses) {
  const std::string program = wideRaster(), out = scratch("wide-optimised.nc"), json = scratch("wide-optimised.json");
  const CommandResult r = runCli("optimize " + program + " --all --gap-limit 4 -o " + out + " --report " + json);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json));
  for (const char* side : {"before", "after"}) {
    const nlohmann::json& whole = report["whole_program"][side];
    EXPECT_GT(whole["samples"].get<double>(), 10000) << side;
    EXPECT_GT(whole["speed_inconsistency_p99_mm_min"].get<double>(), 1.0) << side;
    EXPECT_GT(whole["predicted_deviation_p99_um"].get<double>(), 0.1) << side;
  }
}

TEST(gapLimitCli, AnalyzeFindsRegionsOnceTheGapIsRaised) {
  const std::string program = wideRaster(), json = scratch("wide-analysis.json");
  expectRefusedForItsGap(runCli("analyze " + program + " -o " + json), json);
  const CommandResult r = runCli("analyze " + program + " --gap-limit 4 -o " + json);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readFile(json));
  EXPECT_EQ(report["passes"].get<int>(), 12);
  EXPECT_GT(report["region_count"].get<int>(), 0);
  EXPECT_EQ(runCli("analyze " + program + " --gap-limit 0 -o " + json).exitCode, 2);
}

TEST(gapLimitCli, AReportDrawsItsMapsAndRegionsOnceTheGapIsRaised) {
  const std::string program = wideRaster(), html = scratch("wide-report.html"), json = scratch("wide-report.json");
  CommandResult r = runCli("report " + program + " -o " + html + " --json " + json + " --regions 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("0 maps"), std::string::npos) << r.out;
  EXPECT_NE(readFile(html).find("too far apart"), std::string::npos);
  r = runCli("report " + program + " -o " + html + " --json " + json + " --regions 2 --gap-limit 3.5 --optimize auto");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find(" 0 maps"), std::string::npos) << r.out;
  const nlohmann::json figures = nlohmann::json::parse(readFile(json));
  EXPECT_EQ(figures["regions"].size(), 2u);
  EXPECT_FALSE(figures["optimisation"].contains("not_done")) << figures["optimisation"].dump();
}

TEST(gapLimitCli, ExportJoinsThePassesOnceTheGapIsRaised) {
  const std::string program = wideRaster(), dump = scratch("wide-raster.biip"), vtp = scratch("wide-raster.vtp");
  ASSERT_EQ(runCli("simulate " + program + " -o " + dump).exitCode, 0);
  expectRefusedForItsGap(runCli("export " + dump + " --gcode " + program + " --vtp " + vtp), vtp);
  const CommandResult r = runCli("export " + dump + " --gcode " + program + " --vtp " + vtp + " --gap-limit 4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("triangles"), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(vtp), 10000u);
}

TEST(gapLimitCli, ARegionWhosePassesAreNotJoinedIsRefusedThoughOthersAre) {
  const std::string program = partlyJoinedRaster(), out = scratch("partly-joined-optimised.nc");
  for (const char* region : {"--box 5,14,30,26", "--lines 611-1014"}) {
    const CommandResult r = runCli("optimize " + program + " " + region + " -o " + out);
    EXPECT_EQ(r.exitCode, 2) << region << ": " << r.out << r.err;
    EXPECT_NE(r.err.find("no sample of the region has a neighbouring pass on the surface (its passes are further apart "
                         "than the gap limit of 2 mm"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << region;
  }
  // Where the passes are joined, the same program is optimised (kept or not, measured).
  const std::string json = scratch("partly-joined.json");
  const CommandResult r = runCli("optimize " + program + " --box 0,0,30,4 -o " + out + " --report " + json);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(readFile(json))["region"]["before"]["speed_inconsistency_p99_mm_min"].get<double>(), 1.0);
}

TEST(gapLimitCli, AGateOnFiguresBetweenPassesFailsWhereTheyWereNotMeasured) {
  const std::string program = wideRaster(), html = scratch("gate.html");
  CommandResult r = runCli("report " + program + " -o " + html + " --fail-on 'speed_inconsistency>100000'");
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("not measured (speed_inconsistency): the passes are too far apart"), std::string::npos) << r.err;
  // The machining time is measured all the same.
  EXPECT_EQ(runCli("report " + program + " -o " + html + " --fail-on 'machining_time>100000'").exitCode, 0);
  r = runCli("report " + program + " -o " + html + " --gap-limit 4 --fail-on 'speed_inconsistency>100000'");
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  // A single pass has no surface either: not measured, whatever the gap.
  const std::string single = scratch("single-pass.nc");
  std::ofstream(single) << "G21 G90\nG0 X0 Y0 Z1\nG1 Z0 F1000\nG1 X10 Z0.5\nG1 X20 Z0\nG1 X30 Z0.5\nG0 Z5\nM2\n";
  r = runCli("report " + single + " -o " + html + " --gap-limit 10 --fail-on 'jerk>1e12'");
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("not measured (jerk): a single cutting pass makes no surface"), std::string::npos) << r.err;
}

TEST(gapLimitCli, AComparisonWithoutASurfaceSaysSoAndTheReportStands) {
  const std::string program = wideRaster(), dump = scratch("wide-compared.biip"), html = scratch("compared.html"),
                    json = scratch("compared.json");
  ASSERT_EQ(runCli("simulate " + program + " -o " + dump).exitCode, 0);
  const CommandResult r = runCli("report " + program + " --compare " + dump + " -o " + html + " --json " + json);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json comparison = nlohmann::json::parse(readFile(json))["comparison"];
  EXPECT_NE(comparison["not_done"].get<std::string>().find("too far apart"), std::string::npos) << comparison.dump();
  EXPECT_NE(readFile(html).find("Not compared: the passes are too far apart"), std::string::npos);
}

TEST(gapLimitCli, ABatchRanksAProgramItCouldNotMeasureFirst) {
  const std::filesystem::path folder = scratchDir() / "batch-unmeasured", out = scratchDir() / "batch-unmeasured-out";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(wideRaster(), folder / "wide.nc", std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(sourcePath("samples/transition-surface.nc"), folder / "transition-surface.nc",
                             std::filesystem::copy_options::overwrite_existing);
  const CommandResult r = runCli("report --batch " + folder.string() + " -o " + out.string() +
                                 " --fail-on 'speed_inconsistency>100000' --fail-on 'jerk>1e12' --fail-on 'jerk>1e13'");
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  const std::string index = readFile((out / "index.html").string());
  const std::size_t wide = index.find(">wide.nc<"), measured = index.find(">transition-surface.nc<");
  ASSERT_NE(wide, std::string::npos);
  ASSERT_NE(measured, std::string::npos);
  EXPECT_LT(wide, measured) << "the program that could not be measured is listed first";
  EXPECT_NE(index.find("not measured (speed_inconsistency, jerk): the passes are too far apart"), std::string::npos);
}
