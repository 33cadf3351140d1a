#include "isurface/base/file_read_stream.h"

#include <ext/stdio_filebuf.h>

#include <cerrno>

#include "isurface/base/bounded_file.h"

namespace isurface {

namespace {
constexpr std::size_t kBufferBytes = 1 << 16;
}

FileReadStream::FileReadStream(const std::string& path) : std::istream(nullptr) {
  const int fd = openForReading(path);
  if (fd < 0) {
    const int error = errno;
    setstate(std::ios::failbit);
    errno = error;
    return;
  }
  // The buffer owns the descriptor and closes it.
  buffer_ = std::make_unique<__gnu_cxx::stdio_filebuf<char>>(fd, std::ios::in | std::ios::binary, kBufferBytes);
  rdbuf(buffer_.get());
}

FileReadStream::~FileReadStream() { rdbuf(nullptr); }

}  // namespace isurface
