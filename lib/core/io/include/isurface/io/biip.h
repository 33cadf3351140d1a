#pragma once
// Biip.dat: the binary interpolation dump (format in docs/biip-format.md, version 1).
// The reader maps the file; channels are read in place through strided views.
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <optional>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "isurface/base/shrink_guard.h"

namespace isurface {

enum class BiipType : std::uint8_t { F64 = 1, F32 = 2, I32 = 3, U32 = 4, I64 = 5, U64 = 6 };

// Limits of format version 1.
constexpr std::uint16_t kBiipVersionMajor = 1;
constexpr std::uint16_t kBiipVersionMinor = 0;
constexpr std::uint32_t kBiipFixedHeaderBytes = 64;
constexpr std::uint32_t kBiipChannelEntryBytes = 32;
constexpr std::uint32_t kBiipMaxChannels = 256;
constexpr std::uint32_t kBiipMaxRecordBytes = 4096;
// The sample periods a control or a recorder has, s: a dump's cycle_s and every importer's.
constexpr double kBiipShortestCycle = 1e-6;
constexpr double kBiipLongestCycle = 60;
constexpr std::size_t kBiipMaxNameLength = 24;

std::size_t biipTypeSize(BiipType type);   // 0 for a value outside the enumeration
const char* biipTypeName(BiipType type);   // "f64", "f32", "i32", "u32", "i64", "u64"; "?" else
bool biipTypeKnown(std::uint8_t code);     // 1..6
bool biipValidChannelName(std::string_view name);  // 1..24 characters of [a-z0-9_]

struct BiipChannel {
  std::string name;  // [a-z0-9_], at most 24 characters
  BiipType type = BiipType::F64;
  std::uint32_t offset = 0;  // bytes inside a record
};

// Stores `value` converted to the channel's type at its offset in `record` (writers' helper).
// Integer types are rounded to nearest and clamped to the type's range; NaN stores 0.
void biipStore(void* record, const BiipChannel& channel, double value);

struct BiipHeader {
  std::uint16_t versionMajor = 1;
  std::uint16_t versionMinor = 0;
  std::uint32_t headerBytes = 0;
  std::uint32_t recordBytes = 0;
  std::uint32_t flags = 0;
  double cycleSeconds = 0.001;
  std::uint64_t recordCount = 0;  // as written in the file (0 = not known)
  double t0Seconds = 0;
  std::vector<BiipChannel> channels;
  std::string metadataJson;  // "" when the file has none (or its metadata was unusable)
};

// A read-only view of one channel: value i converted to double (or to u64 for counters).
class BiipChannelView;
// Value i of a line or move-index channel: an InputError naming the file, the channel and the
// record where it is not a whole number from 0 to 4294967295.
std::uint32_t countAt(const BiipChannelView& view, std::size_t i, const std::string& path, const char* channel);

// Every rate is divided by a time difference: time i of a dump's `t` channel (record i * thinning)
// must be finite and later than time i - 1, else an InputError naming the file and the record.
template <class Times>
void requireTimeAdvances(const Times& time, std::size_t i, const std::string& path, std::size_t thinning = 1);
void requireTimeAdvances(double before, double now, std::size_t record, const std::string& path);
template <class Times>
void requireTimeAdvances(const Times& time, std::size_t i, const std::string& path, std::size_t thinning) {
  requireTimeAdvances(i > 0 ? time[i - 1] : -std::numeric_limits<double>::infinity(), time[i], i * thinning, path);
}

class BiipChannelView {
 public:
  BiipChannelView() = default;
  BiipChannelView(const unsigned char* first, std::size_t stride, BiipType type, std::size_t count)
      : first_(first), stride_(stride), type_(type), count_(count) {}
  bool valid() const { return first_ != nullptr; }
  std::size_t size() const { return count_; }
  BiipType type() const { return type_; }
  std::size_t stride() const { return stride_; }  // bytes between consecutive values
  // Every k-th value (k >= 1) from the first: value i of the result is value i * k of this.
  BiipChannelView every(std::size_t k) const {
    if (!valid() || k <= 1) return *this;
    return BiipChannelView(first_, stride_ * k, type_, (count_ + k - 1) / k);
  }
  // Values [begin, begin + count) (clipped to the view): value i of the result is begin + i.
  BiipChannelView part(std::size_t begin, std::size_t count) const {
    if (!valid()) return *this;
    begin = std::min(begin, count_);
    return BiipChannelView(first_ + begin * stride_, stride_, type_, std::min(count, count_ - begin));
  }
  double operator[](std::size_t i) const {
    const unsigned char* p = first_ + i * stride_;
    if (type_ == BiipType::F64) {
      double v;
      std::memcpy(&v, p, sizeof v);
      return v;
    }
    return convert(p, type_);
  }
  // Value i as an unsigned integer, exact for every integer type (negative values clamp to 0,
  // floating values are truncated; NaN gives 0).
  std::uint64_t integer(std::size_t i) const;
  // Value i as a count of 32 bits (a line number, a move index), exact for every type; nullopt
  // when it is not a whole number from 0 to 4294967295 (1.5, -3, NaN, 1e20).
  std::optional<std::uint32_t> wholeNumber(std::size_t i) const;
  // Converts values [begin, begin + count) to doubles; count is clipped to the view's size.
  void copyTo(double* out, std::size_t begin, std::size_t count) const;
  void copyTo(float* out, std::size_t begin, std::size_t count) const;

