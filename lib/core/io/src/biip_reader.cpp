// Biip reader: maps the file read-only and validates it against format version 1.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <system_error>
#include <unordered_set>

#include "isurface/io/biip.h"
#include "isurface/base/input_files.h"
#include "isurface/base/bounded_file.h"
#include "isurface/base/diagnostic.h"

namespace isurface {

namespace {

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

std::string inQuotes(const std::string& s) { return "'" + s + "'"; }

// A channel name as stored: up to 24 bytes, NUL-padded. Non-printable bytes are shown as \xNN.
std::string printableName(const unsigned char* p, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n && p[i] != 0; ++i) {
    if (p[i] >= 0x20 && p[i] < 0x7f) {
      out += static_cast<char>(p[i]);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[p[i] >> 4];
      out += hex[p[i] & 15];
    }
  }
  return out;
}

// Records scanned between two releases of their pages at open: 16 MB of a 64-byte record.
constexpr std::size_t kScanRecords = std::size_t(1) << 18;

std::size_t countNonFinite(const BiipChannelView& x, const BiipChannelView& y, const BiipChannelView& z,
                           std::size_t begin, std::size_t end) {
  std::size_t bad = 0;
  // v - v is 0 for a finite v and NaN for NaN or an infinity: no branch per sample.
  for (std::size_t i = begin; i < end; ++i) {
    const double a = x[i], b = y[i], c = z[i];
    const double s = (a - a) + (b - b) + (c - c);
    bad += static_cast<std::size_t>(s != s);
  }
  return bad;
}

}  // namespace

