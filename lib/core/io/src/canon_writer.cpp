// The canonical move listing (docs/canon-format.md), written as the interpreter streams moves.
#include "isurface/io/canon_writer.h"

#include <unistd.h>

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <vector>

#include "isurface/io/atomic_file.h"

namespace isurface {

namespace {

// The calls each move is made in, by the move's index, for the moves told and not yet written.
using CallStacks = std::unordered_map<std::uint64_t, std::string>;

// Formats into a large buffer handed to `sink(data, size)` whenever it fills.
template <typename Sink>
class Output {
 public:
  // Not zeroed: its pages are first touched by the thread that formats.
  explicit Output(Sink& sink) : sink_(sink), buffer_(new char[kCapacity + kLineRoom]) {}

  char* cursor() {
    if (used_ > kCapacity) flush();
    return buffer_.get() + used_;
  }
  void advance(const char* end) { used_ = static_cast<std::size_t>(end - buffer_.get()); }
  void flush() {
    if (used_ > 0) sink_(buffer_.get(), used_);
    used_ = 0;
  }

 private:
  static constexpr std::size_t kCapacity = std::size_t{1} << 20;
  static constexpr std::size_t kLineRoom = 4096;  // far more than one line needs
  Sink& sink_;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

// "00" .. "99": two digits per division by 100.
struct DigitPairs {
  char text[200];
  constexpr DigitPairs() : text() {
    for (int i = 0; i < 100; ++i) {
      text[2 * i] = static_cast<char>('0' + i / 10);
      text[2 * i + 1] = static_cast<char>('0' + i % 10);
    }
  }
};
constexpr DigitPairs kPairs;

inline char* writePair(char* out, unsigned v) {
  std::memcpy(out, kPairs.text + 2 * v, 2);
  return out + 2;
}

char* writeUnsigned(char* out, unsigned long long v) {
  if (v < 10) {
    *out = static_cast<char>('0' + v);
    return out + 1;
  }
  if (v < 100) return writePair(out, static_cast<unsigned>(v));
  char digits[24];
  char* const last = digits + sizeof digits;
  char* first = last;
  while (v >= 100) {
    first -= 2;
    writePair(first, static_cast<unsigned>(v % 100));
    v /= 100;
  }
  if (v >= 10) {
    first -= 2;
    writePair(first, static_cast<unsigned>(v));
  } else {
    *--first = static_cast<char>('0' + v);
  }
  std::memcpy(out, first, static_cast<std::size_t>(last - first));
  return out + (last - first);
}

// `v` with exactly 4 decimals, as printf("%.4f") would print it, except that a value that rounds
// to zero is always "0.0000" (never "-0.0000").
char* writeFixed4(char* out, double v) {
  const double scaled = v * 10000.0;
  if (std::fabs(scaled) < 4.5e15) {  // below 2^52: a whole number here is not a tie to even
    // floor() by conversion, exact below 2^53: std::floor is a library call on baseline x86-64.
    const double truncated = static_cast<double>(static_cast<long long>(scaled));
    const double frac = scaled - (truncated > scaled ? truncated - 1.0 : truncated);
    // Away from a rounding tie the scaled value rounds like the exact decimal would.
    if (std::fabs(frac - 0.5) > 1e-6) {
      const long long n = static_cast<long long>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
      if (n < 0) *out++ = '-';
      const auto magnitude = static_cast<unsigned long long>(n < 0 ? -n : n);
      out = writeUnsigned(out, magnitude / 10000);
      const auto f = static_cast<unsigned>(magnitude % 10000);
      *out = '.';
      writePair(out + 1, f / 100);
      writePair(out + 3, f % 100);
      return out + 5;
    }
  }
  if (!std::isfinite(v)) return fmt::format_to(out, "{}", v);
  char buffer[400];
  char* end = fmt::format_to(buffer, "{:.4f}", v);
  const std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
  if (text == "-0.0000") return fmt::format_to(out, "0.0000");
  return std::copy(text.begin(), text.end(), out);
}

// Feeds are stored as float: print the decimal the float stands for (F999 in inch is 25374.6,
// not 25374.5996).
class FeedText {
 public:
  double operator()(float f) {
    if (f == last_) return lastValue_;
    last_ = f;
    char buffer[64];
    char* end = fmt::format_to(buffer, "{}", f);
    double v = f;
    fast_float::from_chars(buffer, end, v);
    lastValue_ = v;
    return v;
  }

