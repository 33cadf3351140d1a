#include "isurface/base/bounded_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw InputError(Diagnostic{path, 0, 0, message});
}

// Closes the descriptor however the read ends.
struct OpenFile {
  int fd;
  ~OpenFile() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace

int openForReading(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return fd;
  const int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

std::string readBoundedFile(const std::string& path, const BoundedRead& limits) {
  const OpenFile file{openForReading(path)};
  if (file.fd < 0) fail(path, fmt::format("cannot open {}: {}", limits.what, std::strerror(errno)));
  struct stat info {};
  if (fstat(file.fd, &info) != 0) fail(path, fmt::format("cannot read {}: {}", limits.what, std::strerror(errno)));
  if (limits.regularOnly && !S_ISREG(info.st_mode)) fail(path, fmt::format("the {} is not a regular file", limits.what));
  if (S_ISREG(info.st_mode) && std::size_t(info.st_size) > limits.maxBytes)
    fail(path, fmt::format("{} bytes: a {} is at most {} bytes", info.st_size, limits.what, limits.maxBytes));
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, fmt::format("cannot read {}: {}", limits.what, std::strerror(errno)));
    if (n == 0) break;
    text.append(buffer, std::size_t(n));
    if (text.size() > limits.maxBytes)
      fail(path, fmt::format("more than {} bytes: a {} is not that large (a device or an endless stream?)", limits.maxBytes,
                             limits.what));
  }
  return text;
}

}  // namespace isurface
