#pragma once
// Reading one RS274/NGC block (one physical line) into its words. Private to the core library.
#include <cstdint>
#include <string>

namespace isurface::gcode {

// Letters are indexed 0..25 ('A'..'Z').
constexpr int letterIndex(char upper) { return upper - 'A'; }
constexpr std::uint32_t letterBit(char upper) { return 1u << letterIndex(upper); }

constexpr int kMaxGWords = 16;
constexpr int kMaxMWords = 8;

enum class BlockKind : std::uint8_t {
  Normal,   // words (possibly none: a blank or comment-only line)
  Deleted,  // starts with '/': block delete, skipped
  Percent,  // a '%' demarcation line
  OWord,    // an O-word line: a program number or control flow (gcode_control_flow.h)
  SenderCommand,  // a line for the program's sender, not G-code: grbl's `$H`, `$$`, ...
  SenderComment,  // a sender's `# text` comment line (not a parameter setting)
};

struct Block {
  BlockKind kind = BlockKind::Normal;
  std::uint32_t present = 0;    // letterBit() of every word given, except G and M
  double value[26];             // value of each present word, as written (program units)
  std::uint32_t column[26];     // 1-based column of each present word's letter
  int gCount = 0;
  int g[kMaxGWords];            // G codes in tenths: G1 -> 10, G90.1 -> 901; -1 if not tenths
  double gValue[kMaxGWords];    // as written, for messages
  std::uint32_t gColumn[kMaxGWords];
  int mCount = 0;
  int m[kMaxMWords];            // M codes in tenths, like G codes
  std::uint32_t mColumn[kMaxMWords];

  bool has(char upper) const { return (present & letterBit(upper)) != 0; }
  double get(char upper) const { return value[letterIndex(upper)]; }
  std::uint32_t col(char upper) const { return column[letterIndex(upper)]; }
  bool hasWords() const { return present != 0 || gCount != 0 || mCount != 0; }
};

struct LexError {
  std::uint32_t column = 0;
  std::string message;
};

class Parameters;

// Reads the block in [begin, end) (no line terminator). Returns false and fills `error` when the
// text is not a valid block. `block` is reset first. Words may take their values from
// `parameters` and expressions, and the line's parameter assignments are staged in it (see
// gcode_parameters.h); without parameters, '#' and '[' are refused.
bool lexBlock(const char* begin, const char* end, Block& block, LexError& error, Parameters* parameters = nullptr);

// Parses an RS274/NGC number starting at `p` (blanks allowed anywhere inside, optional sign,
// digits with at most one decimal point, no exponent). Advances `p` past it and any trailing
// blanks. Returns false (and a message) when there is no valid finite number of sane magnitude.
bool parseNumber(const char*& p, const char* end, double& value, std::string* message);

}  // namespace isurface::gcode