 private:
  float last_ = 0;
  double lastValue_ = 0;
};

inline char* writeText(char* out, const char (&text)[5]) {
  std::memcpy(out, text, 4);
  return out + 4;
}

// The rotary axes after a move's feed, from the program's first A, B or C word on.
char* writeRotary(char* out, const std::array<double, 3>& abc) {
  for (int i = 0; i < 3; ++i) {
    *out++ = ' ';
    *out++ = "ABC"[i];
    out = writeFixed4(out, abc[i]);
  }
  return out;
}

char* writeMove(char* out, const Move& m, FeedText& feedText, const std::optional<std::array<double, 3>>& rotary) {
  out = writeUnsigned(out, m.line);
  switch (m.kind) {
    case MoveKind::Rapid: out = writeText(out, " G0 "); break;
    case MoveKind::Linear: out = writeText(out, " G1 "); break;
    case MoveKind::ArcCW: out = writeText(out, " G2 "); break;
    case MoveKind::ArcCCW: out = writeText(out, " G3 "); break;
    case MoveKind::Dwell:
      out = writeText(out, " G4 ");
      *out++ = 'P';
      out = writeFixed4(out, m.dwellSeconds());
      *out++ = '\n';
      return out;
  }
  for (int i = 0; i < 3; ++i) {
    out = writeFixed4(out, m.end[i]);
    *out++ = ' ';
  }
  if (m.isArc()) {
    for (int i = 0; i < 3; ++i) {
      out = writeFixed4(out, m.centre[i]);
      *out++ = ' ';
    }
    *out++ = 'G';
    out = writeUnsigned(out, static_cast<unsigned>(m.plane));
    *out++ = ' ';
    out = writeUnsigned(out, m.turns);
    *out++ = ' ';
  }
  out = writeFixed4(out, m.kind == MoveKind::Rapid ? 0.0 : feedText(m.feed));
  if (rotary) out = writeRotary(out, *rotary);
  *out++ = '\n';
  return out;
}

// Formats the moves into `write(data, size)`.
template <typename Write>
class MoveFormatter {
 public:
  explicit MoveFormatter(Write& write) : output_(write) {}
  // Rotary positions, told in move order before their moves are formatted.
  void addRotary(const RotaryPosition& change) { rotaryChanges_.push_back(change); }
  void format(const Move* moves, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) output_.advance(writeMove(output_.cursor(), moves[i], feedText_, nextRotary()));
  }
  // Each line followed by " @ " and the calls its move was made in, where it was made in any.
  void formatWithStacks(const Move* moves, std::size_t count, std::uint64_t firstIndex, CallStacks& stacks) {
    for (std::size_t i = 0; i < count; ++i) {
      char* end = writeMove(output_.cursor(), moves[i], feedText_, nextRotary());
      const auto found = stacks.find(firstIndex + i);
      if (found != stacks.end()) {
        // The line's own newline goes after the stack; a stack longer than the room a line has
        // is written through a flush of its own.
        --end;
        output_.advance(end);
        appendText(" @ ");
        appendText(found->second);
        appendText("\n");
        stacks.erase(found);
      } else {
        output_.advance(end);
      }
    }
  }
  void flush() { output_.flush(); }

 private:
  void appendText(std::string_view text) {
    while (!text.empty()) {
      const std::size_t n = std::min<std::size_t>(text.size(), 1024);
      char* at = output_.cursor();
      std::memcpy(at, text.data(), n);
      output_.advance(at + n);
      text.remove_prefix(n);
    }
  }

  // The rotary position of the move about to be written (none before the first A, B or C).
  const std::optional<std::array<double, 3>>& nextRotary() {
    while (!rotaryChanges_.empty() && rotaryChanges_.front().move <= moveIndex_) {
      rotary_ = rotaryChanges_.front().abc;
      rotaryChanges_.pop_front();
    }
    ++moveIndex_;
    return rotary_;
  }

