// What a third outside attack on the command line found (issue 47): a batch that stopped half
// written at a name too long for the file system, a dangling link that let two outputs meet,
// traces whose clocks or positions no recorder makes, and messages that did not say what was
// wrong with what the user typed.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_files.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace isurface::test;

namespace {

const char* const kSquare = "G21 G90 G17\nG1 X10 Y0 F600\nG1 X10 Y10\nG1 X0 Y10\nM2\n";

bool says(const CommandResult& r, const std::string& text) { return r.err.find(text) != std::string::npos; }

}  // namespace

// A program whose name fills the file system's longest name still gets its report (under a name
// cut to fit, marked "~") and the index lists both; before, the batch stopped after the first
// report with no index.
TEST(InputsOutputsRoundThreeCli, BatchReportsAProgramWithTheLongestNameTheFolderHolds) {
  const fs::path in = freshScratchFolder("longest-in"), out = scratchDir() / "longest-out";
  fs::remove_all(out);
  const std::string longest(252, 'x');
  writeFileBytes(in / "ok.nc", kSquare);
  writeFileBytes(in / (longest + ".nc"), kSquare);
  const auto r = runCli("report --batch " + shellQuoted(in) + " -o " + shellQuoted(out));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(fs::exists(out / "index.html"));
  int reports = 0;
  for (const auto& entry : fs::directory_iterator(out)) reports += entry.path().extension() == ".html";
  EXPECT_EQ(reports, 3);  // the index and two reports
  const std::string index = readFile((out / "index.html").string());
  EXPECT_NE(index.find(longest + ".nc</a>"), std::string::npos);
}

// A single output whose name is too long is refused before any work, naming it.
TEST(InputsOutputsRoundThreeCli, AnOutputNameTooLongIsRefusedBeforeTheWork) {
  const fs::path dir = freshScratchFolder("too-long");
  writeFileBytes(dir / "p.nc", kSquare);
  const fs::path html = dir / (std::string(300, 'y') + ".html");
  const auto r = runCli("report " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(html));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(says(r, "File name too long")) << r.err;
  EXPECT_EQ(r.out, "");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.path().filename() != "p.nc";
  EXPECT_EQ(files, 0);  // nothing written, no temporary file left
}

// A dangling link is written through, as a shell's `>` does, so it and the file it names are one
// output: `-o x.html --json l.html` with l.html -> x.html is refused; a link alone writes its file.
TEST(InputsOutputsRoundThreeCli, ADanglingLinkIsTheFileItNames) {
  const fs::path dir = freshScratchFolder("dangling");
  writeFileBytes(dir / "p.nc", kSquare);
  fs::create_symlink("x.html", dir / "l.html");
  const auto both = runCli("report " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "x.html") + " --json " +
                           shellQuoted(dir / "l.html"));
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_TRUE(says(both, "name the same file")) << both.err;
  EXPECT_FALSE(fs::exists(dir / "x.html"));
  EXPECT_TRUE(fs::is_symlink(dir / "l.html"));

  const auto alone = runCli("report " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "l.html"));
  EXPECT_EQ(alone.exitCode, 0) << alone.err;
  EXPECT_TRUE(fs::is_symlink(dir / "l.html"));
  EXPECT_TRUE(fs::is_regular_file(dir / "x.html"));
}

