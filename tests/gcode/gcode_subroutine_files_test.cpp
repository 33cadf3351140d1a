// Subroutines and subprograms in files of their own, found in the subroutine path (and beside
// the program): LinuxCNC's `o<name> call` reads name.ngc, a Fanuc M98 / G65 P1000 reads O1000.
// Their moves carry the calling line of the program; their errors name their own file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gcode_test_support.h"
#include "isurface/gcode/gcode_stream.h"
#include "scratch_files.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

// A folder of its own for each test, so that files of one test are not found by another.
std::string folder(const std::string& name) {
  const std::filesystem::path dir = test::scratchDir() / name;
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string write(const std::string& dir, const std::string& name, const std::string& text) {
  return test::writeScratch(std::filesystem::path(std::filesystem::path(dir).filename() / name).string(), text);
}

InterpreterOptions searching(const std::string& dir, bool fanuc = false) {
  InterpreterOptions options;
  options.subroutinePath = {dir};
  options.fanuc = fanuc;
  return options;
}

}  // namespace

TEST(gcodeSubroutineFiles, AnOWordCallReadsTheNamedFileWithItsArguments) {
  const std::string dir = folder("owords");
  write(dir, "step.ngc", "(one step)\no<step> sub\n  G91 G1 X#1 Y#2\n  G90\no<step> endsub\nM2\n");
  const InterpretResult r = run("G21 F100\no<step> call [2] [3]\no<step> call [1] [-1]\n", searching(dir));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 2u);
  expectNear(r.program.moves[0].end, Vec3(2, 3, 0));
  expectNear(r.program.moves[1].end, Vec3(3, 2, 0));
  // The moves point at the calls in the program the user opened, not into step.ngc.
  EXPECT_EQ(r.program.moves[0].line, 2u);
  EXPECT_EQ(r.program.moves[1].line, 3u);
}

TEST(gcodeSubroutineFiles, AFanucSubprogramIsReadFromItsProgramFile) {
  const std::string dir = folder("fanuc");
  write(dir, "O1000.nc", "%\nO1000 (square side)\nG91 G1 X5 F200\nY5\nG90\nM99\n%\n");
  write(dir, "O0200", "O200\nG1 X#1 Y#2 F100\nM99\n");
  const InterpretResult r = run("O1\nG21 G90 G0 X0 Y0\nM98 P1000 L2\nG65 P200 A7 B8\nM30\n", searching(dir, true));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 6u);
  expectNear(r.program.moves[4].end, Vec3(10, 10, 0));
  EXPECT_EQ(r.program.moves[4].line, 3u);
  expectNear(r.program.moves[5].end, Vec3(7, 8, 0));
  EXPECT_EQ(r.program.moves[5].line, 4u);
}

TEST(gcodeSubroutineFiles, AFileThatDoesNotDefineItLeavesTheSearchToTheProgram) {
  const std::string dir = folder("elsewhere");
  write(dir, "later.ngc", "o<other> sub\nG1 X99\no<other> endsub\n");
  const InterpretResult r = run("G21 F100\no<later> call\nM2\no<later> sub\nG1 X4\no<later> endsub\n", searching(dir));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 1u);
  expectNear(r.program.moves[0].end, Vec3(4, 0, 0));
  EXPECT_EQ(r.program.moves[0].line, 5u);
  EXPECT_NE(firstError("G21\no<nowhere> call\nM2\n").find("no nowhere.ngc in the subroutine path defines it"),
            std::string::npos);
}

TEST(gcodeSubroutineFiles, ErrorsInAFileNameThatFile) {
  const std::string dir = folder("errors");
  const std::string broken = write(dir, "broken.ngc", "o<broken> sub\nG1 X1 F100\nG1 X1 X2\no<broken> endsub\n");
  InterpretResult r = run("G21\no<broken> call\nM2\n", searching(dir));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors.front().str(), broken + ":3:7: Multiple x words on one line");
  const std::string open = write(dir, "open.ngc", "o<open> sub\nG1 X1 F100\n");
  r = run("G21\no<open> call\nM2\n", searching(dir));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors.front().str(),
            open + ":2: the subroutine file ends without returning (endsub, return or M99) to line 2 of t.ngc");
}

TEST(gcodeSubroutineFiles, AProgramFindsTheFilesBesideItWhetherReadWholeOrStreamed) {
  const std::string dir = folder("beside");
  write(dir, "arc.ngc", "o<arc> sub\nG2 X#1 Y0 R[#1 / 2]\no<arc> endsub\n");
  const std::string program = write(dir, "main.ngc", "G21 F100\nG0 X0 Y0\no<arc> call [10]\no<arc> call [20]\nM2\n");
  const InterpretResult whole = interpretGcodeFile(program);
  ASSERT_TRUE(whole.ok()) << whole.errors.front().str();
  ASSERT_EQ(whole.program.moves.size(), 3u);
  expectNear(whole.program.moves[2].end, Vec3(20, 0, 0));
  struct Collect : MoveSink {
    std::vector<Move> moves;
    void consume(const Move* m, std::size_t n, std::uint64_t) override { moves.insert(moves.end(), m, m + n); }
  } sink;
  const StreamedInterpretation streamed = interpretGcodeFileStream(program, sink, {}, 1);
  ASSERT_TRUE(streamed.ok());
  EXPECT_EQ(streamed.lineCount, 5u);
  ASSERT_EQ(sink.moves.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    expectNear(sink.moves[i].end, whole.program.moves[i].end, 0);
    EXPECT_EQ(sink.moves[i].line, whole.program.moves[i].line);
  }
}

TEST(gcodeSubroutineFiles, ACallInAFileOfSomethingDefinedNowhereIsAnErrorNotAHang) {
  const std::string dir = folder("nowhere");
  write(dir, "a.ngc", "o<a> sub\no<missing> call\no<a> endsub\n");
  write(dir, "O1000.nc", "O1000\nM98 P2000\nM99\n");
  InterpretResult r = run("G21\no<a> call\nM2\n", searching(dir));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors.front().message.find("o<missing> is called"), std::string::npos) << r.errors.front().str();
  r = run("O1\nG21\nM98 P1000\nM30\n", searching(dir, true));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors.front().message.find("subprogram O2000 is called"), std::string::npos) << r.errors.front().str();
  // The call on a last line without its newline, and a file that does not define it.
  write(dir, "foo.ngc", "o<bar> sub\no<bar> endsub\n");
  r = run("G21\no<foo> call", searching(dir));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors.front().message.find("o<foo> is called"), std::string::npos) << r.errors.front().str();
}
