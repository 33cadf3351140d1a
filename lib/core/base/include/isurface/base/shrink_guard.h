// Mapped files that another process cuts short while they are read.
#pragma once

#include <cstddef>

namespace isurface {

// Registers a read-only file mapping for as long as it lives. A read past the file's new end
// (another process truncated it) would raise SIGBUS and kill the process; under a guard the
// page read instead holds zeros, and shrank() tells the reader that what it read is not the
// file it opened. Reads outside every guarded mapping keep the default SIGBUS behaviour.
// At most kMaxGuards mappings are guarded at once; beyond that a mapping is read unguarded.
class ShrinkGuard {
 public:
  static constexpr int kMaxGuards = 64;

  ShrinkGuard(const void* data, std::size_t bytes);
  ~ShrinkGuard();
  ShrinkGuard(const ShrinkGuard&) = delete;
  ShrinkGuard& operator=(const ShrinkGuard&) = delete;

  // Whether a read found the file shorter than when it was mapped.
  bool shrank() const;

 private:
  int slot_ = -1;
};

}  // namespace isurface
