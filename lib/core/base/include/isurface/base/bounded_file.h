#pragma once
// Small files read whole (machine descriptions, tool tables, settings), never more than their
// kind can be: /dev/zero or a huge file is refused at the bound, not read until memory runs out.
#include <cstddef>
#include <string>

namespace isurface {

struct BoundedRead {
  std::size_t maxBytes = 1 << 20;
  const char* what = "file";  // how the message names it: "machine description", ...
  // Only a regular file: a FIFO or a device is refused without waiting for a writer.
  bool regularOnly = false;
};

// The file's bytes; an InputError naming it when it cannot be opened or read, is larger than
// maxBytes, or (regularOnly) is not a regular file.
std::string readBoundedFile(const std::string& path, const BoundedRead& limits);

// open(path, O_RDONLY | O_CLOEXEC) that does not wait for a FIFO's writer: a named pipe nobody
// writes to reads as empty (at once) instead of keeping the command waiting for ever. Reads of
// what it returns block as usual. -1 and errno as open().
int openForReading(const std::string& path);

}  // namespace isurface
