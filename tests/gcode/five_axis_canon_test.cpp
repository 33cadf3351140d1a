// Five-axis programs read as LinuxCNC's rs274 reads them: every move's X Y Z and A B C, in
// order, against rs274's STRAIGHT_TRAVERSE, STRAIGHT_FEED and ARC_FEED (rs274 2.9's output,
// recorded beside the programs in tests/data/linuxcnc-2.9-xyzbc-trt). And what is not read of
// the rotary axes is refused with its line, never read as if they stood still.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "gcode_test_support.h"
#include "rs274_canon.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::test;

namespace {

std::filesystem::path folder() { return std::filesystem::path(sourceDir()) / "tests/data/linuxcnc-2.9-xyzbc-trt"; }

std::vector<std::string> programs() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(folder()))
    if (entry.path().extension() == ".ngc") out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string canonOf(const std::string& program) {
  return std::filesystem::path(program).replace_extension(".rs274.canon").string();
}

}  // namespace

TEST(fiveAxisCanon, EveryMoveAndItsRotaryAxesAsRs274ReadsThem) {
  const std::vector<std::string> files = programs();
  ASSERT_GE(files.size(), 10u);
  std::size_t compared = 0, rotaryMoves = 0;
  for (const std::string& program : files) {
    const InterpretResult ours = interpretGcode(readFile(program), program, InterpreterOptions{});
    ASSERT_TRUE(ours.ok()) << ours.errors.front().str();
    const std::vector<Rs274Motion> theirs = rs274Motions(readFile(canonOf(program)));
    std::vector<std::size_t> motion;
    for (std::size_t i = 0; i < ours.program.moves.size(); ++i)
      if (ours.program.moves[i].isMotion()) motion.push_back(i);
    ASSERT_EQ(motion.size(), theirs.size()) << program;
    for (std::size_t k = 0; k < theirs.size(); ++k) {
      const std::size_t i = motion[k];
      EXPECT_LT((ours.program.moves[i].end - theirs[k].end).cwiseAbs().maxCoeff(), 6e-5) << program << " move " << k;
      const std::array<double, 3> abc = ours.program.rotaryAt(i);
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(abc[a], theirs[k].abc[a], 6e-5) << program << " move " << k << " " << "ABC"[a];
      rotaryMoves += theirs[k].abc != std::array<double, 3>{};
    }
    compared += theirs.size();
  }
  EXPECT_GT(compared, 1500u);
  EXPECT_GT(rotaryMoves, 1000u);
}

// Offsets of the rotary axes set to zero while they stand at zero change nothing: read.
TEST(fiveAxisCanon, ZeroOffsetsOfTheRotaryAxesAreRead) {
  EXPECT_TRUE(interpretGcode("G21\nG10 L2 P1 X0 Y0 Z0 A0 B0 C0\nG92 A0\nG1 X1 F100\n", "zero.ngc").ok());
}

TEST(fiveAxisCanon, IncrementalRotaryWordsAddUp) {
  const InterpretResult r = interpretGcode("G21 G90\nG1 X1 B10 F100\nG91\nG1 B5 C-20\nG1 X1 A2.5\n", "inc.ngc");
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_EQ(r.program.moves.size(), 3u);
  EXPECT_EQ(r.program.rotaryAt(0), (std::array<double, 3>{0, 10, 0}));
  EXPECT_EQ(r.program.rotaryAt(1), (std::array<double, 3>{0, 15, -20}));
  EXPECT_EQ(r.program.rotaryAt(2), (std::array<double, 3>{2.5, 15, -20}));
  // An inch program's angles stay degrees.
  const InterpretResult inch = interpretGcode("G20 G90\nG1 X1 C90 F10\n", "inch.ngc");
  ASSERT_TRUE(inch.ok());
  EXPECT_EQ(inch.program.rotaryAt(0)[2], 90);
  // A program that never writes A, B or C has no rotary positions at all.
  EXPECT_TRUE(interpretGcode("G1 X1 F100\n", "plain.ngc").program.rotary.empty());
}

TEST(fiveAxisCanon, WhatIsNotReadOfTheRotaryAxesIsRefusedWithItsLine) {
  const struct {
    const char* program;
    const char* says;
  } refused[] = {
      {"G21\nG92 B10\nG1 X1 B20 F100\n", "after an offset of the rotary axes (G10, G52 or G92 with A, B or C, line 2)"},
      {"G21\nG1 B5 F100\nG28 B0\n", "B word with G28, G30 or G68"},
      {"G21\nG28 C10\n", "C word with G28, G30 or G68"},
      {"G21\nG10 L2 P1 A5\nG0 A1\n", "after an offset of the rotary axes"},
      {"G21\nG81 X1 Y1 Z-1 R1 B5 F100\n", "canned cycle"},
      {"G21 G40\nT1 M6\nG41 D1 G1 X10 Y0 F100\nG1 X20 B10\n", "cutter radius compensation"},
  };
  for (const auto& r : refused) {
    const InterpretResult result = interpretGcode(r.program, "rotary.ngc");
    ASSERT_FALSE(result.ok()) << r.program;
    EXPECT_NE(result.errors.front().str().find(r.says), std::string::npos) << result.errors.front().str();
    EXPECT_GT(result.errors.front().line, 1u) << r.program;
  }
}
