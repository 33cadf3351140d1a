// Errors located at file:line:column, stopping or going on, and degenerate inputs.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "isurface/gcode/gcode_interpreter.h"
#include "gcode_test_support.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

std::string writeScratch(const std::string& name, const std::string& content) {
  const std::string path = (test::scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

}  // namespace

TEST(gcodeErrors, LocatedAtTheOffendingWord) {
  EXPECT_EQ(firstError("G0 X1\n  G1 X1..2 F10\n"),
            "t.ngc:2:6: Bad number format (trailing characters) parsing '1..2'");
  EXPECT_EQ(firstError("G0 X1\nG6 X1\n"), "t.ngc:2:1: Unknown g code used: G6");
  EXPECT_EQ(firstError("G0 X1\nG7 X1\n"), "t.ngc:2:1: G7 is not supported");
  EXPECT_EQ(firstError("G1.5 X1\n"), "t.ngc:1:1: Unknown g code used: G1.5");
  EXPECT_EQ(firstError("G0 G1.25 X1\n"), "t.ngc:1:4: Unknown g code used: G1.25");
  EXPECT_EQ(firstError("G0 X1 Y2 y3\n"), "t.ngc:1:10: Multiple y words on one line");
  EXPECT_EQ(firstError("G0 G1 X1 F100\n"),
            "t.ngc:1:4: Two g codes used from same modal group: G0 and G1");
  EXPECT_EQ(firstError("G17 G90 G18\n"),
            "t.ngc:1:9: Two g codes used from same modal group: G17 and G18");
  EXPECT_EQ(firstError("G20 G21\n"), "t.ngc:1:5: Two g codes used from same modal group: G20 and G21");
  EXPECT_EQ(firstError("G4 P1 G28\n"),
            "t.ngc:1:7: Two g codes used from same modal group: G4 and G28");
  EXPECT_EQ(firstError("M3 M5\n"), "t.ngc:1:4: Two m codes used from same modal group: M3 and M5");
  EXPECT_EQ(firstError("G1 X1\n"), "t.ngc:1:1: Cannot do G1 with zero feed rate");
  EXPECT_EQ(firstError("G0 X0\nG1 F0\n  X1\n"), "t.ngc:3:3: Cannot do G1 with zero feed rate");
  EXPECT_EQ(firstError("G33 X1 K1\n"), "t.ngc:1:1: G33 is not supported");
  EXPECT_EQ(firstError("G0 X1 E2\n"), "t.ngc:1:7: Unknown word starting with E");
}

TEST(gcodeErrors, StopAtTheFirstErrorKeepingEarlierMoves) {
  const InterpretResult r = run("G0 X1\nG0 X2 X3\nG0 X4\n");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].line, 2u);
  EXPECT_EQ(r.errors[0].file, "t.ngc");
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].end.x(), 1);
  EXPECT_FALSE(r.ok());
}

TEST(gcodeErrors, KeepGoingCollectsEveryBadBlock) {
  InterpreterOptions options;
  options.keepGoing = true;
  const InterpretResult r =
      run("G0 X1\nG0 X2 X3\nG6\nG0 X4\nG1 X5\nG0 X6\nG2 X1 Y1\n", options);
  ASSERT_EQ(r.errors.size(), 4u);
  EXPECT_EQ(r.errors[0].str(), "t.ngc:2:7: Multiple x words on one line");
  EXPECT_EQ(r.errors[1].str(), "t.ngc:3:1: Unknown g code used: G6");
  EXPECT_EQ(r.errors[2].str(), "t.ngc:5:1: Cannot do G1 with zero feed rate");
  EXPECT_EQ(r.errors[3].line, 7u);
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_EQ(r.program.moves[0].end.x(), 1);
  EXPECT_EQ(r.program.moves[1].end.x(), 4);
  EXPECT_EQ(r.program.moves[1].line, 4u);
  EXPECT_EQ(r.program.moves[2].end.x(), 6);
}

TEST(gcodeErrors, ABadBlockChangesNoModalState) {
  InterpreterOptions options;
  options.keepGoing = true;
  // G91 and G20 of the bad block must not stay in effect.
  const InterpretResult r = run("G0 X1\nG91 G20 G1 X1\nG0 X5\n", options);
  ASSERT_EQ(r.errors.size(), 1u);
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[1].end.x(), 5);
}

