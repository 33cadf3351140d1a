// Where a command's results go, as attacked from outside (issue 47): links in a batch index that
// open only their report, no two outputs on one file, standard output never into an input, JSON
// for any file name, nothing printed before the files are in place, exit code 2 for what the
// user can fix.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "scratch_files.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace isurface::test;

namespace {

const char* const kSquare = "G21 G90 G17\nG1 X10 Y0 F600\nG1 X10 Y10\nG1 X0 Y10\nM2\n";

// `report --batch` on a folder holding one program named `program`; the folder of the reports.
fs::path reportBatchOf(const std::string& test, const std::string& program) {
  const fs::path in = freshScratchFolder(test + "-in"), out = scratchDir() / (test + "-out");
  writeFileBytes(in / program, kSquare);
  const auto r = runCli("report --batch " + shellQuoted(in) + " -o " + shellQuoted(out));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return out;
}

}  // namespace

// Item 1: a program named like a script URL gets a link that opens its own report.
TEST(OutputsRoundTwoCli, BatchIndexLinksAreRelativeAndPercentEncoded) {
  const fs::path out = reportBatchOf("links", "javascript:document.title='X';location.nc");
  const std::string index = readFile((out / "index.html").string());
  const std::regex href("href=\"([^\"]*)\"");
  int links = 0;
  for (auto it = std::sregex_iterator(index.begin(), index.end(), href); it != std::sregex_iterator(); ++it, ++links) {
    const std::string url = (*it)[1];
    EXPECT_EQ(url.rfind("./", 0), 0u) << url;
    EXPECT_EQ(url.find(':'), std::string::npos) << url;
  }
  EXPECT_EQ(links, 1);
  EXPECT_NE(index.find("href=\"./javascript%3Adocument.title%3D%27X%27%3Blocation.nc.html\""), std::string::npos);
}

// Item 2: two options naming one file, however written, are refused before anything is done.
TEST(OutputsRoundTwoCli, TwoOutputsOnOneFileAreRefused) {
  const fs::path dir = freshScratchFolder("same-output");
  writeFileBytes(dir / "p.nc", kSquare);
  const std::string cd = "cd " + shellQuoted(dir) + " && " + cliProgram();
  const auto analyze = runShell(cd + " analyze p.nc -o a.json --png ./a.json");
  EXPECT_EQ(analyze.exitCode, 2);
  EXPECT_NE(analyze.err.find("--output and --png name the same file"), std::string::npos) << analyze.err;
  EXPECT_FALSE(fs::exists(dir / "a.json"));

  const auto report = runShell(cd + " report p.nc -o r.html --json r.html");
  EXPECT_EQ(report.exitCode, 2);
  EXPECT_NE(report.err.find("--output and --json name the same file"), std::string::npos) << report.err;
  EXPECT_FALSE(fs::exists(dir / "r.html"));

  writeFileBytes(dir / "o.nc", "old");
  fs::create_symlink("o.nc", dir / "link.nc");
  const auto linked = runShell(cd + " optimize p.nc -o o.nc --report link.nc");
  EXPECT_EQ(linked.exitCode, 2);
  EXPECT_NE(linked.err.find("--output and --report name the same file"), std::string::npos) << linked.err;
  EXPECT_EQ(readFile((dir / "o.nc").string()), "old");

  fs::create_hard_link(dir / "o.nc", dir / "hard.nc");
  const auto hard = runShell(cd + " sts -o o.nc --report s.json --biip hard.nc");
  EXPECT_EQ(hard.exitCode, 2);
  EXPECT_NE(hard.err.find("--output and --biip name the same file"), std::string::npos) << hard.err;
}

// Item 2: in a batch, a program called `index` keeps its report beside the index.
TEST(OutputsRoundTwoCli, BatchProgramNamedIndexIsNotReplacedByTheIndex) {
  const fs::path out = reportBatchOf("index", "index");
  const std::string index = readFile((out / "index.html").string());
  EXPECT_NE(index.find("1 programs"), std::string::npos);
  EXPECT_NE(index.find("href=\"./index%20%282%29.html\""), std::string::npos) << index;
  EXPECT_TRUE(fs::exists(out / "index (2).html"));
  EXPECT_TRUE(fs::exists(out / "index (2).json"));
}

// Item 3: standard output appended onto an input is refused before a byte is written.
TEST(OutputsRoundTwoCli, StandardOutputOntoAnInputIsRefused) {
  const fs::path dir = freshScratchFolder("stdout-input");
  writeFileBytes(dir / "p.nc", kSquare);
  const std::string program = shellQuoted(dir / "p.nc");
  const std::string cli = cliProgram();
  for (const std::string& command : {cli + " canon " + program + " >> " + program,
                                     cli + " simulate " + program + " -o " + shellQuoted(dir / "p.biip") + " >> " + program}) {
    const auto r = runShell(command);
    EXPECT_EQ(r.exitCode, 2) << command;
    EXPECT_NE(r.err.find("standard output is this file"), std::string::npos) << r.err;
    EXPECT_EQ(readFile((dir / "p.nc").string()), kSquare) << command;
  }
  EXPECT_FALSE(fs::exists(dir / "p.biip"));
  // A folder of programs with standard output into one of them: refused, nothing written.
  const fs::path out = scratchDir() / "stdout-batch-out";
  const auto batch = runShell(cli + " report --batch " + shellQuoted(dir) + " -o " + shellQuoted(out) + " >> " + program);
  EXPECT_EQ(batch.exitCode, 2);
  EXPECT_EQ(readFile((dir / "p.nc").string()), kSquare);
  EXPECT_FALSE(fs::exists(out / "index.html"));
}

