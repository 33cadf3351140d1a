// Cutter radius compensation from the command line: a LinuxCNC tool table given by --tool-table
// (in the machine's tool table units) or by the machine description's "tools".
#include <gtest/gtest.h>

#include <string>

#include "scratch_files.h"
#include "test_support.h"

using namespace isurface;

namespace {

// A 20 mm wide slot side run along +X with the tool on the left.
const char* const kProgram = "G21 G17 G90\nG0 X-10 Y-10\nF100\nG41 D3\nG1 X0 Y0\nG1 X20 Y0\nG40\nG0 X30\nM2\n";

}  // namespace

TEST(CutterCompCli, ToolTableFromTheCommandLineOffsetsThePath) {
  const std::string program = test::writeScratch("comp.ngc", kProgram);
  const std::string table = test::writeScratch("tools.tbl", "; a LinuxCNC tool table\nT3 P3 D4.0 Z10 ;4 mm end mill\n");
  const test::CommandResult r = test::runCli("canon --tool-table " + table + " " + program);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The side runs 2 mm to the left of the programmed line: y = 2.
  EXPECT_NE(r.out.find("6 G1 20.0000 2.0000 0.0000 100.0000\n"), std::string::npos) << r.out;
  // Without a table the path is the programmed one.
  EXPECT_NE(test::runCli("canon " + program).out.find("6 G1 20.0000 0.0000 0.0000 100.0000\n"), std::string::npos);
}

TEST(CutterCompCli, TheMachineDescriptionGivesTheToolsAndTheirUnits) {
  const std::string program = test::writeScratch("comp-machine.ngc", kProgram);
  test::writeScratch("inch-tools.tbl", "T3 P3 D0.15748\n");  // 4 mm in inches
  const std::string machine = test::writeScratch(
      "tools-machine.json", R"({"name": "inch tool table", "tools": {"units": "inch", "table": "inch-tools.tbl"}})");
  const test::CommandResult r = test::runCli("canon --machine " + machine + " " + program);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("6 G1 20.0000 2.0000 0.0000 100.0000\n"), std::string::npos) << r.out;
  const std::string listed =
      test::writeScratch("listed-tools.json", R"({"name": "tools listed", "tools": {"diameters": {"3": 4.0}}})");
  EXPECT_NE(test::runCli("canon --machine " + listed + " " + program).out.find("6 G1 20.0000 2.0000"), std::string::npos);
}

TEST(CutterCompCli, BadToolTablesAndMissingToolsAreClearErrors) {
  const std::string program = test::writeScratch("comp-missing.ngc", kProgram);
  const std::string other = test::writeScratch("other.tbl", "T1 P1 D6\n");
  test::CommandResult r = test::runCli("canon --tool-table " + other + " " + program);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("comp-missing.ngc:4:5: Tool 3 is not in the tool table"), std::string::npos) << r.err;
  const std::string bad = test::writeScratch("bad.tbl", "T1 P1 D6\nT2 P2 Dx\n");
  r = test::runCli("canon --tool-table " + bad + " " + program);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("bad.tbl:2: the D word of a tool table entry has no number"), std::string::npos) << r.err;
  r = test::runCli("canon --tool-table " + test::writeScratch("twice.tbl", "T1 D1\nT1 D2\n") + " " + program);
  EXPECT_NE(r.err.find("twice.tbl:2: tool 1 is in the table twice"), std::string::npos) << r.err;
  r = test::runCli("canon --tool-table /nonexistent/tools.tbl " + program);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent/tools.tbl: cannot open tool table"), std::string::npos) << r.err;
  const std::string both = test::writeScratch(
      "both-tools.json", R"({"tools": {"table": "other.tbl", "diameters": {"1": 2}}})");
  r = test::runCli("canon --machine " + both + " " + program);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("not both"), std::string::npos) << r.err;
}

TEST(CutterCompCli, LinuxCncsOwnTableFormatWithSignedNumbersIsRead) {
  const std::string program = test::writeScratch("comp-signed.ngc", kProgram);
  const std::string table = test::writeScratch("signed.tbl", "T3 P3 D+4.000000 Z+0.511000 ;as LinuxCNC writes it\n");
  const test::CommandResult r = test::runCli("canon --tool-table " + table + " " + program);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("6 G1 20.0000 2.0000 0.0000 100.0000\n"), std::string::npos) << r.out;
}
