// A read-only mapping of the file and one offset per line: showing any line costs nothing and
// nothing of the text is copied.
#include "isurface/app_model/text_lines.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>

#include "isurface/base/bounded_file.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/shrink_guard.h"
#include "isurface/gcode/line_ends.h"

namespace isurface::app_model {

namespace {

[[noreturn]] void failToOpen(const std::string& path, int error) {
  throw InputError(Diagnostic{path, 0, 0, std::string("cannot open: ") + std::strerror(error)});
}

// Fills `starts` with the offset of each line's first byte plus one sentinel: the offset one past
// the last line's end as if it ended with '\n'. Line i then spans [starts[i], starts[i+1] - 1).
template <class Offset>
void indexLineStarts(const char* data, std::size_t size, std::vector<Offset>& starts) {
  if (size == 0) return;
  starts.push_back(0);
  if (hasLoneCarriageReturn(std::string_view(data, size))) {
    // Lines end at LF, CR LF or CR alone, as the interpreter reads them.
    for (std::size_t i = 0; i < size; ++i)
      if (data[i] == '\n' || (data[i] == '\r' && (i + 1 == size || data[i + 1] != '\n')))
        starts.push_back(static_cast<Offset>(i + 1));
    if (data[size - 1] != '\n' && data[size - 1] != '\r') starts.push_back(static_cast<Offset>(size + 1));
    return;
  }
  const char* cursor = data;
  const char* const end = data + size;
  while (cursor < end) {
    const void* newline = std::memchr(cursor, '\n', static_cast<std::size_t>(end - cursor));
    if (!newline) break;
    cursor = static_cast<const char*>(newline) + 1;
    starts.push_back(static_cast<Offset>(cursor - data));
  }
  // A file ending with '\n' already has its sentinel (the file size); otherwise the last line
  // runs to the end and gets an imaginary line end.
  if (data[size - 1] != '\n') starts.push_back(static_cast<Offset>(size + 1));
}

}  // namespace

struct TextLines::Impl {
  const char* data = nullptr;
  std::size_t size = 0;
  // Files below 4 GB store 32-bit offsets: half the memory for the usual G-code file.
  bool wideOffsets = false;
  std::vector<std::uint32_t> starts32;
  std::vector<std::uint64_t> starts64;
  // The pane shows zeros, not a crash, where another program cut the file short.
  std::unique_ptr<ShrinkGuard> guard;

  std::size_t sentinelCount() const { return wideOffsets ? starts64.size() : starts32.size(); }
  std::uint64_t start(std::size_t i) const { return wideOffsets ? starts64[i] : starts32[i]; }

  ~Impl() {
    guard.reset();
    if (data) munmap(const_cast<char*>(data), size);
  }
};

TextLines::TextLines(const std::string& path) : impl_(std::make_unique<Impl>()) {
  const int fd = openForReading(path);  // a FIFO without a writer: refused below, not waited on
  if (fd < 0) failToOpen(path, errno);
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int error = errno;
    ::close(fd);
    failToOpen(path, error);
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd);
    if (S_ISDIR(info.st_mode)) failToOpen(path, EISDIR);
    throw InputError(Diagnostic{path, 0, 0, "cannot be shown: it is a pipe or a device, not a file (save it to a file and open that)"});
  }
  const std::size_t size = static_cast<std::size_t>(info.st_size);
  if (size > 0) {
    void* mapped = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapped == MAP_FAILED) {
      const int error = errno;
      ::close(fd);
      failToOpen(path, error);
    }
    impl_->data = static_cast<const char*>(mapped);
    impl_->size = size;
    impl_->guard = std::make_unique<ShrinkGuard>(mapped, size);
  }
  ::close(fd);  // the mapping keeps the file's pages reachable

  if (size == 0) return;
  ::madvise(const_cast<char*>(impl_->data), size, MADV_SEQUENTIAL);
  // The sentinel may be size + 1: 32 bits hold it only below 2^32 - 1.
  impl_->wideOffsets = size >= std::numeric_limits<std::uint32_t>::max();
  if (impl_->wideOffsets)
    indexLineStarts(impl_->data, size, impl_->starts64);
  else
    indexLineStarts(impl_->data, size, impl_->starts32);
  // The pane then jumps around the file.
  ::madvise(const_cast<char*>(impl_->data), size, MADV_RANDOM);
}

TextLines::~TextLines() = default;

std::size_t TextLines::count() const {
  const std::size_t n = impl_->sentinelCount();
  return n == 0 ? 0 : n - 1;
}

std::string_view TextLines::line(std::size_t oneBased) const {
  if (oneBased == 0 || oneBased > count()) return {};
  const std::uint64_t begin = impl_->start(oneBased - 1);
  std::uint64_t end = impl_->start(oneBased) - 1;  // drops the '\n'
  if (end > begin && impl_->data[end - 1] == '\r') --end;
  return std::string_view(impl_->data + begin, static_cast<std::size_t>(end - begin));
}

namespace {

bool holdsIgnoringCase(std::string_view text, std::string_view needle) {
  const auto same = [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  };
  return std::search(text.begin(), text.end(), needle.begin(), needle.end(), same) != text.end();
}

}  // namespace

std::optional<std::size_t> findLine(const TextLines& text, std::string_view needle, std::size_t from, bool backwards) {
  const std::size_t n = text.count();
  if (needle.empty() || n == 0) return std::nullopt;
  std::size_t line = std::min(from, n);
  for (std::size_t step = 0; step < n; ++step) {
    line = backwards ? (line <= 1 ? n : line - 1) : (line >= n ? 1 : line + 1);
    if (holdsIgnoringCase(text.line(line), needle)) return line;
  }
  return std::nullopt;
}

}  // namespace isurface::app_model