// Item 12: a file name that is not UTF-8 is carried by the JSON, never a failure.
TEST(OutputsRoundTwoCli, JsonCarriesFileNamesThatAreNotUtf8) {
  const fs::path dir = freshScratchFolder("not-utf8");
  const std::string name = "bad\xff.nc";
  writeFileBytes(dir / name, kSquare);
  const std::string cd = "cd " + shellQuoted(dir) + " && " + cliProgram();
  const auto simulate = runShell(cd + " simulate $(printf 'bad\\377.nc') -o s.biip --json");
  ASSERT_EQ(simulate.exitCode, 0) << simulate.err;
  EXPECT_NE(simulate.out.find("\"source\": \"bad\xEF\xBF\xBD.nc\""), std::string::npos) << simulate.out;
  const auto intervals = runShell(cd + " intervals $(printf 'bad\\377.nc')");
  EXPECT_EQ(intervals.exitCode, 0) << intervals.err;
  const auto report = runShell(cd + " report $(printf 'bad\\377.nc') -o r.html --json r.json");
  EXPECT_EQ(report.exitCode, 0) << report.err;
  EXPECT_NE(readFile((dir / "r.json").string()).find("bad\xEF\xBF\xBD.nc"), std::string::npos);
}

// Item 13: a command that fails prints no result.
TEST(OutputsRoundTwoCli, NothingIsPrintedByACommandThatFailed) {
  const fs::path dir = freshScratchFolder("no-success");
  writeFileBytes(dir / "p.nc", kSquare);
  const auto r = runCli("ui-snapshot " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "x.png") +
                        " --size 320x240 --pick-sample 999999");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("sample 999999 is out of range"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// Item 14: a standard output that cannot be written is exit code 2, as a file that cannot.
TEST(OutputsRoundTwoCli, FailedStandardOutputIsExitCodeTwo) {
  const fs::path dir = freshScratchFolder("stdout-full");
  writeFileBytes(dir / "p.nc", kSquare);
  const auto r = runShell(std::string(cliProgram()) + " simulate " + shellQuoted(dir / "p.nc") + " -o " +
                          shellQuoted(dir / "p.biip") + " --json > /dev/full");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("cannot write standard output"), std::string::npos) << r.err;
}

// Item 14: values out of range are said as written, and why.
TEST(OutputsRoundTwoCli, OutOfRangeValuesAreSaidAsWritten) {
  const fs::path dir = freshScratchFolder("ranges");
  writeFileBytes(dir / "p.nc", kSquare);
  ASSERT_EQ(runCli("simulate " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "p.biip")).exitCode, 0);
  const auto far = runCli("locate " + shellQuoted(dir / "p.biip") + " --point 1e308,0,0");
  EXPECT_EQ(far.exitCode, 2);
  EXPECT_NE(far.err.find("--point 1e308,0,0 is out of range"), std::string::npos) << far.err;
  const auto pick = runCli("ui-snapshot " + shellQuoted(dir / "p.nc") + " -o " + shellQuoted(dir / "x.png") + " --pick-sample -1");
  EXPECT_EQ(pick.exitCode, 2);
  EXPECT_NE(pick.err.find("--pick-sample: -1 must be from 0"), std::string::npos) << pick.err;
  EXPECT_LT(pick.err.size(), 200u) << pick.err;
}

// Item 14: a program without motion has nothing to simulate: said, not 43 samples of standing.
TEST(OutputsRoundTwoCli, ProgramWithoutMotionIsRefused) {
  const fs::path dir = freshScratchFolder("no-motion");
  writeFileBytes(dir / "empty.nc", "");
  writeFileBytes(dir / "modal.nc", "G21 G90 G17\nF600\nM2\n");
  for (const std::string name : {"empty.nc", "modal.nc"}) {
    const auto simulate = runCli("simulate " + shellQuoted(dir / name) + " -o " + shellQuoted(dir / "s.biip"));
    EXPECT_EQ(simulate.exitCode, 2) << name;
    EXPECT_NE(simulate.err.find(name + ": no motion in the program"), std::string::npos) << simulate.err;
    EXPECT_FALSE(fs::exists(dir / "s.biip"));
    const auto report = runCli("report " + shellQuoted(dir / name) + " -o " + shellQuoted(dir / "r.html"));
    EXPECT_EQ(report.exitCode, 2) << name;
    EXPECT_NE(report.err.find("no motion in the program"), std::string::npos) << report.err;
  }
}