  static double convert(const unsigned char* p, BiipType type) {
    switch (type) {
      case BiipType::F64: { double v; std::memcpy(&v, p, 8); return v; }
      case BiipType::F32: { float v; std::memcpy(&v, p, 4); return v; }
      case BiipType::I32: { std::int32_t v; std::memcpy(&v, p, 4); return double(v); }
      case BiipType::U32: { std::uint32_t v; std::memcpy(&v, p, 4); return double(v); }
      case BiipType::I64: { std::int64_t v; std::memcpy(&v, p, 8); return double(v); }
      case BiipType::U64: { std::uint64_t v; std::memcpy(&v, p, 8); return double(v); }
    }
    return 0;
  }

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
  // Problems the reader worked around, one sentence each, without the file name; the first call
  // reads every record's x, y and z to count the non-finite ones (seconds on a dump of tens of
  // millions of records; InputError when the file was cut short since it was opened).
  const std::vector<std::string>& warnings() const;
  // The same without the count of non-finite records: what opening the file found. A loader that
  // reads every record anyway counts them itself (nonFiniteWarning) instead of a walk of its own.
  const std::vector<std::string>& headerWarnings() const { return headerWarnings_; }
  // Records whose x, y or z is NaN or infinite (counted at the first call: a walk over the file,
  // which throws InputError when the file was cut short since it was opened).
  std::size_t nonFiniteSampleCount() const;

  bool hasChannel(const std::string& name) const;
  const BiipChannel* findChannel(const std::string& name) const;  // nullptr when absent
  // An invalid view when the channel is absent.
  BiipChannelView channel(const std::string& name) const;
  // Converts records [begin, begin + count) of a channel to doubles (count clipped to the
  // records loaded). Returns false when the channel is absent.
  bool copyChannel(const std::string& name, double* out, std::size_t begin, std::size_t count) const;
  // Time of record i in seconds: the `t` channel when present, else t0 + i * cycle.
  double timeAt(std::size_t i) const;
  // The raw bytes of record i (recordBytes() of them), in place in the mapping.
  const unsigned char* record(std::size_t i) const { return data_ + header_.headerBytes + i * header_.recordBytes; }
  std::size_t fileBytes() const { return size_; }
  // Drops the pages of records [begin, end) from this process's resident memory; reading them
  // again maps them again from the file. A reader that walks a dump once calls it behind itself,
  // so a dump larger than memory can be read and a copy of it does not cost twice its size.
  void releaseRecords(std::size_t begin, std::size_t end) const;
  // Throws InputError when another process cut the file short while it was read: the records
  // read past its new end held zeros, not the dump.
  void checkIntact() const;

 private:
  [[noreturn]] void refuse(const std::string& problem) const;
  void parse();
  void mapFile();
  // Returns the channel count and the metadata's size in bytes.
  std::pair<std::uint32_t, std::uint32_t> parseFixedHeader();
  void parseChannelTable(std::uint32_t channelCount);
  void parseMetadata(std::size_t tableEnd, std::uint32_t metadataBytes);
  void countRecords();
  void checkTimeChannel() const;
  void unmap() noexcept;

  std::string path_;
  BiipHeader header_;
  std::size_t records_ = 0;
  std::vector<std::string> headerWarnings_;
  const unsigned char* data_ = nullptr;
  std::size_t size_ = 0;
  std::unique_ptr<ShrinkGuard> guard_;
  BiipChannelView t_;
  // Counted once, when first asked for (by any thread: the window shares an open dump).
  mutable std::once_flag nonFiniteCounted_;
  mutable std::size_t nonFinite_ = 0;
  mutable std::vector<std::string> warnings_;
};

// The warning for `count` samples with a non-finite x, y or z ("" for none).
std::string nonFiniteWarning(std::size_t count);

// Streams records to `path` through a temporary file beside it; commit() renames it into place.
// Destroying a writer that was not committed removes the temporary file: no partial output.
// The header is written first with record_count 0; commit() writes the real count.
class BiipWriter {
 public:
  // Throws std::invalid_argument for channels that break the format (bad or duplicate names,
  // a channel outside the record, no x/y/z, more than 256 channels, records over 4096 bytes),
  // a cycle that is not finite and > 0, or metadata that is not a JSON object; throws
  // InputError when the file cannot be created.
  BiipWriter(const std::string& path, std::vector<BiipChannel> channels, double cycleSeconds,
             std::string metadataJson, double t0Seconds = 0);
  ~BiipWriter();
  BiipWriter(const BiipWriter&) = delete;
  BiipWriter& operator=(const BiipWriter&) = delete;

  // Lays channels out in the given order, each aligned to its size; returns the channel list.
  static std::vector<BiipChannel> layout(
      const std::vector<std::pair<std::string, BiipType>>& namesAndTypes);
  // Record size for a channel list: the end of the last byte used, rounded up to 8.
  static std::uint32_t recordBytesFor(const std::vector<BiipChannel>& channels);
  std::uint32_t recordBytes() const { return recordBytes_; }
  const std::vector<BiipChannel>& channels() const;
  // The offset of a channel in a record; throws std::out_of_range when absent.
  std::uint32_t offsetOf(const std::string& name) const;

  // Appends one record of recordBytes() bytes, already laid out.
  void append(const void* record);
  // Appends `count` consecutive records.
  void appendRecords(const void* records, std::size_t count);
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
