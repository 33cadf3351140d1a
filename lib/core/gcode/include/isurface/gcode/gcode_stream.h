#pragma once
// Interpreting G-code of any size in bounded memory. The moves are handed to a sink in chunks
// as they are made, instead of being kept in a Program; a file is read through a mapping whose
// pages are released behind the reader. Same interpreter as interpretGcode: the same moves,
// lines, warnings and errors (file:line:column), only delivered as they come.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "isurface/gcode/gcode_interpreter.h"

namespace isurface {

class MoveSink {
 public:
  virtual ~MoveSink() = default;
  // `count` consecutive moves; `firstIndex` is the index of moves[0] in the whole program.
  // The moves are final: no later block changes them.
  virtual void consume(const Move* moves, std::size_t count, std::uint64_t firstIndex) = 0;
  // The same for every move in `moves`, which the sink may take whole by swapping the vector
  // with an empty one of its own (returning true) instead of copying them; false: consume()
  // is called instead.
  virtual bool adopt(std::vector<Move>& moves, std::uint64_t firstIndex) {
    (void)moves, (void)firstIndex;
    return false;
  }
  // G64's tolerances from move `blending.firstMove` on; told before that move is consumed.
  virtual void blendingChanged(const PathBlending& blending) { (void)blending; }
  // A, B and C at the end of move `rotary.move` on; told before that move is consumed.
  virtual void rotaryChanged(const RotaryPosition& rotary) { (void)rotary; }
  // True once the sink takes no more moves (its run is over: an error it keeps, a bound passed):
  // the interpretation then stops, instead of making moves no one uses.
  virtual bool stopped() const { return false; }
};

// What interpretGcodeStream leaves besides the moves: a Program without its moves.
struct StreamedInterpretation {
  std::string source;
  Vec3 start = Vec3::Zero();         // position before the first move, mm
  std::vector<Diagnostic> warnings;
  std::vector<Diagnostic> errors;    // empty on success; with keepGoing, every bad block
  std::uint32_t lineCount = 0;       // physical lines in the source
  std::uint64_t moveCount = 0;       // moves handed to the sink
  bool ok() const { return errors.empty(); }
};

// Moves per chunk by default: 4 MB of moves.
constexpr std::size_t kDefaultMoveChunk = std::size_t{1} << 16;

// Interprets text held in memory; moves reach `sink` in chunks of at most `chunkMoves` (>= 1),
// the last one when the text has been read. An exception thrown by the sink stops the
// interpretation and is passed on; a sink that says it has stopped ends it too, the error being
// the sink's to tell.
StreamedInterpretation interpretGcodeStream(std::string_view text, const std::string& sourceName,
                                            MoveSink& sink, const InterpreterOptions& options = {},
                                            std::size_t chunkMoves = kDefaultMoveChunk);

// The same on a file. A regular file is mapped without being read in ahead and the pages already
// interpreted are released as the reader moves on, so that the memory used does not grow with
// the file: chunkMoves x 64 bytes of moves, plus a few MB of the file. A pipe is read whole.
StreamedInterpretation interpretGcodeFileStream(const std::string& path, MoveSink& sink,
                                                const InterpreterOptions& options = {},
                                                std::size_t chunkMoves = kDefaultMoveChunk);

}  // namespace isurface
