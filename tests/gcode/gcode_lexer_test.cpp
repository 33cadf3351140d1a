// Reading G-code text: numbers, words, comments, spacing, case, line ends, block delete.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "gcode_test_support.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::gcodetest;

namespace {

Vec3 onlyEnd(const std::string& text) {
  const InterpretResult r = run(text);
  EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].str());
  EXPECT_EQ(r.program.moves.size(), 1u);
  return r.program.moves.empty() ? Vec3(Vec3::Constant(-999)) : r.program.moves.back().end;
}

}  // namespace

TEST(gcodeLexer, NumberFormats) {
  EXPECT_EQ(onlyEnd("G0 X75. Y-.5 Z+.25"), Vec3(75, -0.5, 0.25));
  EXPECT_EQ(onlyEnd("G0 X0 Y-0 Z007"), Vec3(0, 0, 7));
  EXPECT_EQ(onlyEnd("G0 X1.500 Y-12.345 Z.0001"), Vec3(1.5, -12.345, 0.0001));
  // Exactly what strtod gives, short and long numbers alike.
  const char* const texts[] = {"0.1", "123.456789012345", "1.00000000000000000001",
                               "0.000000000000000000000000123", "987654321.5"};
  for (const char* t : texts) {
    const Vec3 e = onlyEnd(std::string("G0 X") + t);
    EXPECT_EQ(e.x(), std::strtod(t, nullptr)) << t;
  }
}

TEST(gcodeLexer, SpacingAndCase) {
  EXPECT_EQ(onlyEnd("G0X1Y2Z3"), Vec3(1, 2, 3));
  EXPECT_EQ(onlyEnd("g0 x1 y2 z3"), Vec3(1, 2, 3));
  EXPECT_EQ(onlyEnd("   \tG0 X1"), Vec3(1, 0, 0));
  // RS274/NGC ignores blanks, even inside numbers.
  const InterpretResult r = run("G 1 X 1 0 Y - 2 . 5 F 1 0 0");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].end, Vec3(10, -2.5, 0));
  EXPECT_EQ(r.program.moves[0].feed, 100.0f);
  EXPECT_EQ(r.program.moves[0].kind, MoveKind::Linear);
  EXPECT_EQ(onlyEnd("G00 X1"), Vec3(1, 0, 0));
}

TEST(gcodeLexer, CommentsAndLineEnds) {
  const InterpretResult r =
      run("(header comment)\r\nG0 X1 (inline) Y2 ; to the end X9\r\n; whole line\r\nG0 Z3\r\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[0].end, Vec3(1, 2, 0));
  EXPECT_EQ(r.program.moves[0].line, 2u);
  EXPECT_EQ(r.program.moves[1].end, Vec3(1, 2, 3));
  EXPECT_EQ(r.program.moves[1].line, 4u);
  EXPECT_EQ(r.program.lineCount, 4u);
}

TEST(gcodeLexer, ByteOrderMarkIsSkipped) {
  const InterpretResult r = run("\xEF\xBB\xBFG0 X1\nG0 X2 X3\n");
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].line, 1u);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].str(), "t.ngc:2:7: Multiple x words on one line");
}

TEST(gcodeLexer, LastLineWithoutNewline) {
  const InterpretResult r = run("G0 X1\nG0 X2");
  ASSERT_EQ(r.program.moves.size(), 2u);
  EXPECT_EQ(r.program.moves[1].line, 2u);
  EXPECT_EQ(r.program.lineCount, 2u);
}