TEST(gcodeErrors, EmptyAndBlankInputs) {
  for (const std::string text : {"", "\n", "\n\n\r\n", "   \t  ", "(only a comment)\n", "%\n%\n"}) {
    const InterpretResult r = run(text);
    EXPECT_TRUE(r.ok()) << text;
    EXPECT_TRUE(r.program.moves.empty());
  }
  EXPECT_EQ(run("").program.lineCount, 0u);
  EXPECT_EQ(run("\n\n").program.lineCount, 2u);
}

TEST(gcodeErrors, BinaryJunkGivesErrorsNotCrashes) {
  std::mt19937 random(42);
  std::string junk(1 << 20, '\0');
  for (char& c : junk) c = static_cast<char>(random() & 0xff);
  InterpretResult r = run(junk);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.errors.size(), 1u);

  InterpreterOptions options;
  options.keepGoing = true;
  r = run(junk, options);
  EXPECT_FALSE(r.ok());
  // Interpretation gives up after 1000 bad blocks.
  EXPECT_LE(r.errors.size(), 1001u);
  EXPECT_GT(r.errors.size(), 100u);
  // A NUL byte inside a line is a bad character like any other.
  EXPECT_EQ(firstError(std::string("G0 X1\0", 6)), "t.ngc:1:6: Bad character used: '\\x00'");
}

TEST(gcodeErrors, GiganticLines) {
  // A 20 MB comment line, then a move.
  std::string text = "(" + std::string(20 << 20, 'a') + ")\nG0 X1\n";
  InterpretResult r = run(text);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].line, 2u);
  // Blanks inside a number, millions of them.
  r = run("G0 X1" + std::string(5 << 20, ' ') + "2\n");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.program.moves[0].end.x(), 12);
  // An error far to the right is located there.
  r = run(std::string(3 << 20, ' ') + "G0 X1 X2\n");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].column, (3u << 20) + 7);
  // Too many words on one line.
  std::string many;
  for (int i = 0; i < 20; ++i) many += "G90 ";
  EXPECT_EQ(firstError(many), "t.ngc:1:65: Too many G words on one line");
}

TEST(gcodeErrors, AbsurdExpansionsAreRefused) {
  EXPECT_EQ(firstError("G2 X0 Y0 I1 P100000 F100\n"),
            "t.ngc:1:13: P value too large with G2 or G3 (over 10000 turns)");
  EXPECT_EQ(firstError("G0 Z10\nG81 X1 Y1 Z-1 R1 L1000000 F100\n"),
            "t.ngc:2:18: L word too large (over 100000 repeats)");
  EXPECT_EQ(firstError("G0 Z10\nG83 X1 Y1 Z-1 R1 Q0.01 L100000 F100\n"),
            "t.ngc:2:1: Canned cycle expands to too many moves (L and Q)");
}

TEST(gcodeErrors, Files) {
  InterpretResult r = interpretGcodeFile("/nonexistent/x.ngc");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].str(), "/nonexistent/x.ngc: cannot open: No such file or directory");

  r = interpretGcodeFile(test::scratchDir().string());
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].message.find("directory"), std::string::npos);

  r = interpretGcodeFile(writeScratch("empty.ngc", ""));
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.program.moves.empty());

  r = interpretGcodeFile("/dev/null");
  EXPECT_TRUE(r.ok());

  const std::string path = writeScratch("two.ngc", "G0 X1\nG0 X2 X3\n");
  r = interpretGcodeFile(path);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].str(), path + ":2:7: Multiple x words on one line");
  EXPECT_EQ(r.program.source, path);
  EXPECT_EQ(r.program.moves.size(), 1u);
}

TEST(gcodeErrors, ProgressIsReported) {
  std::string text;
  for (int i = 0; i < 200000; ++i) text += "G1 X1 Y2 F100\n";
  std::vector<double> fractions;
  InterpreterOptions options;
  options.progress = [&](double f) { fractions.push_back(f); };
  const InterpretResult r = run(text, options);
  ASSERT_TRUE(r.ok());
  ASSERT_GE(fractions.size(), 3u);
  for (std::size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1]);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_GT(fractions.front(), 0.0);
  // Moves are stored compactly: the reserve follows the line count.
  EXPECT_LE(r.program.moves.capacity(), r.program.moves.size() + r.program.moves.size() / 4 + 64);
}
