// `isurface-cli canon`: output format, exit codes, diagnostics, -o through a temporary file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "test_support.h"

using namespace isurface;

namespace {

std::string writeScratch(const std::string& name, const std::string& content) {
  const std::string path = (test::scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

const char* const kProgram =
    "G21 G90 G17\n"
    "G0 X1 Y2 Z3\n"
    "G1 X4 F100\n"
    "G2 X6 Y4 I0 J2 F200\n"
    "G4 P1.5\n"
    "G18 G3 X8 Z3 I1 K0\n"
    "G17 G0 X-0.00001 Y-1.23456\n"
    "M2\n";

const char* const kExpected =
    "2 G0 1.0000 2.0000 3.0000 0.0000\n"
    "3 G1 4.0000 2.0000 3.0000 100.0000\n"
    "4 G2 6.0000 4.0000 3.0000 4.0000 4.0000 3.0000 G17 1 200.0000\n"
    "5 G4 P1.5000\n"
    "6 G3 8.0000 4.0000 3.0000 7.0000 4.0000 3.0000 G18 1 200.0000\n"
    "7 G0 0.0000 -1.2346 3.0000 0.0000\n";

}  // namespace

TEST(gcodeCanonCli, PrintsOneLinePerMove) {
  const std::string path = writeScratch("prog.ngc", kProgram);
  const test::CommandResult r = test::runCli("canon " + path);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, kExpected);
  EXPECT_EQ(r.err, "");
}

TEST(gcodeCanonCli, InchFeedsAndTurns) {
  const std::string path =
      writeScratch("inch.ngc", "G20\nG1 X1 F999\nG3 X1 Y0 Z-0.1 I-1 P2\nG0 Z1\n");
  const test::CommandResult r = test::runCli("canon " + path);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out,
            "2 G1 25.4000 0.0000 0.0000 25374.6000\n"
            "3 G3 25.4000 0.0000 -2.5400 0.0000 0.0000 0.0000 G17 2 25374.6000\n"
            "4 G0 25.4000 0.0000 25.4000 0.0000\n");
}

TEST(gcodeCanonCli, ErrorsExitWithTwo) {
  const std::string path = writeScratch("bad.ngc", "G21 G0 X1\nG0 X2 X3\nG0 X4\nG1 X5\nG0 X6\n");
  test::CommandResult r = test::runCli("canon " + path);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.out, "1 G0 1.0000 0.0000 0.0000 0.0000\n");
  EXPECT_EQ(r.err, "error: " + path + ":2:7: Multiple x words on one line\n");

  r = test::runCli("canon --keep-going " + path);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.out,
            "1 G0 1.0000 0.0000 0.0000 0.0000\n"
            "3 G0 4.0000 0.0000 0.0000 0.0000\n"
            "5 G0 6.0000 0.0000 0.0000 0.0000\n");
  EXPECT_EQ(r.err, "error: " + path + ":2:7: Multiple x words on one line\n" + "error: " + path +
                       ":4:1: Cannot do G1 with zero feed rate\n");
}

TEST(gcodeCanonCli, WarningsGoToStderr) {
  const std::string path = writeScratch("no-units.ngc", "G1 X1 F100\n");
  const test::CommandResult r = test::runCli("canon " + path);
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out, "1 G1 1.0000 0.0000 0.0000 100.0000\n");
  EXPECT_EQ(r.err.rfind("warning: " + path + ":1:1: no G20 or G21 before the first length", 0), 0u) << r.err;
}

