#pragma once
// A file read as a std::istream without waiting for a FIFO's writer.
#include <istream>
#include <memory>
#include <streambuf>
#include <string>

namespace isurface {

// A std::istream over openForReading(path): a named pipe nobody writes to reads as empty at once,
// where a std::ifstream would keep the command waiting for ever. When the file cannot be opened
// the stream starts failed and errno says why, as after a std::ifstream.
class FileReadStream : public std::istream {
 public:
  explicit FileReadStream(const std::string& path);
  ~FileReadStream() override;
  FileReadStream(const FileReadStream&) = delete;
  FileReadStream& operator=(const FileReadStream&) = delete;

 private:
  std::unique_ptr<std::streambuf> buffer_;
};

}  // namespace isurface
