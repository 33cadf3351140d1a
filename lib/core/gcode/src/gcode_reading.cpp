// RS274/NGC interpreter: reading the text line by line (streaming, control flow jumping back and
// on), and a line's block lexed and executed.
#include <sys/mman.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <optional>

#include "interpreter_state.h"
#include "isurface/gcode/line_ends.h"

namespace isurface::gcode {

namespace {

// With keepGoing, interpretation stops after this many bad blocks (binary junk, wrong file).
constexpr std::size_t kMaxErrors = 1000;
// Streaming releases the text read so far in steps of this many bytes.
constexpr std::ptrdiff_t kReleaseBytes = std::ptrdiff_t{8} << 20;

// Large move buffers are filled front to back once: huge pages save thousands of page faults.
void adviseHugePages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < 4 * kHuge) return;
  const auto first = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto last = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (last > first) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

// Physical lines: newlines, plus a last line that has none.
std::size_t countLines(const char* begin, const char* end) {
  std::size_t newlines = 0;
  for (const char* p = begin; p < end;) {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (!nl) break;
    ++newlines;
    p = static_cast<const char*>(nl) + 1;
  }
  return newlines + (begin < end && end[-1] != '\n' ? 1 : 0);
}

std::uint32_t clampToU32(std::size_t n) { return static_cast<std::uint32_t>(std::min<std::size_t>(n, 0xffffffffu)); }

}  // namespace

void InterpreterState::streamTo(MoveSink& sink, std::size_t chunkMoves, std::function<void(const char*)> released) {
  sink_ = &sink;
  chunkMoves_ = std::max<std::size_t>(chunkMoves, 1);
  released_ = std::move(released);
}

void InterpreterState::deliverMoves(bool all) {
  const std::size_t last = all ? moves_.size() : firstHeldMove();
  // The moves handed over without a copy when only a few at the end are held (the last one,
  // which a later block may still mark as a stop): those few are set aside and put back.
  constexpr std::size_t kHeldAside = 4;
  const std::size_t held = moves_.size() - last;
  if (last > 0 && held <= kHeldAside && moves_.size() <= chunkMoves_ + 64) {
    Move aside[kHeldAside];
    std::copy(moves_.begin() + static_cast<std::ptrdiff_t>(last), moves_.end(), aside);
    moves_.resize(last);
    if (sink_->adopt(moves_, delivered_)) {
      delivered_ += last;
      moves_.assign(aside, aside + held);
      return;
    }
    moves_.insert(moves_.end(), aside, aside + held);
  }
  std::size_t first = 0;
  while (first < last) {
    const std::size_t count = std::min(chunkMoves_, last - first);
    sink_->consume(moves_.data() + first, count, delivered_);
    delivered_ += count;
    first += count;
  }
  moves_.erase(moves_.begin(), moves_.begin() + static_cast<std::ptrdiff_t>(first));
}

void InterpreterState::run(std::string_view text) {
  if (hasLoneCarriageReturn(text)) {
    lineFedText_ = withLineFeeds(text);
    text = lineFedText_;
    released_ = nullptr;  // the copy is read, not the mapping
  }
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  if (sink_) {
    moves_.reserve(chunkMoves_ + 64);
  } else {
    result_.program.lineCount = clampToU32(countLines(begin, end));
    // One move per line is the common case; a line of a move is rarely under 8 bytes.
    moves_.reserve(std::min<std::size_t>(result_.program.lineCount, text.size() / 8) + 16);
    adviseHugePages(moves_.data(), moves_.capacity() * sizeof(Move));
  }

  const double total = text.empty() ? 1.0 : static_cast<double>(text.size());
  const char* first = begin;
  if (text.size() >= 3 && std::memcmp(begin, "\xEF\xBB\xBF", 3) == 0) first += 3;  // UTF-8 BOM
  macro_.setText(first, end);
  mainText_ = {first, end};
  textEnd_ = end;
  const char* releasedUpTo = begin;
  const char* p = first;
  while (!ended_) {
    if (p >= textEnd_) {
      if (reading_ && leaveFile(p)) continue;
      break;
    }
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(textEnd_ - p));
    const char* lineEnd = nl ? static_cast<const char*>(nl) : textEnd_;
    ++line_;
    if (!countLineRead(p, lineEnd)) break;
    if (flow_.skipping() && !isOWordLine(p, lineEnd)) {  // inside a construct read past
      p = lineEnd + 1;
      continue;
    }
    lineStart_ = {p, line_};
    lineEnd_ = lineEnd;
    nextLine_ = {nl ? lineEnd + 1 : textEnd_, line_ + 1};  // never past the text's end
    runLine(p, lineEnd);
    p = lineEnd + 1;
    if (jump_) {  // a loop, a call or a return: on from another line
      noteJump(lineStart_, *jump_);
      p = jump_->at;
      enterTextOf(p);
      line_ = jump_->line - 1;
      jump_.reset();
    }
    if (sink_) {
      if (moves_.size() > chunkMoves_) deliverMoves(false);
      if (sink_->stopped()) ended_ = true;  // its error is the run's: what follows is not read
      // Once a loop or a call may read lines again, the text stays.
      if (released_ && !flow_.seen() && p - releasedUpTo >= kReleaseBytes) released_(releasedUpTo = std::min(p, end));
    }
    if ((line_ & 0xffffu) == 0 && options_.progress && !reading_) options_.progress((p - begin) / total);
  }
  if (reading_) {  // ended in a subroutine file: the main text's count goes on from the call
    p = mainLeftAt_;
    line_ = callLine_;
    enterTextOf(p);
  }
  if (!ended_)
    if (const auto open = flow_.unfinished()) result_.errors.push_back(Diagnostic{source_, line_, 0, *open});
  if (sink_) {
    deliverMoves(true);
    // The lines after M2, M30 or a closing '%' still count; read in pieces released behind.
    std::size_t lines = line_;
    for (const char* rest = std::min(p, end); rest < end;) {
      const char* pieceEnd = rest + std::min<std::size_t>(kReleaseBytes, static_cast<std::size_t>(end - rest));
      lines += countLines(rest, pieceEnd) - (pieceEnd < end && pieceEnd[-1] != '\n' ? 1 : 0);
      rest = pieceEnd;
      if (released_) released_(rest);
    }
    // Text that is only a byte order mark is one (empty) line, as countLines() says.
    if (lines == 0 && !text.empty()) lines = 1;
    result_.program.lineCount = clampToU32(lines);
  } else if (moves_.capacity() > moves_.size() + moves_.size() / 4 + 64) {
    moves_.shrink_to_fit();
  }
  if (options_.progress) options_.progress(1.0);
}

