// One bound on the whole run (InterpreterOptions::maxLinesReadAgain): nested loops, subprograms
// repeated three deep and M99 P back-jumps, whose rounds multiply, stop with an error naming
// where the never-ending construct stands; programs within the bound run as they did.
#include <gtest/gtest.h>

#include <chrono>

#include "gcode_test_support.h"
#include "isurface/gcode/gcode_stream.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

// Each never-ending form the bound is for, and the line of the loop or call that runs on.
struct NeverEnding {
  const char* name;
  std::string text;
  std::uint32_t line;
  const char* running;  // what the message names
  bool fanuc = false;
};

std::vector<NeverEnding> neverEndingPrograms() {
  return {
      {"nested repeat",
       "G21 G90 F1000\no100 repeat [1000000]\no200 repeat [1000000]\nG1 X1\nG1 X0\no200 endrepeat\no100 endrepeat\nM2\n",
       2, "running: o100 repeat (line 2) > o200 repeat (line 3)"},
      {"M98 L three deep",
       "G21 G90 F1000\nM98 P1 L9999\nM30\nO1\nM98 P2 L9999\nM99\nO2\nM98 P3 L9999\nM99\nO3\nG1 X1\nG1 X0\nM99\n", 2,
       "running: M98 P1 (line 2) > M98 P2 (line 5) > M98 P3 (line 8)"},
      {"M99 P back-jump", "G21 G90 F1000\nN10 M98 P100\nM30\nO100\nG1 X1\nG1 X0\nM99 P10\n", 2,
       "the last jump back: line 7 to line 2"},
      {"while", "G21 G90 F1000\no1 while [1]\nG1 X1\nG1 X0\no1 endwhile\nM2\n", 2, "running: o1 while (line 2)"},
      {"Fanuc GOTO", "G21 G90 F1000\nN10 G1 X1\nG1 X0\nGOTO 10\nM30\n", 2, "the last jump back: line 4 to line 2",
       true},
  };
}

InterpreterOptions bounded(std::uint64_t lines, bool fanuc = false) {
  InterpreterOptions options;
  options.maxLinesReadAgain = lines;
  options.fanuc = fanuc;
  return options;
}

class CountingSink : public MoveSink {
 public:
  explicit CountingSink(std::uint64_t stopAfter = UINT64_MAX) : stopAfter_(stopAfter) {}
  void consume(const Move*, std::size_t count, std::uint64_t) override { moves += count; }
  bool stopped() const override { return moves >= stopAfter_; }
  std::uint64_t moves = 0;

 private:
  std::uint64_t stopAfter_;
};

}  // namespace

TEST(gcodeRunBound, EveryNeverEndingFormStopsWithAnErrorNamingItsLoopOrCall) {
  for (const NeverEnding& program : neverEndingPrograms()) {
    const InterpretResult r = run(program.text, bounded(100000, program.fanuc));
    ASSERT_EQ(r.errors.size(), 1u) << program.name;
    const Diagnostic& e = r.errors[0];
    EXPECT_EQ(e.file, "t.ngc") << program.name;
    EXPECT_EQ(e.line, program.line) << program.name << ": " << e.str();
    EXPECT_NE(e.message.find("never ends"), std::string::npos) << e.str();
    EXPECT_NE(e.message.find("read lines again 100000 times"), std::string::npos) << e.str();
    EXPECT_NE(e.message.find(program.running), std::string::npos) << program.name << ": " << e.str();
    // The moves made before the bound: as many as the lines read, not more.
    EXPECT_LT(r.program.moves.size(), 100000u) << program.name;
  }
}

TEST(gcodeRunBound, TheDefaultBoundStopsEveryFormWithinSeconds) {
  for (const NeverEnding& program : neverEndingPrograms()) {
    const auto start = std::chrono::steady_clock::now();
    const InterpretResult r = run(program.text, bounded(InterpreterOptions::kDefaultMaxLinesReadAgain, program.fanuc));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(r.ok()) << program.name;
    EXPECT_NE(r.errors[0].message.find("never ends"), std::string::npos) << r.errors[0].str();
    EXPECT_LT(seconds, 20.0) << program.name;
  }
}

TEST(gcodeRunBound, TheBoundCountsLinesReadAgainExactly) {
  // `repeat [k]` reads its two lines again k - 1 times: 2 (k - 1) lines read again.
  auto repeated = [](int times) {
    return "G21 G90 F1000\no1 repeat [" + std::to_string(times) + "]\nG1 X1\no1 endrepeat\nM2\n";
  };
  const InterpretResult within = run(repeated(51), bounded(100));
  EXPECT_TRUE(within.ok()) << within.errors.at(0).str();
  EXPECT_EQ(within.program.moves.size(), 51u);
  const InterpretResult past = run(repeated(52), bounded(100));
  ASSERT_FALSE(past.ok());
  EXPECT_EQ(past.errors[0].line, 2u);
}

TEST(gcodeRunBound, LinesReadForTheFirstTimeAreNotCounted) {
  // A Fanuc subprogram after M30: the call reads on to find it, the return reads the main
  // program's lines for the first time as blocks. A long straight program is not a loop.
  std::string main = "G21 G90 F1000\nM98 P100\n";
  for (int i = 0; i < 500; ++i) main += "G1 X" + std::to_string(i % 7) + "\n";
  const InterpretResult r = run(main + "M30\nO100\nG1 Y1\nM99\n", bounded(10));
  EXPECT_TRUE(r.ok()) << r.errors.at(0).str();
  EXPECT_EQ(r.program.moves.size(), 501u);
}

TEST(gcodeRunBound, KeepGoingDoesNotGoOnPastTheBound) {
  InterpreterOptions options = bounded(1000);
  options.keepGoing = true;
  const InterpretResult r = run("G21 G90 F1000\no1 while [1]\nG1 X1\no1 endwhile\nM2\n", options);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].message.find("never ends"), std::string::npos);
}

TEST(gcodeRunBound, AStreamedRunStopsAtTheBoundToo) {
  CountingSink sink;
  const StreamedInterpretation r =
      interpretGcodeStream(neverEndingPrograms()[0].text, "t.ngc", sink, bounded(100000), 1024);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].line, 2u);
  EXPECT_LT(sink.moves, 100000u);
}

TEST(gcodeRunBound, AStreamedRunStopsWhenItsSinkHasStopped) {
  // The simulation's own bound (the machine's longest run) passed: nothing more is read.
  CountingSink sink(5000);
  const StreamedInterpretation r = interpretGcodeStream(neverEndingPrograms()[3].text, "t.ngc", sink, {}, 1024);
  EXPECT_TRUE(r.ok());
  EXPECT_LT(sink.moves, 5000u + 2048u);
}
