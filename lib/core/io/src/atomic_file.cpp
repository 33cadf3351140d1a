#include "isurface/io/atomic_file.h"
#include "isurface/io/output_path.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <system_error>
#include <thread>

#include "isurface/base/diagnostic.h"
#include "isurface/base/input_files.h"
#include "isurface/io/output_transaction.h"
#include "temporary_files.h"

namespace isurface {

namespace {

std::string errorText(int error) { return std::error_code(error, std::generic_category()).message(); }

// Writes all n bytes; returns 0 or the errno of the failure.
int writeAll(int fd, const unsigned char* data, std::size_t n) {
  while (n > 0) {
    const std::size_t chunk = std::min<std::size_t>(n, std::size_t(1) << 30);
    const ssize_t done = ::write(fd, data, chunk);
    if (done < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (done == 0) return ENOSPC;  // no progress: treat as a full device
    data += done;
    n -= static_cast<std::size_t>(done);
  }
  return 0;
}

int pwriteAll(int fd, const unsigned char* data, std::size_t n, std::uint64_t offset) {
  while (n > 0) {
    const ssize_t done = ::pwrite(fd, data, n, static_cast<off_t>(offset));
    if (done < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (done == 0) return ENOSPC;
    data += done;
    n -= static_cast<std::size_t>(done);
    offset += static_cast<std::uint64_t>(done);
  }
  return 0;
}

// The process umask without changing it (umask() would race with other threads).
mode_t currentUmask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
  }
  return 022;
}

std::string folderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string baseNameOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A temporary name beside `destination`: its own name and a suffix, or a short hidden name
// when a legal long name would pass the file system's limit with the suffix.
std::string temporaryPattern(const std::string& destination) {
  constexpr std::size_t kSuffix = 10;  // ".tmpXXXXXX"
  const long longest = ::pathconf(folderOf(destination).c_str(), _PC_NAME_MAX);
  const std::size_t limit = longest > 0 ? static_cast<std::size_t>(longest) : 255;
  if (baseNameOf(destination).size() + kSuffix <= limit) return destination + ".tmpXXXXXX";
  const std::string folder = folderOf(destination);
  return (folder == "/" ? "" : folder) + "/.isurface-tmpXXXXXX";
}

constexpr const char* kInputMessage = "cannot write: it is an input of this command (give another output name)";

// Past this many bytes written since the last request, the file is synced in the background.
constexpr std::uint64_t kBackgroundSyncBytes = std::uint64_t{8} << 20;

// Devices and pipes do not support fsync (EINVAL, EROFS): nothing to sync there.
bool cannotSync(int error) { return error == EINVAL || error == EROFS || error == ENOTSUP; }

}  // namespace

// Syncing a large file costs about as much as writing it (tens of milliseconds for 50 MB here),
// and commit() must not rename before the data is on disk. Syncing what is already written on
// another thread while the writer goes on leaves commit() only the last few megabytes.
//
// The rename frees the file it replaces, cached pages included, on the committing thread; the
// cache of a large file is dropped here beforehand (its content stays as it is until the rename).
class AtomicOutputFile::BackgroundSync {
 public:
  // `replaced`: the file the rename will replace, or empty.
  BackgroundSync(int fd, std::string replaced)
      : fd_(fd), replaced_(std::move(replaced)), thread_([this] { run(); }) {}
  ~BackgroundSync() { finish(); }
  BackgroundSync(const BackgroundSync&) = delete;
  BackgroundSync& operator=(const BackgroundSync&) = delete;

  // Syncs again once the sync under way (if any) is done.
  void request() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      requested_ = true;
    }
    wake_.notify_one();
  }

  // Waits for the sync under way; returns the errno of the first failed sync, or 0. A writeback
  // error is reported to one sync only, so it must not be lost here.
  int finish() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    if (thread_.joinable()) thread_.join();
    return error_;
  }

 private:
  void run() {
    if (!replaced_.empty()) {
      const int old = ::open(replaced_.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
      if (old >= 0) {
        ::posix_fadvise(old, 0, 0, POSIX_FADV_DONTNEED);
        ::close(old);
      }
    }
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return requested_ || stopping_; });
      if (stopping_) return;
      requested_ = false;
      lock.unlock();
      const int error = ::fdatasync(fd_) == 0 ? 0 : errno;
      lock.lock();
      if (error != 0 && error_ == 0 && !cannotSync(error)) error_ = error;
    }
  }

  const int fd_;
  const std::string replaced_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool requested_ = false, stopping_ = false;
  int error_ = 0;
  std::thread thread_;  // last: it starts once the rest is ready
};