TEST(gcodeLexer, BlockDelete) {
  const InterpretResult r = run("/G0 X5\n  /G0 X6 (skipped)\nG0 X1\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].end.x(), 1);
  EXPECT_EQ(r.program.moves[0].line, 3u);
}

TEST(gcodeLexer, PercentLines) {
  // A program that opens with '%' ends at the next '%'.
  InterpretResult r = run("%\nG0 X1\n%\nG0 X2\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.lineCount, 4u);
  // Otherwise a '%' line is just skipped.
  r = run("G0 X1\n%\nG0 X2\n");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.program.moves.size(), 2u);
}

TEST(gcodeLexer, CoordinateOnlyLinesContinueTheMotion) {
  const InterpretResult r = run("G1 X1 F100\nY2\n Z-1\nG0 X0\nY0\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.program.moves.size(), 5u);
  EXPECT_EQ(r.program.moves[1].kind, MoveKind::Linear);
  EXPECT_EQ(r.program.moves[1].end, Vec3(1, 2, 0));
  EXPECT_EQ(r.program.moves[2].end, Vec3(1, 2, -1));
  EXPECT_EQ(r.program.moves[2].line, 3u);
  EXPECT_EQ(r.program.moves[4].kind, MoveKind::Rapid);
  EXPECT_EQ(r.program.moves[4].end, Vec3(0, 0, -1));
}

TEST(gcodeLexer, LineNumbersAndOtherWordsAreAccepted) {
  const InterpretResult r = run("N10 G0 X1 S1000 T2 M3\nN20 G43 H2 D1 G1 X2 F50\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  EXPECT_EQ(r.program.moves.size(), 2u);
}

TEST(gcodeLexer, BadNumbers) {
  EXPECT_EQ(firstError("G1 X1..2 F10"),
            "t.ngc:1:4: Bad number format (trailing characters) parsing '1..2'");
  EXPECT_EQ(firstError("G0 X-"), "t.ngc:1:4: Bad number format parsing '-'");
  EXPECT_EQ(firstError("G0 X Y1"), "t.ngc:1:4: Bad number format: X word without a number");
  EXPECT_EQ(firstError("G0 X1-2"), "t.ngc:1:4: Bad number format (trailing characters) parsing '1-2'");
  EXPECT_EQ(firstError("G0 Xnan"), "t.ngc:1:4: Bad number format: X word without a number");
  EXPECT_EQ(firstError("G0 Xinf"), "t.ngc:1:4: Bad number format: X word without a number");
  // Exponents are not G-code: E is not a word here.
  EXPECT_EQ(firstError("G0 X1e400"), "t.ngc:1:6: Unknown word starting with E");
  EXPECT_EQ(firstError("G0 X" + std::string(400, '9')).substr(0, 30), "t.ngc:1:4: Number out of range");
  EXPECT_EQ(firstError("G0 X12345678901"), "t.ngc:1:4: Number out of range: '12345678901'");
}

TEST(gcodeLexer, BadWordsAndCharacters) {
  EXPECT_EQ(firstError("G0 X1 X2"), "t.ngc:1:7: Multiple x words on one line");
  EXPECT_EQ(firstError("G1 F10 F20 X1"), "t.ngc:1:8: Multiple f words on one line");
  EXPECT_EQ(firstError("G0 [1+2]"), "t.ngc:1:4: An expression must stand where a word's number does (after its letter)");
  EXPECT_EQ(firstError("G0 X[1+2"), "t.ngc:1:5: Unclosed expression (missing ']')");
  EXPECT_EQ(firstError("G0 (a (b) c) X1"), "t.ngc:1:7: Nested comment found");
  EXPECT_EQ(firstError("G0 X1 (open"), "t.ngc:1:7: Unclosed comment found");
  EXPECT_EQ(firstError("G0 X1 *5"), "t.ngc:1:7: Bad character used: '*'");
  EXPECT_EQ(firstError(std::string("G0 X1 \x01")), "t.ngc:1:7: Bad character used: '\\x01'");
  EXPECT_EQ(firstError("12 G0"), "t.ngc:1:1: Number 12 without a letter");
  EXPECT_EQ(firstError("G0 X1 (c) 12"), "t.ngc:1:11: Number 12 without a letter");
  EXPECT_EQ(firstError("G0 12"), "t.ngc:1:1: Unknown g code used: G12");  // blanks inside numbers
  EXPECT_EQ(firstError("G0 X1 / Y2"), "t.ngc:1:7: Bad character used: '/'");
}

// Plain blocks (letters, plain numbers, blanks, comments) are read by a quicker path than blocks
// with parameters or expressions: a parameter setting added to a block changes nothing else.
TEST(gcodeLexer, PlainBlocksReadAsTheGeneralLexerReadsThem) {
  const char* const blocks[] = {
      "G1 X1.5 Y-2 Z.25 F100", "g1x-.5y+7.000z1 f 100", "N10 G0 X1 (move) Y2 ; rest",
      "G1 X0.00005 Y123456789 Z-0", "G1 X1 (a(b) Y2", "G1 X1 (open", "G1 X1 X2", "G1 X1.2.3",
      "G1 X- 1", "G1 X 1", "G1 X1 2", "G1 X1 E2", "G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1 G1",
      "M3 M5 M3 M5 M3 M5 M3 M5 M3 G1 X1 F10", "G1 X1 Y2 Z3 F100 S1000 T1 M3", "G90.1 G17.5 X1",
      "G1 X1234567890 F1", "G1 X1.0000000000000001 F1", "G1\tX1\rY2\fZ3 F1", "G1 X#1"};
  for (const char* block : blocks) {
    const std::string plain = std::string("G21 F50\n") + block + "\n";
    const std::string general = std::string("G21 F50\n") + block + " #100=1\n";
    const InterpretResult a = gcodetest::run(plain);
    const InterpretResult b = gcodetest::run(general);
    ASSERT_EQ(a.errors.size(), b.errors.size()) << block;
    for (std::size_t i = 0; i < a.errors.size(); ++i)
      EXPECT_EQ(a.errors[i].str(), b.errors[i].str()) << block;
    ASSERT_EQ(a.program.moves.size(), b.program.moves.size()) << block;
    for (std::size_t i = 0; i < a.program.moves.size(); ++i) {
      EXPECT_EQ(a.program.moves[i].end, b.program.moves[i].end) << block;
      EXPECT_EQ(a.program.moves[i].feed, b.program.moves[i].feed) << block;
    }
  }
}

TEST(gcodeLexer, OWordLines) {
  // A program number is a label and nothing more.
  InterpretResult r = run("O1000 (program number)\nG21 G0 X1\n");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.program.moves.size(), 1u);
  EXPECT_TRUE(r.program.warnings.empty());
  // Control flow is executed (gcode_control_flow_test.cpp): a subroutine never called does not run.
  r = run("G21\no<square> sub\nG0 X1\no<square> endsub\nO100 if [1 GT 0]\nG0 X2\nO100 endif\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  ASSERT_EQ(r.program.moves.size(), 1u);
  EXPECT_EQ(r.program.moves[0].end.x(), 2.0);
  EXPECT_TRUE(r.program.warnings.empty());
  EXPECT_EQ(firstError("G0 X1 O100"), "t.ngc:1:7: An O-word must start the block");
}

TEST(gcodeLexer, UnknownMCodesAreIgnored) {
  const InterpretResult r = run("G21 M7 M8\nM123\nG0 X1 M9\nM48 M49\n");
  ASSERT_TRUE(r.ok()) << r.errors[0].str();
  EXPECT_EQ(r.program.moves.size(), 1u);
}
