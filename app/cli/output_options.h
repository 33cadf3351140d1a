#pragma once
// The options that name a command's output files, and standard output held until they are
// published: what every command shares about where its results go.
#include <cstddef>
#include <cstdio>

#include <CLI/CLI.hpp>

namespace isurface::cli {

// Marks `option` as naming an output file (or several); returns it. No two outputs of one run
// may be the same file.
CLI::Option* outputOption(CLI::Option* option);

// Throws InputError naming both options when two output options given to `sub` name the same
// file: the same path written two ways (`a`, `./a`, a link to it) or, for a file that exists,
// another hard link to it. Devices (/dev/null) may be named twice.
void refuseSharedOutputs(const CLI::App& sub);

// What a command prints on standard output, held in memory while it runs: release() writes it
// once the command's files are published, so that a success is never printed before a failure.
// Output written straight to the file descriptor (`canon` streaming its moves) is not held.
class HeldStandardOutput {
 public:
  HeldStandardOutput();
  ~HeldStandardOutput();  // drops what was not released
  HeldStandardOutput(const HeldStandardOutput&) = delete;
  HeldStandardOutput& operator=(const HeldStandardOutput&) = delete;

  // Writes what was held to the real standard output and flushes it. False on a failure
  // (errno says why).
  bool release();

 private:
  void restore();
  std::FILE* real_ = nullptr;
  std::FILE* memory_ = nullptr;
  char* buffer_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace isurface::cli
