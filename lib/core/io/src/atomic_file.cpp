#include "isurface/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include "isurface/base/diagnostic.h"

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

}  // namespace

AtomicOutputFile::AtomicOutputFile(std::string target, std::size_t bufferBytes)
    : target_(std::move(target)), capacity_(std::max<std::size_t>(bufferBytes, 4096)) {
  if (target_.empty()) fail(ENOENT, "empty file name");
  std::string destination = target_;  // the path the temporary file is renamed to
  mode_t mode = 0666 & ~currentUmask();
  struct stat st {};
  if (::stat(target_.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fail(EISDIR);
    if (!S_ISREG(st.st_mode)) {
      // A device, pipe or socket: it cannot be replaced, so write it in place.
      direct_ = true;
      temp_ = target_;
      fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      if (fd_ < 0) fail(errno);
      seekable_ = ::lseek(fd_, 0, SEEK_CUR) != static_cast<off_t>(-1);
    } else {
      mode = st.st_mode & 07777;  // keep an existing file's permissions
      struct stat lst {};
      if (::lstat(target_.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
        // Replace the file the link points to, not the link.
        if (char* real = ::realpath(target_.c_str(), nullptr)) {
          destination = real;
          std::free(real);
        }
      }
    }
  }
  if (!direct_) {
    std::string pattern = destination + ".tmpXXXXXX";
    fd_ = ::mkostemp(pattern.data(), O_CLOEXEC);
    if (fd_ < 0) fail(errno, "cannot create a temporary file in '" + folderOf(destination) + "'");
    temp_ = pattern;
    if (::fchmod(fd_, mode) != 0) fail(errno);
    destination_ = destination;
  }
  buffer_.reset(new unsigned char[capacity_]);
}

AtomicOutputFile::~AtomicOutputFile() { discard(); }

void AtomicOutputFile::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!direct_ && !committed_ && !temp_.empty()) {
    ::unlink(temp_.c_str());
    temp_.clear();
  }
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
}

void AtomicOutputFile::writeSlow(const void* data, std::size_t n) {
  flushBuffer();
  if (n >= capacity_) {
    if (fd_ < 0) fail(EBADF, "the file was already closed");
    if (const int error = writeAll(fd_, static_cast<const unsigned char*>(data), n)) fail(error);
    flushed_ += n;
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
  // Data on disk before the rename, so a crash leaves the old file or the whole new one.
  // Devices and pipes do not support fsync (EINVAL, EROFS): nothing to sync there.
  if (::fsync(fd_) != 0 && errno != EINVAL && errno != EROFS && errno != ENOTSUP) fail(errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && errno != EINTR) fail(errno);
  if (!direct_) {
    if (::rename(temp_.c_str(), destination_.c_str()) != 0) fail(errno);
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
