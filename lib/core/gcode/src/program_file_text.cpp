#include "program_file_text.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "isurface/base/bounded_file.h"
#include "isurface/base/input_files.h"
#include "isurface/base/shrink_guard.h"

namespace isurface::gcode {

namespace {

// A program read from a pipe is copied to an unlinked temporary file and mapped like any other,
// so that it costs disk, not memory. Beyond this it is refused: save it to a file. A pipe that
// never ends (`yes 'G1 X1' |`) reaches it in seconds; at 16 GB it filled a disk first.
constexpr std::uint64_t kLargestPipedProgram = std::uint64_t{2} << 30;  // bytes

// Maps `size` bytes of `fd` and calls use(text, true), guarded against the file shrinking under
// the mapping. Returns nullopt when the file cannot be mapped, else why it could not be read
// (empty: it was read).
std::optional<std::string> useMapped(int fd, std::size_t size, bool readAhead, const TextUse& use) {
  void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | (readAhead ? MAP_POPULATE : 0), fd, 0);
  if (map == MAP_FAILED) return std::nullopt;
  ::madvise(map, size, MADV_SEQUENTIAL);
  struct Unmap {
    void* map;
    std::size_t size;
    ~Unmap() { ::munmap(map, size); }
  } unmap{map, size};
  const ShrinkGuard guard(map, size);
  const auto cutShort = [&] {
    return fmt::format("the file was cut short while it was read (it had {} bytes when opened)", size);
  };
  try {
    use(std::string_view(static_cast<const char*>(map), size), true);
  } catch (...) {
    if (guard.shrank()) return cutShort();
    throw;
  }
  return guard.shrank() ? cutShort() : std::string();
}

// Copies what `fd` delivers into an unlinked temporary file. Returns its descriptor and size,
// or why it could not (a NUL byte: binary data such as /dev/zero, not a program).
std::variant<std::pair<int, std::uint64_t>, std::string> spool(int fd) {
  const char* folder = std::getenv("TMPDIR");
  const std::string where = folder && *folder ? folder : "/tmp";
  int out = ::open(where.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (out < 0) {
    std::string pattern = where + "/isurface-pipe-XXXXXX";
    out = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (out < 0) return fmt::format("cannot keep the piped program in {}: {}", where, std::strerror(errno));
    ::unlink(pattern.c_str());
  }
  std::uint64_t total = 0;
  std::vector<char> buffer(std::size_t{1} << 20);
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    std::string why;
    if (n < 0) why = fmt::format("cannot read: {}", std::strerror(errno));
    else if (n == 0) return std::make_pair(out, total);
    else if (const void* nul = std::memchr(buffer.data(), '\0', std::size_t(n)))
      why = fmt::format("a NUL byte at byte {}: binary data, not a G-code program",
                        total + std::uint64_t(static_cast<const char*>(nul) - buffer.data()) + 1);
    else if (total + std::uint64_t(n) > kLargestPipedProgram)
      why = fmt::format("more than {} GB through a pipe: save the program to a file", kLargestPipedProgram >> 30);
    else if (::write(out, buffer.data(), std::size_t(n)) != n)
      why = fmt::format("cannot keep the piped program in {}: {}", where, std::strerror(errno));
    if (!why.empty()) {
      ::close(out);
      return why;
    }
    total += std::uint64_t(n);
  }
}

}  // namespace

std::string withFileText(const std::string& path, bool readAhead, const TextUse& use) {
  const int fd = openForReading(path);
  if (fd < 0) return fmt::format("cannot open: {}", std::strerror(errno));
  try {
    noteInputFile(fd, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
    const int e = S_ISDIR(st.st_mode) ? EISDIR : errno;
    ::close(fd);
    return fmt::format("cannot read: {}", e == EISDIR ? "is a directory" : std::strerror(e));
  }
  if (S_ISREG(st.st_mode) && st.st_size == 0) {
    ::close(fd);
    use(std::string_view(), false);
    return {};
  }
  if (S_ISREG(st.st_mode)) {
    const std::optional<std::string> read = useMapped(fd, static_cast<std::size_t>(st.st_size), readAhead, use);
    ::close(fd);
    if (read) return *read;
    return "cannot map the file";
  }
  auto spooled = spool(fd);
  ::close(fd);
  if (const std::string* why = std::get_if<std::string>(&spooled)) return *why;
  const auto [copy, bytes] = std::get<std::pair<int, std::uint64_t>>(spooled);
  std::optional<std::string> read;
  if (bytes == 0) use(std::string_view(), false), read = std::string();
  else read = useMapped(copy, static_cast<std::size_t>(bytes), false, use);
  ::close(copy);
  return read ? *read : "cannot map the piped program";
}

}  // namespace isurface::gcode
