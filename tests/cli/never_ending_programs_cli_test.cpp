// Programs that never end (issue 47, item 10): nested repeats, M98 L three deep, M99 P jumping
// back, a while that stays true. Every command that reads them stops within seconds with exit 2,
// an error naming the file and line of the loop or call, and no output file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "scratch_files.h"
#include "test_support.h"

namespace fs = std::filesystem;
using isurface::test::scratchDir;
using isurface::test::writeScratch;

namespace {

struct NeverEnding {
  std::string file, text, where;  // where: "file:line" of the loop or call that runs on
};

std::vector<NeverEnding> neverEndingPrograms() {
  return {
      {"nested-repeat.ngc",
       "G21 G90 F1000\no100 repeat [1000000]\no200 repeat [1000000]\nG1 X1\nG1 X0\no200 endrepeat\no100 endrepeat\nM2\n",
       "nested-repeat.ngc:2:"},
      {"m98-three-deep.nc",
       "G21 G90 F1000\nM98 P1 L9999\nM30\nO1\nM98 P2 L9999\nM99\nO2\nM98 P3 L9999\nM99\nO3\nG1 X1\nG1 X0\nM99\n",
       "m98-three-deep.nc:2:"},
      {"m99-back-jump.nc", "G21 G90 F1000\nN10 M98 P100\nM30\nO100\nG1 X1\nG1 X0\nM99 P10\n", "m99-back-jump.nc:2:"},
      {"endless-while.ngc", "G21 G90 F1000\nG1 X1\no1 while [1]\nG1 X0\nG1 X1\no1 endwhile\nM2\n",
       "endless-while.ngc:3:"},
  };
}

// Runs `command` (with the program's path for PROGRAM and the output's, the program's name with
// `outputExtension`, for OUTPUT) on every never-ending program and checks the outcome.
void expectEveryProgramRefused(const std::string& command, const std::string& outputExtension) {
  for (const NeverEnding& program : neverEndingPrograms()) {
    const std::string path = writeScratch(program.file, program.text);
    const std::string output = (scratchDir() / (program.file + outputExtension)).string();
    std::string line = command;
    line.replace(line.find("PROGRAM"), 7, path);
    if (const auto at = line.find("OUTPUT"); at != std::string::npos) line.replace(at, 6, output);
    const auto start = std::chrono::steady_clock::now();
    // A run that does not end is cut off (exit 124), a failure, not a hung suite.
    const auto r = isurface::test::runShell("timeout 60 " + std::string(isurface::test::cliProgram()) + " " + line);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exitCode, 2) << line << "\n" << r.err;
    EXPECT_NE(r.err.find(program.where), std::string::npos) << line << "\n" << r.err;
    EXPECT_NE(r.err.find("a program that never ends?"), std::string::npos) << line << "\n" << r.err;
    EXPECT_LT(seconds, 30.0) << line;
    if (outputExtension.empty()) continue;  // a command that prints its result
    EXPECT_FALSE(fs::exists(output)) << line;
    // Nothing of the output was left under another name either (the temporary file renamed).
    for (const auto& entry : fs::directory_iterator(scratchDir()))
      EXPECT_EQ(entry.path().filename().string().find(program.file + outputExtension), std::string::npos)
          << entry.path();
  }
}

}  // namespace

TEST(NeverEndingPrograms, CanonStopsWithoutWritingItsOutput) { expectEveryProgramRefused("canon PROGRAM -o OUTPUT", ".txt"); }

TEST(NeverEndingPrograms, SimulateStopsWithoutWritingItsDump) {
  expectEveryProgramRefused("simulate PROGRAM -o OUTPUT", ".biip");
}

TEST(NeverEndingPrograms, RenderStopsWithoutWritingItsMap) { expectEveryProgramRefused("render PROGRAM -o OUTPUT", ".png"); }

TEST(NeverEndingPrograms, IntervalsStopsWithAnError) { expectEveryProgramRefused("intervals PROGRAM", ""); }

TEST(NeverEndingPrograms, SimulateStopsReadingAtItsLongestRun) {
  // Through a pipe the program is not read ahead: the simulation's own bound stops it, and the
  // interpretation with it, long before the interpreter's bound.
  const std::string program = writeScratch("endless-moves.ngc", neverEndingPrograms()[3].text);
  const std::string dump = (scratchDir() / "endless-moves.biip").string();
  const auto start = std::chrono::steady_clock::now();
  const auto r = isurface::test::runShell(std::string("timeout 30 sh -c 'cat ") + program + " | " +
                                          isurface::test::cliProgram() + " simulate /dev/stdin -o " + dump +
                                          " --max-hours 0.01'");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("the run passes 0.01 h of machining"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dump));
}
