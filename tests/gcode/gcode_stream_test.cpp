// Streaming interpretation: the same moves, lines, warnings and errors as the whole program,
// whatever the chunk size, with chunk boundaries inside blocks that make several moves.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/gcode_stream.h"
#include "program_corpus.h"

using namespace isurface;

namespace {

// Keeps every chunk, checking that they follow each other and respect the chunk size.
class CollectingSink : public MoveSink {
 public:
  explicit CollectingSink(std::size_t chunkMoves) : chunkMoves_(chunkMoves) {}
  void consume(const Move* moves, std::size_t count, std::uint64_t firstIndex) override {
    EXPECT_EQ(firstIndex, moves_.size());
    EXPECT_GE(count, 1u);
    EXPECT_LE(count, chunkMoves_);
    moves_.insert(moves_.end(), moves, moves + count);
    ++chunks_;
  }
  std::vector<Move> moves_;
  std::size_t chunks_ = 0;

 private:
  std::size_t chunkMoves_;
};

bool sameMove(const Move& a, const Move& b) {
  return a.end == b.end && a.centre == b.centre && a.line == b.line && a.feed == b.feed && a.kind == b.kind &&
         a.plane == b.plane && a.flags == b.flags && a.turns == b.turns;
}

void expectSameMoves(const std::vector<Move>& streamed, const std::vector<Move>& whole) {
  ASSERT_EQ(streamed.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i)
    if (!sameMove(streamed[i], whole[i])) {
      ADD_FAILURE() << "move " << i << " (line " << whole[i].line << ") differs";
      return;
    }
}

void expectSameDiagnostics(const std::vector<Diagnostic>& a, const std::vector<Diagnostic>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].str(), b[i].str());
}

// Streams `text` in chunks of `chunkMoves` and compares everything with interpretGcode.
void expectStreamMatchesWhole(const std::string& text, std::size_t chunkMoves, InterpreterOptions options = {}) {
  SCOPED_TRACE("chunk of " + std::to_string(chunkMoves) + " moves");
  const InterpretResult whole = interpretGcode(text, "t.ngc", options);
  CollectingSink sink(chunkMoves);
  const StreamedInterpretation streamed = interpretGcodeStream(text, "t.ngc", sink, options, chunkMoves);
  EXPECT_EQ(streamed.source, whole.program.source);
  EXPECT_EQ(streamed.start, whole.program.start);
  EXPECT_EQ(streamed.lineCount, whole.program.lineCount);
  EXPECT_EQ(streamed.moveCount, whole.program.moves.size());
  expectSameDiagnostics(streamed.warnings, whole.program.warnings);
  expectSameDiagnostics(streamed.errors, whole.errors);
  expectSameMoves(sink.moves_, whole.program.moves);
}

// Every size of chunk that puts a boundary somewhere inside these short programs.
void expectStreamMatchesWholeForSmallChunks(const std::string& text, InterpreterOptions options = {}) {
  for (std::size_t chunk : {1, 2, 3, 5, 1000}) expectStreamMatchesWhole(text, chunk, options);
}

}  // namespace

TEST(GcodeStream, ArcsAndHelicesAcrossChunkBoundaries) {
  expectStreamMatchesWholeForSmallChunks(
      "G21 G90 G17 F600\nG0 X10 Y0\nG2 X0 Y10 I-10 J0\nG3 X-10 Y0 R10\nG2 X-10 Y0 I10 J0 Z-2 P3\n"
      "G18 G2 X0 Z-12 I10 K0\nG19 G3 Y20 Z-2 R10\nG17 G1 X0 Y0\n");
}

TEST(GcodeStream, CannedCyclesMakeSeveralMovesPerBlock) {
  // Each hole is a rapid, the feed down and a retract: a chunk of 1 or 2 moves ends inside it.
  expectStreamMatchesWholeForSmallChunks(
      "G21 G90 F200\nG0 Z5\nG99 G81 X0 Y0 Z-3 R1\nX10\nG91 X5 L4\nG90 G83 X20 Y5 Z-9 R1 Q2\n"
      "G73 X25 Z-6 R1 Q1.5\nG82 X30 Z-2 R1 P0.5\nG80 G0 Z10\nM2\n");
}

