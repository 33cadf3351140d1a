#pragma once
// Biip.dat: the binary interpolation dump (format in docs/biip-format.md, version 1).
// The reader maps the file; channels are read in place through strided views.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace isurface {

enum class BiipType : std::uint8_t { F64 = 1, F32 = 2, I32 = 3, U32 = 4, I64 = 5, U64 = 6 };

std::size_t biipTypeSize(BiipType type);

struct BiipChannel {
  std::string name;  // [a-z0-9_], at most 24 characters
  BiipType type = BiipType::F64;
  std::uint32_t offset = 0;  // bytes inside a record
};

struct BiipHeader {
  std::uint16_t versionMajor = 1;
  std::uint16_t versionMinor = 0;
  std::uint32_t headerBytes = 0;
  std::uint32_t recordBytes = 0;
  std::uint32_t flags = 0;
  double cycleSeconds = 0.001;
  std::uint64_t recordCount = 0;
  double t0Seconds = 0;
  std::vector<BiipChannel> channels;
  std::string metadataJson;  // "" when the file has none
};

// A read-only view of one channel: value i converted to double (or to u64 for counters).
class BiipChannelView {
 public:
  BiipChannelView() = default;
  BiipChannelView(const unsigned char* first, std::size_t stride, BiipType type, std::size_t count)
      : first_(first), stride_(stride), type_(type), count_(count) {}
  bool valid() const { return first_ != nullptr; }
  std::size_t size() const { return count_; }
  BiipType type() const { return type_; }
  double operator[](std::size_t i) const;

 private:
  const unsigned char* first_ = nullptr;
  std::size_t stride_ = 0;
  BiipType type_ = BiipType::F64;
  std::size_t count_ = 0;
};

class BiipReader {
 public:
  // Maps and validates the file. Throws InputError naming the file and the problem for every
  // refusal listed in the format; recoverable damage is reported through warnings().
  explicit BiipReader(const std::string& path);
  ~BiipReader();
  BiipReader(const BiipReader&) = delete;
  BiipReader& operator=(const BiipReader&) = delete;

  const std::string& path() const { return path_; }
  const BiipHeader& header() const { return header_; }
  std::size_t recordCount() const { return records_; }  // records actually loaded
  const std::vector<std::string>& warnings() const { return warnings_; }

  bool hasChannel(const std::string& name) const;
  // An invalid view when the channel is absent.
  BiipChannelView channel(const std::string& name) const;
  // Time of record i in seconds: the `t` channel when present, else t0 + i * cycle.
  double timeAt(std::size_t i) const;

 private:
  std::string path_;
  BiipHeader header_;
  std::size_t records_ = 0;
  std::vector<std::string> warnings_;
  const unsigned char* data_ = nullptr;
  std::size_t size_ = 0;
  BiipChannelView t_;
};

// Streams records to `path` through a temporary file beside it; commit() renames it into place.
// Destroying a writer that was not committed removes the temporary file: no partial output.
class BiipWriter {
 public:
  BiipWriter(const std::string& path, std::vector<BiipChannel> channels, double cycleSeconds,
             std::string metadataJson, double t0Seconds = 0);
  ~BiipWriter();
  BiipWriter(const BiipWriter&) = delete;
  BiipWriter& operator=(const BiipWriter&) = delete;

  // Lays channels out in the given order, each aligned to its size; returns the channel list.
  static std::vector<BiipChannel> layout(
      const std::vector<std::pair<std::string, BiipType>>& namesAndTypes);
  std::uint32_t recordBytes() const { return recordBytes_; }

  // Appends one record of recordBytes() bytes, already laid out.
  void append(const void* record);
  std::uint64_t recordCount() const { return count_; }
  // Writes the final count, flushes, renames into place. Throws InputError on an I/O failure.
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::uint32_t recordBytes_ = 0;
  std::uint64_t count_ = 0;
};

}  // namespace isurface