  Output<Write> output_;
  FeedText feedText_;
  std::deque<RotaryPosition> rotaryChanges_;
  std::optional<std::array<double, 3>> rotary_;
  std::uint64_t moveIndex_ = 0;
};

// Moves per batch handed to the formatting thread (64 KB): small enough for the copy to stay in
// the cache and for the batches to take few pages (a page first touched costs microseconds in a
// virtual machine), large enough that handing over costs nothing next to formatting.
constexpr std::size_t kBatchMoves = 1024;

// Formats and writes the moves on a thread of its own while the interpreter reads on: on plain
// programs formatting and writing the lines costs about half as much as interpreting them, and
// the machines have two cores.
// The moves are copied into a few batches that go round between the two threads (the
// interpreter reuses its own buffer once consume() returns); the interpreter waits only when
// all of them are queued. Without a thread (none can be made) it formats in place.
template <typename Write>
class PipelinedCanonWriter final : public MoveSink {
 public:
  explicit PipelinedCanonWriter(Write& write) : formatter_(write) {}
  ~PipelinedCanonWriter() override { stop(true); }
  PipelinedCanonWriter(const PipelinedCanonWriter&) = delete;
  PipelinedCanonWriter& operator=(const PipelinedCanonWriter&) = delete;

  void consume(const Move* moves, std::size_t count, std::uint64_t) override {
    if (!threadTried_) start();
    if (!thread_.joinable()) return formatter_.format(moves, count);
    while (count > 0) {
      const std::size_t n = std::min(count, kBatchMoves);
      std::vector<Move>& batch = emptyBatch();
      batch.assign(moves, moves + n);
      bool wake;
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        wake = ++queued_ >= kWakeAt && formatterAsleep_;
      }
      if (wake) ready_.notify_one();
      moves += n;
      count -= n;
    }
  }

  bool adopt(std::vector<Move>& moves, std::uint64_t) override {
    if (!threadTried_) start();
    if (!thread_.joinable()) return false;
    std::vector<Move>& batch = emptyBatch();
    batch.clear();
    batch.swap(moves);  // the interpreter goes on in the batch's room
    bool wake;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      wake = ++queued_ >= kWakeAt && formatterAsleep_;
    }
    if (wake) ready_.notify_one();
    return true;
  }

  void rotaryChanged(const RotaryPosition& change) override {
    if (!thread_.joinable()) return formatter_.addRotary(change);
    const std::lock_guard<std::mutex> lock(mutex_);
    rotaryChanges_.push_back(change);
  }

  // Waits until every move is formatted and written; passes on what the formatting threw.
  void finish() {
    stop(false);
    if (error_) std::rethrow_exception(error_);
    formatter_.flush();
  }

 private:
  static constexpr std::size_t kBatches = 12;
  // The formatting thread, faster than the interpreter, empties the queue and sleeps; waking it
  // costs a system call (and, in a virtual machine, an interrupt to the other core), so it is
  // woken only once this many batches wait. The batches left over keep the interpreter going
  // while it wakes.
  static constexpr std::size_t kWakeAt = 4;

  void start() {
    threadTried_ = true;
    // As much room as the interpreter keeps for a chunk: batches and its buffer trade places.
    for (auto& batch : batches_) batch.reserve(kBatchMoves + 64);
    try {
      thread_ = std::thread([this] { formatQueued(); });
    } catch (const std::system_error&) {
      // No thread to be had: format on the interpreter's own.
    }
  }

  // The batch to fill next, once the formatting thread has finished with it.
  std::vector<Move>& emptyBatch() {
    std::unique_lock<std::mutex> lock(mutex_);
    space_.wait(lock, [this] { return queued_ < kBatches || failed_; });
    if (failed_) {
      lock.unlock();
      stop(true);
      std::rethrow_exception(error_);
    }
    return batches_[(next_ + queued_) % kBatches];
  }