TEST(GcodeStream, StopsMarkTheMoveBeforeThemAcrossAChunkBoundary) {
  // M0, M6 and spindle changes mark the move before them as ending at rest: with one move per
  // chunk that move must not have been handed over yet.
  const std::string text = "G21 F1000\nG1 X10\nM0\nG1 X20\nT2 M6\nG1 X30\nS9000 M3\nG1 X40\nG4 P2\nM1\nG1 X50\nM30\n";
  expectStreamMatchesWholeForSmallChunks(text);
  CollectingSink sink(1);
  interpretGcodeStream(text, "t.ngc", sink, {}, 1);
  ASSERT_GE(sink.moves_.size(), 4u);
  EXPECT_TRUE(sink.moves_[0].flags & kStopAfter);
  EXPECT_TRUE(sink.moves_[1].flags & kStopAfter);
  EXPECT_TRUE(sink.moves_[2].flags & kStopAfter);
}

TEST(GcodeStream, ErrorsStopAtTheSameMoveAndNameTheLine) {
  const std::string text = "G21 F500\nG1 X1\nG1 X2\nG2 X3 Y3 I0.1 J0\nG1 X4\nG1 X5 X6\nG1 X7\n";
  expectStreamMatchesWholeForSmallChunks(text);
  CollectingSink sink(1);
  const StreamedInterpretation r = interpretGcodeStream(text, "t.ngc", sink, {}, 1);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].line, 4u);
  EXPECT_NE(r.errors[0].str().find("t.ngc:4:"), std::string::npos) << r.errors[0].str();
  EXPECT_EQ(sink.moves_.size(), 2u);  // the moves before the bad block, all handed over
}

TEST(GcodeStream, KeepGoingSkipsBadBlocksAcrossChunks) {
  InterpreterOptions options;
  options.keepGoing = true;
  // A bad canned cycle block after a good one, a bad arc, unknown codes, more moves after them.
  expectStreamMatchesWholeForSmallChunks(
      "G21 F500\nG1 X1\nG81 X2 Z-1 R1\nG81 X3 Z-1\nG2 X3 Y3 I0.1 J0\nG1 X4\nG7\nG1 X5 X6\nG80\nG1 X7 Y1\n"
      "G2 X9 Y3 I2 J0\n",
      options);
}

TEST(GcodeStream, LinesAfterTheProgramEndStillCount) {
  expectStreamMatchesWholeForSmallChunks("G1 X1 F100\nM2\nG1 X2\nG1 X3\nno newline at the end");
  expectStreamMatchesWholeForSmallChunks("%\nG1 X1 F100\n%\nG1 X2\n\n");
  expectStreamMatchesWholeForSmallChunks("");
  expectStreamMatchesWholeForSmallChunks("\xEF\xBB\xBF");
  expectStreamMatchesWholeForSmallChunks("\xEF\xBB\xBFG0 X1\r\nG0 X2");
}

TEST(GcodeStream, AnExceptionFromTheSinkStopsTheInterpreter) {
  struct FailingSink : MoveSink {
    void consume(const Move*, std::size_t, std::uint64_t) override { throw std::runtime_error("disk full"); }
  } sink;
  EXPECT_THROW(interpretGcodeStream("G0 X1\nG0 X2\nG0 X3\n", "t.ngc", sink, {}, 1), std::runtime_error);
}

TEST(GcodeStream, FilesMissingOrNotFilesAreErrors) {
  CollectingSink sink(16);
  const StreamedInterpretation missing = interpretGcodeFileStream("/nonexistent/x.ngc", sink);
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_NE(missing.errors[0].str().find("cannot open"), std::string::npos);
  const StreamedInterpretation folder = interpretGcodeFileStream("/tmp", sink);
  ASSERT_EQ(folder.errors.size(), 1u);
  EXPECT_NE(folder.errors[0].str().find("is a directory"), std::string::npos);
  EXPECT_TRUE(sink.moves_.empty());
}

// The bundled samples and the real programs: mapped files, default and odd chunk sizes.
TEST(GcodeStream, SamplesAndRealProgramsMatchTheWholeProgram) {
  for (const std::string& path : test::samplesAndRealPrograms()) {
    SCOPED_TRACE(path);
    const InterpretResult whole = interpretGcodeFile(path);
    ASSERT_TRUE(whole.ok());
    for (std::size_t chunk : {std::size_t{997}, kDefaultMoveChunk}) {
      CollectingSink sink(chunk);
      const StreamedInterpretation streamed = interpretGcodeFileStream(path, sink, {}, chunk);
      EXPECT_TRUE(streamed.ok());
      EXPECT_EQ(streamed.lineCount, whole.program.lineCount);
      expectSameDiagnostics(streamed.warnings, whole.program.warnings);
      expectSameMoves(sink.moves_, whole.program.moves);
      if (whole.program.moves.size() > chunk) {
        EXPECT_GT(sink.chunks_, 1u);
      }
    }
  }
}
