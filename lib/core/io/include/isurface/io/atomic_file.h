#pragma once
// Output files that appear whole or not at all.
//
// AtomicOutputFile writes into a temporary file beside the target (`target.tmpXXXXXX`, same
// folder, hence same file system) and renames it over the target on commit(). A file that is
// destroyed without commit() removes its temporary: a failed or interrupted job never leaves a
// partial output behind, and an existing target stays as it was.
//
// A target that already exists and is not a regular file (a terminal, a pipe, /dev/stdout,
// /dev/null, /dev/full) cannot be replaced by renaming; it is written directly instead.
//
// Every failure (folder missing or not writable, disk full, I/O error, a target that is one of
// the process's protected inputs: see input_files.h) throws InputError with
// Diagnostic{file = target, message = "cannot write: <reason>"}. A temporary file is removed
// when SIGINT, SIGTERM, SIGHUP or SIGQUIT ends the process, and while an OutputTransaction is
// open, commit() leaves the rename to it.
//
// The data is on disk before the rename, so that a system crash too leaves the old file or the
// whole new one: the rename alone is atomic for every process, but after a power cut the new
// name may stand for data that never reached the disk (an empty or cut-short file). A large file
// is synced in the background as it is written (a thread of its own, past the first few
// megabytes), so that commit() waits only for the last part.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>

namespace isurface {

class AtomicOutputFile {
 public:
  static constexpr std::size_t kDefaultBufferBytes = std::size_t(1) << 20;

  // Creates the temporary file (or opens a non-regular target). Throws InputError.
  explicit AtomicOutputFile(std::string target, std::size_t bufferBytes = kDefaultBufferBytes);
  ~AtomicOutputFile();  // removes the temporary file unless committed
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  // Appends n bytes (buffered). Throws InputError when a buffer flush fails.
  void write(const void* data, std::size_t n) {
    if (n <= capacity_ - used_) {
      std::memcpy(buffer_.get() + used_, data, n);
      used_ += n;
    } else {
      writeSlow(data, n);
    }
  }
  void write(std::string_view text) { write(text.data(), text.size()); }

  // Overwrites bytes already written (e.g. a count in a header), after flushing the buffer.
  // Throws InputError when the output cannot seek (a pipe): check seekable() first.
  void writeAt(std::uint64_t offset, const void* data, std::size_t n);
  bool seekable() const { return seekable_; }

  // Bytes written so far, buffered or not.
  std::uint64_t size() const { return flushed_ + used_; }

  // Flushes, syncs and closes the temporary file, then renames it over the target.
  // Throws InputError (and removes the temporary file) on any failure. Call once.
  void commit();
  bool committed() const { return committed_; }

  const std::string& target() const { return target_; }
  // The temporary file's path; equal to target() when the target is written directly.
  const std::string& temporaryPath() const { return temp_; }

 private:
  class BackgroundSync;

  void writeSlow(const void* data, std::size_t n);
  void flushBuffer();
  void syncWrittenInBackground();
  [[noreturn]] void fail(int error, const std::string& context = {});
  void discard() noexcept;

  std::string target_;
  std::string temp_;
  std::string destination_;  // where commit() renames the temporary file
  int fd_ = -1;
  bool direct_ = false;  // writing the target itself (not a regular file)
  bool seekable_ = true;
  bool committed_ = false;
  std::unique_ptr<unsigned char[]> buffer_;
  std::size_t capacity_ = 0;
  std::size_t used_ = 0;
  std::uint64_t flushed_ = 0;
  std::unique_ptr<BackgroundSync> sync_;  // null until the file grows large
  std::uint64_t syncRequested_ = 0;       // bytes written when the last background sync was asked for
  bool backgroundSyncFailed_ = false;     // no thread could be made: commit() syncs it all
  bool replacing_ = false;                // the target is a file that commit() replaces
  int signalSlot_ = -1;                   // of the temporary file's removal on a signal
};

// Writes `content` to `path` through an AtomicOutputFile. Throws InputError.
void writeFileAtomically(const std::string& path, std::string_view content);

}  // namespace isurface