TEST(gcodeCanonCli, MissingInput) {
  const test::CommandResult r = test::runCli("canon /nonexistent/in.ngc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "error: /nonexistent/in.ngc: cannot open: No such file or directory\n");
  EXPECT_EQ(test::runCli("canon").exitCode, 2);  // the file argument is required
}

TEST(gcodeCanonCli, OutputFile) {
  const std::string path = writeScratch("out-prog.ngc", kProgram);
  const std::string out = (test::scratchDir() / "prog.canon").string();
  const test::CommandResult r = test::runCli("canon " + path + " -o " + out);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(test::readFile(out), kExpected);
  // No temporary file is left beside it.
  for (const auto& entry : std::filesystem::directory_iterator(test::scratchDir()))
    EXPECT_EQ(entry.path().string().find("prog.canon.tmp"), std::string::npos) << entry.path();
}

TEST(gcodeCanonCli, FailedOutputLeavesNoFile) {
  const std::string path = writeScratch("fail-prog.ngc", kProgram);
  // A full device.
  test::CommandResult r = test::runCli("canon " + path + " -o /dev/full");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("error:"), std::string::npos);
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  // A folder that does not exist.
  const auto missing = test::scratchDir() / "no-such-dir" / "x.canon";
  r = test::runCli("canon " + path + " -o " + missing.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(missing.parent_path()));

  // Bad input: without --keep-going no output file is made, with it the moves are written.
  const std::string bad = writeScratch("fail-bad.ngc", "G0 X1\nG0 X2 X3\nG0 X4\n");
  const auto out = test::scratchDir() / "bad.canon";
  r = test::runCli("canon " + bad + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
  r = test::runCli("canon --keep-going " + bad + " -o " + out.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(test::readFile(out.string()),
            "1 G0 1.0000 0.0000 0.0000 0.0000\n3 G0 4.0000 0.0000 0.0000 0.0000\n");
}

TEST(gcodeCanonCli, RealProgram) {
  const std::string path = test::realdataPath("communicator.nc");
  ISURFACE_SKIP_WITHOUT_REALDATA(path);
  const std::string out = (test::scratchDir() / "communicator.canon").string();
  const test::CommandResult r = test::runCli("canon " + path + " -o " + out);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = test::readFile(out);
  std::size_t lines = 0, arcs = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n') continue;
    ++lines;
  }
  for (std::size_t pos = text.find(" G2 "); pos != std::string::npos; pos = text.find(" G2 ", pos + 1))
    ++arcs;
  EXPECT_GT(lines, 7000u);
  EXPECT_GT(arcs, 900u);
  EXPECT_NE(text.find("\n14 G2 0.5411 26.0931 -1.0000 0.6814 26.1177 -1.0000 G17 1 2000.0000\n"),
            std::string::npos);
}

TEST(gcodeCanonCli, StackNamesTheCallsAMoveWasMadeIn) {
  const std::string path = writeScratch("stack.ngc",
                                        "o<side> sub\n"
                                        "  G1 X#1 F100\n"
                                        "o<side> endsub\n"
                                        "o<square> sub\n"
                                        "  o<side> call [10]\n"
                                        "  G1 Y5\n"
                                        "o<square> endsub\n"
                                        "G21 G90\n"
                                        "G0 Z1\n"
                                        "o<square> call\n"
                                        "o<side> call [2]\n"
                                        "M2\n");
  const test::CommandResult plain = test::runCli("canon " + path);
  EXPECT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(plain.out.find(" @ "), std::string::npos);
  const test::CommandResult r = test::runCli("canon --stack " + path);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out,
            "9 G0 0.0000 0.0000 1.0000 0.0000\n"
            "2 G1 10.0000 0.0000 1.0000 100.0000 @ 10 o<square> > 5 o<side>\n"
            "6 G1 10.0000 5.0000 1.0000 100.0000 @ 10 o<square>\n"
            "2 G1 2.0000 5.0000 1.0000 100.0000 @ 11 o<side>\n");
  // Written to a file the same way.
  const std::string out = (test::scratchDir() / "stack.canon").string();
  EXPECT_EQ(test::runCli("canon --stack " + path + " -o " + out).exitCode, 0);
  EXPECT_EQ(test::readFile(out), r.out);
}

TEST(gcodeCanonCli, StackOfAFanucSubprogramInAFileOfItsOwn) {
  const std::filesystem::path folder = test::scratchDir() / "stack-fanuc";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "O1000.nc") << "O1000\nG91 G1 X1 F50\nM99\n";
  std::ofstream(folder / "main.nc") << "G21 G90\nM98 P1000 L2\nG90 G0 X0\nM30\n";
  const std::filesystem::path machine = folder / "fanuc.json";
  std::ofstream(machine) << R"({"control": {"dialect": "fanuc"}})";
  const test::CommandResult r =
      test::runCli("canon --stack --machine " + machine.string() + " " + (folder / "main.nc").string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // A file's moves carry the calling line; the stack names the subprogram.
  EXPECT_EQ(r.out,
            "2 G1 1.0000 0.0000 0.0000 50.0000 @ 2 O1000\n"
            "2 G1 2.0000 0.0000 0.0000 50.0000 @ 2 O1000\n"
            "3 G0 0.0000 0.0000 0.0000 0.0000\n");
}