AtomicOutputFile::AtomicOutputFile(std::string target, std::size_t bufferBytes)
    : target_(std::move(target)), capacity_(std::max<std::size_t>(bufferBytes, 4096)) {
  if (target_.empty()) fail(ENOENT, "empty file name");
  // The path the temporary file is renamed to: the file the target's links lead to.
  const std::string destination = outputDestination(target_);
  mode_t mode = 0666 & ~currentUmask();
  struct stat st {};
  if (::stat(destination.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fail(EISDIR);
    if (isProtectedInputFile(target_)) throw InputError(Diagnostic{target_, 0, 0, kInputMessage});
    if (!S_ISREG(st.st_mode)) {
      // A device, pipe or socket: it cannot be replaced, so write it in place.
      direct_ = true;
      temp_ = target_;
      fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      if (fd_ < 0) fail(errno);
      seekable_ = ::lseek(fd_, 0, SEEK_CUR) != static_cast<off_t>(-1);
    } else {
      mode = st.st_mode & 07777;  // keep an existing file's permissions
      replacing_ = true;
    }
  }
  if (!direct_) {
    // Remembered for the signal handlers before the file is made, in the buffer mkostemp fills
    // in place: a signal between making and remembering it left the file behind.
    temp_ = temporaryPattern(destination);
    signalSlot_ = detail::rememberTemporary(temp_.c_str());
    fd_ = ::mkostemp(temp_.data(), O_CLOEXEC);
    if (fd_ < 0) {
      const int error = errno;
      detail::forgetTemporary(signalSlot_);
      signalSlot_ = -1;
      temp_.clear();
      fail(error, "cannot create a temporary file in '" + folderOf(destination) + "'");
    }
    if (::fchmod(fd_, mode) != 0) fail(errno);
    destination_ = destination;
  }
  buffer_.reset(new unsigned char[capacity_]);
}

AtomicOutputFile::~AtomicOutputFile() { discard(); }

void AtomicOutputFile::discard() noexcept {
  sync_.reset();  // before the file descriptor it syncs is closed
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!direct_ && !committed_ && !temp_.empty()) ::unlink(temp_.c_str());
  detail::forgetTemporary(signalSlot_);
  signalSlot_ = -1;
  if (!direct_ && !committed_) temp_.clear();
}

void AtomicOutputFile::fail(int error, const std::string& context) {
  discard();
  std::string message = "cannot write: " + errorText(error);
  if (!context.empty()) message += " (" + context + ")";
  throw InputError(Diagnostic{target_, 0, 0, message});
}

void AtomicOutputFile::flushBuffer() {
  if (used_ == 0) return;
  if (fd_ < 0) fail(EBADF, "the file was already closed");
  if (const int error = writeAll(fd_, buffer_.get(), used_)) fail(error);
  flushed_ += used_;
  used_ = 0;
  syncWrittenInBackground();
}

void AtomicOutputFile::syncWrittenInBackground() {
  if (direct_ || backgroundSyncFailed_ || flushed_ - syncRequested_ < kBackgroundSyncBytes) return;
  syncRequested_ = flushed_;
  if (!sync_) {
    try {
      sync_ = std::make_unique<BackgroundSync>(fd_, replacing_ ? destination_ : std::string());
    } catch (const std::system_error&) {
      backgroundSyncFailed_ = true;  // no thread to be had: commit() syncs it all
      return;
    }
  }
  sync_->request();
}

void AtomicOutputFile::writeSlow(const void* data, std::size_t n) {
  flushBuffer();
  if (n >= capacity_) {
    if (fd_ < 0) fail(EBADF, "the file was already closed");
    if (const int error = writeAll(fd_, static_cast<const unsigned char*>(data), n)) fail(error);
    flushed_ += n;
    syncWrittenInBackground();
  } else {
    std::memcpy(buffer_.get(), data, n);
    used_ = n;
  }
}

void AtomicOutputFile::writeAt(std::uint64_t offset, const void* data, std::size_t n) {
  if (!seekable_) fail(ESPIPE);
  flushBuffer();
  if (fd_ < 0) fail(EBADF, "the file was already closed");
  if (const int error = pwriteAll(fd_, static_cast<const unsigned char*>(data), n, offset)) fail(error);
}

void AtomicOutputFile::commit() {
  if (committed_) return;
  flushBuffer();
  if (fd_ < 0) fail(EBADF, "the file was already closed");
  if (sync_) {
    const int error = sync_->finish();
    sync_.reset();
    if (error != 0) fail(error);
  }
  // Data on disk before the rename, so a crash leaves the old file or the whole new one.
  if (::fsync(fd_) != 0 && !cannotSync(errno)) fail(errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && errno != EINTR) fail(errno);
  if (!direct_) {
    if (isProtectedInputFile(destination_)) {
      discard();
      throw InputError(Diagnostic{target_, 0, 0, kInputMessage});
    }
    bool deferred = false;
    try {
      deferred = detail::deferRename(temp_, destination_, target_);
    } catch (...) {
      discard();
      throw;
    }
    if (deferred) {
      detail::forgetTemporary(signalSlot_);  // the transaction removes it now
      signalSlot_ = -1;
      committed_ = true;
      temp_.clear();
      return;
    }
    if (::rename(temp_.c_str(), destination_.c_str()) != 0) fail(errno);
    detail::forgetTemporary(signalSlot_);
    signalSlot_ = -1;
    committed_ = true;
    temp_.clear();
    // Make the rename itself durable; a failure here loses nothing already visible.
    const int dir = ::open(folderOf(destination_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
      ::fsync(dir);
      ::close(dir);
    }
  }
  committed_ = true;
}

void writeFileAtomically(const std::string& path, std::string_view content) {
  AtomicOutputFile out(path, std::min<std::size_t>(std::max<std::size_t>(content.size(), 4096),
                                                   AtomicOutputFile::kDefaultBufferBytes));
  out.write(content);
  out.commit();
}

}  // namespace isurface