// Whether a comment of the line ("(UNITS: INCHES)", "; inch") speaks of inches: a Haas or Fanuc
// program powered on in inches may never say G20.
static bool commentMentionsInches(const char* begin, const char* end) {
  const char* comment = std::find_if(begin, end, [](char c) { return c == '(' || c == ';'; });
  for (const char* p = comment; p + 4 <= end; ++p)
    if (std::toupper(static_cast<unsigned char>(p[0])) == 'I' && std::toupper(static_cast<unsigned char>(p[1])) == 'N' &&
        std::toupper(static_cast<unsigned char>(p[2])) == 'C' && std::toupper(static_cast<unsigned char>(p[3])) == 'H')
      return true;
  return false;
}

bool InterpreterState::runBlock(const char* begin, const char* end) {
  // Columns count from the line's start (the block may be what follows a Fanuc IF .. THEN).
  const auto shift = static_cast<std::uint32_t>(begin - lineStart_.at);
  if (!unitsStated_ && !commentSaysInches_) commentSaysInches_ = commentMentionsInches(begin, end);
  LexError lexError;
  if (!lexBlock(begin, end, block_, lexError, &parameters_)) {
    errorColumn_ = lexError.column + shift;
    errorMessage_ = std::move(lexError.message);
  } else {
    // A bad block has no effect: with --keep-going the interpretation goes on as if it were
    // not there, so its modal changes are undone; without, it ends at the block, and a million
    // good blocks need not copy the modal state for nothing.
    std::optional<ModalState> saved;
    if (options_.keepGoing) saved = state_;
    // Only a block under compensation has compensation to undo (one that turns it on and fails
    // turns it off again below).
    std::optional<CompensationSnapshot> compBefore;
    if (comp_.on()) compBefore = compensationSnapshot();
    const std::size_t movesBefore = moves_.size();
    if (executeBlock(block_)) {
      if (parameters_.hasStaged()) parameters_.commit();
      return true;
    }
    if (saved) state_ = *saved;
    moves_.resize(movesBefore);
    if (compBefore) {
      restoreCompensation(*compBefore);
    } else if (comp_.on()) {
      comp_ = CutterCompensation{};
      compOpenMoves_.clear();
    }
    if (errorColumn_ > 0 && block_.kind != BlockKind::OWord) errorColumn_ += shift;
  }
  parameters_.discardStaged();
  return false;
}

void InterpreterState::runLine(const char* begin, const char* end) {
  if (options_.fanuc) macro_.setCallDepth(flow_.callDepth());
  if (options_.fanuc && FanucMacro::isStatement(begin, end)) {
    const FanucMacro::Outcome out = macro_.execute(lineStart_, end);
    if (out.ok) {
      jump_ = out.jump;
      if (!out.then || runBlock(out.then, end)) return;
    } else {
      errorColumn_ = out.column;
      errorMessage_ = out.message;
    }
  } else if (runBlock(begin, end)) {
    return;
  }
  result_.errors.push_back(Diagnostic{source_, line_, errorColumn_, std::move(errorMessage_)});
  if (!options_.keepGoing) {
    ended_ = true;
  } else if (result_.errors.size() >= kMaxErrors) {
    result_.errors.push_back(Diagnostic{source_, line_, 0,
                                        fmt::format("Too many errors ({}), giving up", kMaxErrors)});
    ended_ = true;
  }
}

}  // namespace isurface::gcode