namespace {

// Metadata is a few notes (the program, the machine): nesting deeper than this is no note, and
// printing it indented would take the square of its depth in bytes.
constexpr std::size_t kDeepestMetadata = 64;

// The deepest nesting of objects and arrays in JSON text, strings skipped; no parsing.
std::size_t jsonNestingDepth(std::string_view text) {
  std::size_t depth = 0, deepest = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == '}' || c == ']') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

BiipReader::BiipReader(const std::string& path) : path_(path) {
  try {
    parse();
  } catch (...) {
    unmap();
    throw;
  }
}

BiipReader::~BiipReader() { unmap(); }

void BiipReader::unmap() noexcept {
  guard_.reset();
  if (data_ != nullptr && size_ > 0) ::munmap(const_cast<unsigned char*>(data_), size_);
  data_ = nullptr;
}

void BiipReader::refuse(const std::string& problem) const {
  throw InputError(Diagnostic{path_, 0, 0, problem});
}

void BiipReader::parse() {
  mapFile();
  const auto [channelCount, metadataBytes] = parseFixedHeader();
  parseChannelTable(channelCount);
  parseMetadata(kBiipFixedHeaderBytes + std::size_t(kBiipChannelEntryBytes) * channelCount, metadataBytes);
  countRecords();
  checkIntact();
}

void BiipReader::releaseRecords(std::size_t begin, std::size_t end) const {
  if (data_ == nullptr || begin >= end) return;
  static const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t recordBytes = header_.recordBytes;
  // Only whole pages inside the range: a page shared with a record outside it stays.
  std::size_t first = header_.headerBytes + begin * recordBytes;
  std::size_t last = end >= records_ ? size_ : header_.headerBytes + end * recordBytes;
  first = (first + page - 1) / page * page;
  last = last / page * page;
  if (last > first) ::madvise(const_cast<unsigned char*>(data_) + first, last - first, MADV_DONTNEED);
}

void BiipReader::checkIntact() const {
  if (guard_ && guard_->shrank())
    refuse("the file was cut short while it was read (it had " + std::to_string(size_) +
           " bytes when opened): another program changed it");
}

void BiipReader::mapFile() {
  const int fd = openForReading(path_);
  if (fd < 0) refuse("cannot read: " + std::error_code(errno, std::generic_category()).message());
  try {
    noteInputFile(fd, path_);
  } catch (...) {
    ::close(fd);
    throw;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int error = errno;
    ::close(fd);
    refuse("cannot read: " + std::error_code(error, std::generic_category()).message());
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    refuse(S_ISDIR(st.st_mode) ? "is a folder, not a Biip file" : "is not a regular file (Biip files are mapped)");
  }
  const std::size_t size = static_cast<std::size_t>(st.st_size);
  if (size == 0) {
    ::close(fd);
    refuse("empty file (0 bytes), not a Biip file");
  }
  void* map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  const int mapError = errno;
  ::close(fd);
  if (map == MAP_FAILED) refuse("cannot map: " + std::error_code(mapError, std::generic_category()).message());
  data_ = static_cast<const unsigned char*>(map);
  size_ = size;
  guard_ = std::make_unique<ShrinkGuard>(map, size);
  ::madvise(map, size, MADV_SEQUENTIAL);
}

std::pair<std::uint32_t, std::uint32_t> BiipReader::parseFixedHeader() {
  const unsigned char* d = data_;
  const auto tooShort = [&] {
    refuse("file too short for the Biip header (" + std::to_string(size_) + " bytes, the fixed header alone is 64)");
  };
  if (size_ < 4) tooShort();
  if (std::memcmp(d, "BIIP", 4) != 0) refuse("not a Biip file (wrong magic: expected \"BIIP\")");
  if (size_ < kBiipFixedHeaderBytes) tooShort();
  BiipHeader& h = header_;
  h.versionMajor = load<std::uint16_t>(d + 4);
  h.versionMinor = load<std::uint16_t>(d + 6);
  h.headerBytes = load<std::uint32_t>(d + 8);
  const std::uint32_t channelCount = load<std::uint32_t>(d + 12);
  h.recordBytes = load<std::uint32_t>(d + 16);
  h.flags = load<std::uint32_t>(d + 20);
  h.cycleSeconds = load<double>(d + 24);
  h.recordCount = load<std::uint64_t>(d + 32);
  h.t0Seconds = load<double>(d + 40);
  const std::uint32_t metadataBytes = load<std::uint32_t>(d + 48);

  if (h.versionMajor != kBiipVersionMajor) {
    refuse("unsupported Biip major version " + std::to_string(h.versionMajor) + "." + std::to_string(h.versionMinor) +
           " (this reader knows version 1)");
  }
  if (channelCount == 0 || channelCount > kBiipMaxChannels) {
    refuse("channel_count " + std::to_string(channelCount) + " is outside 1..256");
  }
  if (h.recordBytes == 0 || h.recordBytes > kBiipMaxRecordBytes) {
    refuse("record_bytes " + std::to_string(h.recordBytes) + " is outside 1..4096");
  }
  // The sample periods a control or a recorder has (import --cycle takes the same): 5e-324 s or
  // 1e300 s made every speed infinite or zero.
  if (!(h.cycleSeconds >= kBiipShortestCycle && h.cycleSeconds <= kBiipLongestCycle)) {
    refuse(fmt::format("cycle_s {:g} is not a sample period (1e-6 to 60 s)", h.cycleSeconds));
  }
  const std::uint64_t tableEnd = kBiipFixedHeaderBytes + std::uint64_t(kBiipChannelEntryBytes) * channelCount;
  const std::uint64_t minimumHeader = tableEnd + metadataBytes;
  if (h.headerBytes < minimumHeader) {
    refuse("header_bytes " + std::to_string(h.headerBytes) + " is smaller than 64 + 32 x " +
           std::to_string(channelCount) + " channels + " + std::to_string(metadataBytes) + " metadata bytes = " +
           std::to_string(minimumHeader));
  }
  if (h.headerBytes > size_) {
    refuse("header runs past the end of the file (header_bytes " + std::to_string(h.headerBytes) + ", file " +
           std::to_string(size_) + " bytes)");
  }

  return {channelCount, metadataBytes};
}

void BiipReader::parseChannelTable(std::uint32_t channelCount) {
  const unsigned char* d = data_;
  BiipHeader& h = header_;
  std::unordered_set<std::string> names;
  h.channels.reserve(channelCount);
  for (std::uint32_t c = 0; c < channelCount; ++c) {
    const unsigned char* e = d + kBiipFixedHeaderBytes + std::size_t(kBiipChannelEntryBytes) * c;
    std::size_t length = 0;
    while (length < kBiipMaxNameLength && e[length] != 0) ++length;
    BiipChannel channel;
    channel.name.assign(reinterpret_cast<const char*>(e), length);
    const std::string label = "channel " + std::to_string(c + 1);
    if (length == 0) refuse(label + " has an empty name");
    if (!biipValidChannelName(channel.name)) {
      refuse(label + " name " + inQuotes(printableName(e, length)) + " is not made of [a-z0-9_]");
    }
    const std::uint8_t type = e[24];
    if (!biipTypeKnown(type)) {
      refuse("channel " + inQuotes(channel.name) + " has unknown type " + std::to_string(type) +
             " (1..6 are f64 f32 i32 u32 i64 u64)");
    }
    channel.type = static_cast<BiipType>(type);
    channel.offset = load<std::uint32_t>(e + 28);
    const std::uint64_t end = std::uint64_t(channel.offset) + biipTypeSize(channel.type);
    if (end > h.recordBytes) {
      refuse("channel " + inQuotes(channel.name) + " (" + biipTypeName(channel.type) + " at offset " +
             std::to_string(channel.offset) + ") lies outside the " + std::to_string(h.recordBytes) +
             "-byte record");
    }
    if (!names.insert(channel.name).second) refuse("two channels are named " + inQuotes(channel.name));
    h.channels.push_back(std::move(channel));
  }
  for (const char* required : {"x", "y", "z"}) {
    if (names.count(required) == 0) {
      refuse(std::string("no '") + required + "' channel (x, y and z are required)");
    }
  }

}

// Metadata: a JSON object. Unusable metadata is ignored with a warning, never fatal.
void BiipReader::parseMetadata(std::size_t tableEnd, std::uint32_t metadataBytes) {
  const unsigned char* d = data_;
  BiipHeader& h = header_;
  if (metadataBytes > 0) {
    std::string_view text(reinterpret_cast<const char*>(d + tableEnd), metadataBytes);
    while (!text.empty() && (text.back() == '\0' || text.back() == ' ' || text.back() == '\n' ||
                             text.back() == '\r' || text.back() == '\t')) {
      text.remove_suffix(1);
    }
    if (!text.empty()) {
      const std::size_t depth = jsonNestingDepth(text);
      const auto parsed = depth > kDeepestMetadata ? nlohmann::json(nlohmann::json::value_t::discarded)
                                                   : nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
      if (depth > kDeepestMetadata) {
        headerWarnings_.push_back("metadata is nested " + std::to_string(depth) + " levels deep, more than " +
                            std::to_string(kDeepestMetadata) + "; ignored");
      } else if (parsed.is_discarded()) {
        headerWarnings_.push_back("metadata is not valid UTF-8 JSON; ignored");
      } else if (!parsed.is_object()) {
        headerWarnings_.push_back("metadata is JSON but not an object; ignored");
      } else {
        h.metadataJson.assign(text.data(), text.size());
      }
    }
  }
  if (!std::isfinite(h.t0Seconds)) {
    headerWarnings_.push_back("t0_s is not finite; 0 is used instead");
    h.t0Seconds = 0;
  }

}

void BiipReader::countRecords() {
  BiipHeader& h = header_;
  const std::size_t body = size_ - h.headerBytes;
  const std::size_t whole = body / h.recordBytes;
  const std::size_t partial = body % h.recordBytes;
  if (h.recordCount == 0) {
    records_ = whole;
    if (partial != 0) {
      headerWarnings_.push_back("final record cut short (" + std::to_string(partial) + " of " +
                          std::to_string(h.recordBytes) + " bytes): dropped");
    }
  } else if (h.recordCount > whole) {
    records_ = whole;
    headerWarnings_.push_back("record_count says " + std::to_string(h.recordCount) + " records but the file holds " +
                        std::to_string(whole) + (partial != 0 ? " whole ones" : "") + "; loaded " +
                        std::to_string(whole));
    if (partial != 0) {
      headerWarnings_.push_back("final record cut short (" + std::to_string(partial) + " of " +
                          std::to_string(h.recordBytes) + " bytes): dropped");
    }
  } else {
    records_ = static_cast<std::size_t>(h.recordCount);  // trailing bytes, if any, are ignored
  }

  t_ = channel("t");
  if (t_.valid()) checkTimeChannel();
}

std::string nonFiniteWarning(std::size_t count) {
  if (count == 0) return "";
  return std::to_string(count) + (count == 1 ? " sample" : " samples") + " with non-finite x/y/z " +
         (count == 1 ? "is" : "are") + " kept out of geometry";
}

std::size_t BiipReader::nonFiniteSampleCount() const {
  std::call_once(nonFiniteCounted_, [this] {
    const BiipChannelView x = channel("x"), y = channel("y"), z = channel("z");
    std::size_t bad = 0;
    for (std::size_t begin = 0; begin < records_; begin += kScanRecords) {
      const std::size_t end = std::min(records_, begin + kScanRecords);
      bad += countNonFinite(x, y, z, begin, end);
      releaseRecords(begin, end);
    }
    checkIntact();
    nonFinite_ = bad;
    warnings_ = headerWarnings_;
    if (bad > 0) warnings_.push_back(nonFiniteWarning(bad));
  });
  return nonFinite_;
}

const std::vector<std::string>& BiipReader::warnings() const {
  nonFiniteSampleCount();
  return warnings_;
}

// Every duration, speed and derivative is taken over the time channel: one that is not a clock
// (NaN, standing still, running backwards) would give a duration of 0 or infinite speeds.
void BiipReader::checkTimeChannel() const {
  double previous = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < records_; ++i) {
    const double t = t_[i];
    if (!std::isfinite(t)) refuse("record " + std::to_string(i) + ": time t is not finite");
    if (t < previous)
      refuse(fmt::format("record {}: time t runs backwards ({:.9g} s after {:.9g} s)", i, t, previous));
    previous = t;
    if ((i + 1) % kScanRecords == 0) releaseRecords(i + 1 - kScanRecords, i + 1);
  }
  if (records_ > 1 && !(t_[records_ - 1] > t_[0]))
    refuse(fmt::format("time t stands still ({:.9g} s in all {} records)", t_[0], records_));
}

const BiipChannel* BiipReader::findChannel(const std::string& name) const {
  for (const auto& c : header_.channels)
    if (c.name == name) return &c;
  return nullptr;
}

bool BiipReader::hasChannel(const std::string& name) const { return findChannel(name) != nullptr; }

BiipChannelView BiipReader::channel(const std::string& name) const {
  const BiipChannel* c = findChannel(name);
  if (c == nullptr || data_ == nullptr) return {};
  return BiipChannelView(data_ + header_.headerBytes + c->offset, header_.recordBytes, c->type, records_);
}

bool BiipReader::copyChannel(const std::string& name, double* out, std::size_t begin, std::size_t count) const {
  const BiipChannelView view = channel(name);
  if (!view.valid()) return false;
  view.copyTo(out, begin, count);
  return true;
}

double BiipReader::timeAt(std::size_t i) const {
  if (t_.valid()) return t_[i];
  return header_.t0Seconds + static_cast<double>(i) * header_.cycleSeconds;
}

}  // namespace isurface
