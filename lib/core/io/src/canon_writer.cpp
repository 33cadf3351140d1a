// The canonical move listing (docs/canon-format.md), written as the interpreter streams moves.
#include "isurface/io/canon_writer.h"

#include <unistd.h>

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "isurface/io/atomic_file.h"

namespace isurface {

namespace {

// Formats into a large buffer handed to `sink(data, size)` whenever it fills.
template <typename Sink>
class Output {
 public:
  explicit Output(Sink& sink) : sink_(sink) { buffer_.resize(kCapacity + kLineRoom); }

  char* cursor() {
    if (used_ > kCapacity) flush();
    return buffer_.data() + used_;
  }
  void advance(const char* end) { used_ = static_cast<std::size_t>(end - buffer_.data()); }
  void flush() {
    if (used_ > 0) sink_(buffer_.data(), used_);
    used_ = 0;
  }

 private:
  static constexpr std::size_t kCapacity = std::size_t{1} << 20;
  static constexpr std::size_t kLineRoom = 4096;  // far more than one line needs
  Sink& sink_;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
};

char* writeUnsigned(char* out, unsigned long long v) {
  char digits[24];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  while (n > 0) *out++ = digits[--n];
  return out;
}

// `v` with exactly 4 decimals, as printf("%.4f") would print it, except that a value that rounds
// to zero is always "0.0000" (never "-0.0000").
char* writeFixed4(char* out, double v) {
  const double scaled = v * 10000.0;
  if (std::fabs(scaled) < 9e15) {
    const double frac = scaled - std::floor(scaled);
    // Away from a rounding tie the scaled value rounds like the exact decimal would.
    if (std::fabs(frac - 0.5) > 1e-6) {
      long long n = static_cast<long long>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
      if (n < 0) {
        *out++ = '-';
        n = -n;
      }
      out = writeUnsigned(out, static_cast<unsigned long long>(n / 10000));
      const int f = static_cast<int>(n % 10000);
      *out++ = '.';
      *out++ = static_cast<char>('0' + f / 1000);
      *out++ = static_cast<char>('0' + f / 100 % 10);
      *out++ = static_cast<char>('0' + f / 10 % 10);
      *out++ = static_cast<char>('0' + f % 10);
      return out;
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

char* writeMove(char* out, const Move& m, FeedText& feedText) {
  out = writeUnsigned(out, m.line);
  switch (m.kind) {
    case MoveKind::Rapid: out = fmt::format_to(out, " G0 "); break;
    case MoveKind::Linear: out = fmt::format_to(out, " G1 "); break;
    case MoveKind::ArcCW: out = fmt::format_to(out, " G2 "); break;
    case MoveKind::ArcCCW: out = fmt::format_to(out, " G3 "); break;
    case MoveKind::Dwell:
      out = fmt::format_to(out, " G4 P");
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
    out = fmt::format_to(out, "G{} ", static_cast<int>(m.plane));
    out = writeUnsigned(out, m.turns);
    *out++ = ' ';
  }
  out = writeFixed4(out, m.kind == MoveKind::Rapid ? 0.0 : feedText(m.feed));
  *out++ = '\n';
  return out;
}

// Formats the moves into `write(data, size)` as the interpreter hands them over.
template <typename Write>
class CanonWriter : public MoveSink {
 public:
  explicit CanonWriter(Write& write) : output_(write) {}
  void consume(const Move* moves, std::size_t count, std::uint64_t) override {
    for (std::size_t i = 0; i < count; ++i) output_.advance(writeMove(output_.cursor(), moves[i], feedText_));
  }
  void flush() { output_.flush(); }

 private:
  Output<Write> output_;
  FeedText feedText_;
};

// Interprets into `write`, streaming: memory stays the same whatever the size of the file.
template <typename Write>
StreamedInterpretation interpretInto(const std::string& input, const InterpreterOptions& options, Write& write) {
  CanonWriter<Write> writer(write);
  StreamedInterpretation result = interpretGcodeFileStream(input, writer, options);
  writer.flush();
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
