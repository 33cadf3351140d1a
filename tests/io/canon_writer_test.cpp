// The canon listing written while the program is interpreted (the lines formatted on a second
// thread): the same lines as a plain printf-style formatting of the interpreted program, on
// programs of many more moves than are handed over at once, and write failures reported.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/io/canon_writer.h"
#include "test_support.h"

namespace isurface {
namespace {

std::string fixed4(double v) {
  const std::string text = fmt::format("{:.4f}", v);
  return text == "-0.0000" ? "0.0000" : text;
}

// Feeds are floats: the decimal the float stands for (docs/canon-format.md).
std::string feedText(float f) { return fixed4(std::strtod(fmt::format("{}", f).c_str(), nullptr)); }

// docs/canon-format.md, written the obvious way.
std::string referenceListing(const Program& program) {
  std::string out;
  for (const Move& m : program.moves) {
    out += std::to_string(m.line);
    if (m.kind == MoveKind::Dwell) {
      out += " G4 P" + fixed4(m.dwellSeconds()) + "\n";
      continue;
    }
    const char* const code = m.kind == MoveKind::Rapid    ? " G0 "
                             : m.kind == MoveKind::Linear ? " G1 "
                             : m.kind == MoveKind::ArcCW  ? " G2 "
                                                          : " G3 ";
    out += code;
    for (int i = 0; i < 3; ++i) out += fixed4(m.end[i]) + " ";
    if (m.isArc()) {
      for (int i = 0; i < 3; ++i) out += fixed4(m.centre[i]) + " ";
      out += "G" + std::to_string(static_cast<int>(m.plane)) + " " + std::to_string(m.turns) + " ";
    }
    out += (m.kind == MoveKind::Rapid ? std::string("0.0000") : feedText(m.feed)) + "\n";
  }
  return out;
}

// Many kinds of moves and numbers: rapids, feeds in mm and inch, arcs, dwells, values near zero
// on both sides, rounding ties, long and negative coordinates. 40,000 moves or so.
std::string mixedProgram() {
  std::string text = "G21 G90 G17\nG0 X0 Y0 Z5\n";
  unsigned seed = 12345;
  auto next = [&seed] {
    seed = seed * 1103515245u + 12345u;
    return (seed >> 8) % 100000;
  };
  for (int block = 0; block < 4000; ++block) {
    if (block == 2000) text += "G20\n";
    text += fmt::format("G1 X{:.4f} Y-{:.5f} Z0.00005 F{}\n", next() / 7.0, next() / 1e6, 100 + next() % 900);
    for (int k = 0; k < 6; ++k)
      text += fmt::format("X{:.4f} Y{:.3f} Z-0.00004\n", (next() - 50000.0) / 13.0, next() / 3.0);
    text += "G0 Z1.23455\nG4 P0.25\n";
    text += fmt::format("G1 X10 Y10 F{:.1f}\nG2 X12 Y10 I1 J0\nG3 X10 Y10 I-1 J0 P2\n",
                        50 + next() % 500 / 10.0);
  }
  return text + "M2\n";
}

std::string writeScratch(const std::string& name, const std::string& content) {
  const std::string path = (test::scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

TEST(canonWriter, FileListsEveryMoveAsPrintfWould) {
  const std::string text = mixedProgram();
  const InterpretResult whole = interpretGcode(text, "mixed.ngc");
  ASSERT_TRUE(whole.ok()) << whole.errors[0].str();
  ASSERT_GT(whole.program.moves.size(), 40000u);
  const std::string input = writeScratch("mixed.ngc", text);
  const std::string output = (test::scratchDir() / "mixed.canon").string();
  std::string writeError;
  const StreamedInterpretation streamed = interpretToPath(input, {}, output, writeError);
  EXPECT_TRUE(streamed.ok());
  EXPECT_EQ(writeError, "");
  EXPECT_EQ(streamed.moveCount, whole.program.moves.size());
  EXPECT_TRUE(test::readFile(output) == referenceListing(whole.program));
}

TEST(canonWriter, StandardOutputGetsTheSameLines) {
  const std::string text = mixedProgram();
  const std::string input = writeScratch("stdout.ngc", text);
  const std::string output = (test::scratchDir() / "stdout.canon").string();
  const int file = ::open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  ASSERT_GE(file, 0);
  std::fflush(stdout);
  const int saved = ::dup(STDOUT_FILENO);
  ::dup2(file, STDOUT_FILENO);
  int error = 0;
  const StreamedInterpretation streamed = interpretToStdout(input, {}, error);
  ::dup2(saved, STDOUT_FILENO);
  ::close(saved);
  ::close(file);
  EXPECT_TRUE(streamed.ok());
  EXPECT_EQ(error, 0);
  EXPECT_TRUE(test::readFile(output) == referenceListing(interpretGcode(text, "stdout.ngc").program));
}

TEST(canonWriter, WriteFailuresAreReported) {
  if (!test::fileExists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  // Megabytes of lines into a full device: the failure of the first write is the one reported,
  // and the program is still read to its end.
  std::string text = mixedProgram();
  text.insert(text.size() - 3, "G0 X1 X2\n");  // before the M2
  const std::string input = writeScratch("full.ngc", text);
  std::string writeError;
  const StreamedInterpretation streamed = interpretToPath(input, {}, "/dev/full", writeError);
  EXPECT_EQ(writeError, "/dev/full: cannot write: No space left on device");
  ASSERT_EQ(streamed.errors.size(), 1u);
  EXPECT_NE(streamed.errors[0].message.find("Multiple x words"), std::string::npos)
      << streamed.errors[0].str();
  // A folder that does not exist: no file, the error, and the moves still counted.
  const std::string missing = (test::scratchDir() / "no-such-dir" / "x.canon").string();
  writeError.clear();
  const StreamedInterpretation counted = interpretToPath(input, {}, missing, writeError);
  EXPECT_NE(writeError.find("cannot write"), std::string::npos) << writeError;
  EXPECT_GT(counted.moveCount, 40000u);
}

}  // namespace
}  // namespace isurface
