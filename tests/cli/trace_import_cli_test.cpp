// isurface-cli import: recorded machine traces (halsampler text, CSV) written as Biip dumps,
// and bad inputs refused with exit code 2.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "isurface/io/biip.h"
#include "isurface/io/trace_import.h"
#include "scratch_files.h"
#include "test_support.h"

namespace isurface {
namespace {

using test::realdataPath;
using test::runCli;
using test::scratchDir;
using test::writeScratch;

// The recording's line column (the 5th value of each line), read independently of the importer.
std::vector<std::uint32_t> recordedLines(const std::string& path) {
  std::vector<std::uint32_t> lines;
  std::ifstream in(path);
  std::string text;
  while (std::getline(in, text)) {
    std::istringstream row(text);
    double index, x, y, z, line;
    if (row >> index >> x >> y >> z >> line) lines.push_back(std::uint32_t(line));
  }
  return lines;
}

TEST(traceImport, cliRejectsBadInputsWithExitCode2) {
  const std::string out = (scratchDir() / "bad.biip").string();
  const std::string csv = writeScratch("cols.csv", "a,b,c\n1,2,3\n");
  auto r = runCli("import csv " + csv + " -o " + out + " --map x=a,y=b,z=nosuch");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(csv), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nosuch"), std::string::npos) << r.err;

  const std::string text = writeScratch("text.csv", "a,b,c\n1,2,3\n1,x2,3\n");
  r = runCli("import csv " + text + " -o " + out + " --map x=a,y=b,z=c");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(text + ":3:3:"), std::string::npos) << r.err;

  const std::string empty = writeScratch("empty.hal", "");
  r = runCli("import halsampler " + empty + " -o " + out);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(empty), std::string::npos) << r.err;

  const std::string emptyCsv = writeScratch("empty.csv", "");
  r = runCli("import csv " + emptyCsv + " -o " + out + " --preset umich");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(emptyCsv), std::string::npos) << r.err;

  r = runCli("import halsampler " + (scratchDir() / "absent.hal").string() + " -o " + out);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(test::fileExists(out));
}

// A trace of another program maps to lines all the same, each sample to its nearest move.
TEST(traceImport, aTraceThatDoesNotFollowTheProgramGivenIsRefusedUnlessForced) {
  const std::string program = writeScratch("along-x.nc", "G21 G90\nG1 X10 F600\nG1 X20\n");
  std::string rows;
  for (int i = 0; i <= 100; ++i) rows += fmt::format("{} 0 {:.2f} 5 0 0 0 1\n", i, 0.2 * i);  // along Y, 5 mm up
  const std::string trace = writeScratch("along-y.hal", rows);
  const std::string out = (scratchDir() / "along-y.biip").string();
  const auto refused = runCli("import halsampler " + trace + " -o " + out + " --gcode " + program);
  EXPECT_EQ(refused.exitCode, 2);
  EXPECT_NE(refused.err.find("is not a trace of"), std::string::npos) << refused.err;
  EXPECT_FALSE(test::fileExists(out));
  EXPECT_EQ(runCli("import halsampler " + trace + " -o " + out + " --gcode " + program + " --force").exitCode, 0);
  EXPECT_TRUE(test::fileExists(out));
}

// A trace imported with its program is a run of that program: it is mapped beside the program
// without --force, and its surface (little of it, the program being a test of moves more than a
// finish) is said to be little, with the options that may fill it.
TEST(traceImport, aTraceImportedWithItsProgramIsMappedWithIt) {
  const std::string program = realdataPath("linuxcnc_test.ngc");
  const std::string dump = (scratchDir() / "linuxcnc_test_trace.biip").string();
  ASSERT_EQ(runCli("import halsampler " + realdataPath("linuxcnc_test.halsampler.txt") + " -o " + dump + " --gcode " +
                   program).exitCode, 0);
  const std::string png = (scratchDir() / "linuxcnc_test_trace.png").string();
  const auto rendered = runCli("render " + program + " " + dump + " --size 400x300 -o " + png);
  EXPECT_EQ(rendered.exitCode, 0) << rendered.err;
  EXPECT_NE(rendered.err.find("of the cutting path lies on the surface"), std::string::npos) << rendered.err;
  EXPECT_NE(rendered.err.find("--pattern or --gap-limit"), std::string::npos) << rendered.err;
}

TEST(traceImport, halsamplerRecordingKeepsLines) {
  const std::string path = realdataPath("linuxcnc_test.halsampler.txt");
  ISURFACE_SKIP_WITHOUT_REALDATA(path);
  const std::vector<std::uint32_t> expected = recordedLines(path);
  const std::string out = (scratchDir() / "linuxcnc.biip").string();
  const auto r = runCli("import halsampler " + path + " -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;

  BiipReader dump(out);
  ASSERT_EQ(dump.recordCount(), expected.size());
  EXPECT_EQ(dump.recordCount(), 14873u);
  EXPECT_DOUBLE_EQ(dump.header().cycleSeconds, 0.001);
  const BiipChannelView line = dump.channel("line");
  ASSERT_TRUE(line.valid());
  std::size_t firstNonZero = expected.size(), mismatches = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    mismatches += line.integer(i) != expected[i];
    if (firstNonZero == expected.size() && expected[i] != 0) firstNonZero = i;
  }
  EXPECT_EQ(mismatches, 0u);
  ASSERT_LT(firstNonZero, expected.size());
  EXPECT_EQ(line.integer(firstNonZero), 3u);
  for (const char* name : {"current_vel", "requested_vel", "running"}) EXPECT_TRUE(dump.hasChannel(name)) << name;
  EXPECT_NEAR(dump.timeAt(1000), 1.0, 1e-9);
}

TEST(traceImport, umichPresetImports) {
  const std::string path = realdataPath("umich_experiment_01.csv");
  ISURFACE_SKIP_WITHOUT_REALDATA(path);
  const Trajectory t = importCsv(path, umichPreset());
  EXPECT_EQ(t.size(), 1055u);
  EXPECT_DOUBLE_EQ(t.cycle, 0.1);
  EXPECT_TRUE(t.hasFeedback());
  EXPECT_TRUE(t.hasFeed());
  EXPECT_TRUE(t.hasLine);
  EXPECT_NE(t.extraChannel("s1_actualposition"), nullptr);
  EXPECT_NE(t.extraChannel("m1_current_program_numbe"), nullptr);  // cut to 24 characters
  EXPECT_EQ(t.extraChannel("machining_process"), nullptr);  // text: left out

  const std::string out = (scratchDir() / "umich.biip").string();
  const auto r = runCli("import csv " + path + " -o " + out + " --preset umich");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  BiipReader dump(out);
  EXPECT_EQ(dump.recordCount(), 1055u);
  EXPECT_DOUBLE_EQ(dump.header().cycleSeconds, 0.1);
  for (const char* name : {"x", "y", "z", "fb_x", "fb_y", "fb_z", "feed", "line", "x1_outputcurrent"})
    EXPECT_TRUE(dump.hasChannel(name)) << name;
  EXPECT_DOUBLE_EQ(dump.channel("x")[0], 198.0);
  EXPECT_NEAR(dump.timeAt(10), 1.0, 1e-9);
}

}  // namespace
}  // namespace isurface