  void formatQueued() {
    for (;;) {
      const std::vector<Move>* batch = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        if (queued_ == 0 && !closing_) {
          formatterAsleep_ = true;
          ready_.wait(lock, [this] { return queued_ >= kWakeAt || closing_; });
          formatterAsleep_ = false;
        }
        if (queued_ == 0 || abandoned_) return;
        batch = &batches_[next_];
        // Told before the moves they belong to were queued: the formatter has them in time.
        for (const RotaryPosition& change : rotaryChanges_) formatter_.addRotary(change);
        rotaryChanges_.clear();
      }
      try {
        formatter_.format(batch->data(), batch->size());
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex_);
        error_ = std::current_exception();
        failed_ = true;
        space_.notify_one();
        return;
      }
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        next_ = (next_ + 1) % kBatches;
        --queued_;
      }
      space_.notify_one();
    }
  }

  // Ends the formatting thread: after the queued batches, or at once when `abandon`.
  void stop(bool abandon) {
    if (!thread_.joinable()) return;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      closing_ = true;
      abandoned_ = abandon;
    }
    ready_.notify_one();
    thread_.join();
  }

  MoveFormatter<Write> formatter_;  // the formatting thread's alone while it runs
  std::vector<Move> batches_[kBatches];
  std::mutex mutex_;
  std::condition_variable ready_, space_;
  std::size_t next_ = 0, queued_ = 0;  // the batch to format next; how many are waiting
  bool formatterAsleep_ = false, closing_ = false, abandoned_ = false, failed_ = false;
  std::exception_ptr error_;
  bool threadTried_ = false;
  std::thread thread_;
  std::vector<RotaryPosition> rotaryChanges_;  // told, not yet handed to the formatter
};

// Formats on the interpreter's thread, each move with the calls it was made in: the stacks are
// told as the moves are made and used up as they are written, so they take the room of one batch.
template <typename Write>
class StackedCanonWriter final : public MoveSink {
 public:
  explicit StackedCanonWriter(Write& write) : formatter_(write) {}
  void consume(const Move* moves, std::size_t count, std::uint64_t firstIndex) override {
    formatter_.formatWithStacks(moves, count, firstIndex, stacks_);
  }
  void rotaryChanged(const RotaryPosition& change) override { formatter_.addRotary(change); }
  // A move made again (its block was found bad and undone) replaces the stack told before.
  void tell(std::uint64_t moveIndex, const std::string& stack) {
    if (stack.empty())
      stacks_.erase(moveIndex);
    else
      stacks_[moveIndex] = stack;
  }
  void finish() { formatter_.flush(); }

 private:
  MoveFormatter<Write> formatter_;
  CallStacks stacks_;
};

// Interprets into `write`, streaming: memory stays the same whatever the size of the file.
template <typename Write>
StreamedInterpretation interpretInto(const std::string& input, const InterpreterOptions& options, Write& write) {
  if (options.callStack) {
    StackedCanonWriter<Write> writer(write);
    InterpreterOptions told = options;
    told.callStack = [&writer](std::uint64_t index, const std::string& stack) { writer.tell(index, stack); };
    StreamedInterpretation result = interpretGcodeFileStream(input, writer, told, kBatchMoves);
    writer.finish();
    return result;
  }
  PipelinedCanonWriter<Write> writer(write);
  StreamedInterpretation result = interpretGcodeFileStream(input, writer, options, kBatchMoves);
  writer.finish();
  return result;
}

}  // namespace

// Writes to standard output; `error` gets the errno of the first failed write.
StreamedInterpretation interpretToStdout(const std::string& input, const InterpreterOptions& options, int& error) {
  auto write = [&error](const char* p, std::size_t left) {
    while (left > 0 && error == 0) {
      const ssize_t n = ::write(STDOUT_FILENO, p, left);
      if (n < 0) {
        if (errno != EINTR) error = errno;
        continue;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
  };
  return interpretInto(input, options, write);
}

// Writes through a temporary file renamed into place (AtomicOutputFile) when the program has no
// error or `keepGoing`: a failed run leaves no partial file. `writeError` gets the message of a
// failed write; the program is still interpreted, so that its own errors are reported.
StreamedInterpretation interpretToPath(const std::string& input, const InterpreterOptions& options,
                                       const std::string& path, std::string& writeError) {
  std::optional<AtomicOutputFile> file;
  try {
    file.emplace(path);
  } catch (const InputError& e) {
    writeError = e.what();
  }
  auto write = [&](const char* p, std::size_t n) {
    if (!writeError.empty()) return;
    try {
      file->write(p, n);
    } catch (const InputError& e) {
      writeError = e.what();
    }
  };
  StreamedInterpretation result = interpretInto(input, options, write);
  if (writeError.empty() && (result.ok() || options.keepGoing)) {
    try {
      file->commit();
    } catch (const InputError& e) {
      writeError = e.what();
    }
  }
  return result;
}

}  // namespace isurface