// A time column whose mean step is no sample period (times in the wrong unit, or 1e300 s apart)
// is refused with the step it has, not written as a dump no command can read.
TEST(InputsOutputsRoundThreeCli, TraceTimesNoRecorderMakesAreRefused) {
  const fs::path dir = freshScratchFolder("trace-clocks");
  const struct {
    const char* name;
    const char* times[3];
    const char* step;
  } cases[] = {{"far.csv", {"0", "1e300", "2e300"}, "1e+300 s"}, {"near.csv", {"0", "1e-15", "2e-15"}, "1e-15 s"}};
  for (const auto& c : cases) {
    std::string text = "t,x,y,z\n";
    for (int i = 0; i < 3; ++i) text += std::string(c.times[i]) + "," + std::to_string(i) + ",0,0\n";
    writeFileBytes(dir / c.name, text);
    const fs::path out = dir / (std::string(c.name) + ".biip");
    const auto r = runCli("import csv " + shellQuoted(dir / c.name) + " --map t=t,x=x,y=y,z=z -o " + shellQuoted(out));
    EXPECT_EQ(r.exitCode, 2) << c.name;
    EXPECT_TRUE(says(r, c.name) && says(r, c.step) && says(r, "is not a sample period")) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// Positions of inf, or beyond a double (1e309), are kept as a dump keeps them, and said at import.
TEST(InputsOutputsRoundThreeCli, NonFinitePositionsAreReportedAtImport) {
  const fs::path dir = freshScratchFolder("trace-infinite");
  writeFileBytes(dir / "inf.csv", "t,x,y,z\n0,0,0,0\n0.001,inf,0,0\n0.002,1e309,0,0\n0.003,3,0,0\n");
  const auto r = runCli("import csv " + shellQuoted(dir / "inf.csv") + " --map t=t,x=x,y=y,z=z -o " + shellQuoted(dir / "inf.biip"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(says(r, "warning: ") && says(r, "inf.csv: 2 of 4 samples have a non-finite x, y or z (the first: sample 2)"))
      << r.err;
}

// A sample number larger than any integer is reported as typed, not as 9223372036854775807;
// line 0 is no line; a line without samples names the dump.
TEST(InputsOutputsRoundThreeCli, LocateSaysWhatWasTyped) {
  const fs::path dir = freshScratchFolder("locate-typed");
  writeFileBytes(dir / "p.nc", kSquare);
  ASSERT_EQ(runCli("simulate " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "p.biip")).exitCode, 0);
  const std::string dump = shellQuoted(dir / "p.biip");
  const struct {
    const char* args;
    const char* message;
  } cases[] = {{"--sample 100000000000000000000", "sample 100000000000000000000 is out of range"},
               {"--sample 1e3", "--sample '1e3' is not a sample number"},
               {"--line 0", "lines are numbered from 1"},
               {"--line 99", "p.biip: line 99 produced no samples"}};
  for (const auto& c : cases) {
    const auto r = runCli("locate " + dump + " " + c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args;
    EXPECT_TRUE(says(r, c.message)) << c.args << ": " << r.err;
  }
}

// A dump of no samples is said to have none, not to lack a line channel it has.
TEST(InputsOutputsRoundThreeCli, CompareOfADumpWithoutSamplesSaysSo) {
  const fs::path dir = freshScratchFolder("compare-empty");
  writeFileBytes(dir / "p.nc", kSquare);
  ASSERT_EQ(runCli("simulate " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "p.biip")).exitCode, 0);
  // The header alone, its record count set to 0 (BIIP.md: u64 at offset 32, header bytes at 8).
  std::string bytes = readFile((dir / "p.biip").string());
  std::uint32_t headerBytes = 0;
  std::memcpy(&headerBytes, bytes.data() + 8, 4);
  bytes.resize(headerBytes);
  std::memset(bytes.data() + 32, 0, 8);
  writeFileBytes(dir / "empty.biip", bytes);
  const auto r = runCli("compare " + shellQuoted(dir / "empty.biip") + " " + shellQuoted(dir / "p.biip") + " -o " +
                        shellQuoted(dir / "c.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(says(r, "empty.biip: has no samples")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "c.json"));
}

// `sts` without an output names the command once.
TEST(InputsOutputsRoundThreeCli, StsWithoutOutputsNamesItselfOnce) {
  const auto r = runCli("sts");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(says(r, "error: sts: give -o")) << r.err;
  EXPECT_FALSE(says(r, "sts: sts:")) << r.err;
}
