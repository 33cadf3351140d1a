// Biip writer: header first (record_count 0), buffered records, the real count on commit.
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <unordered_set>

#include "isurface/io/atomic_file.h"
#include "isurface/io/biip.h"

namespace isurface {

namespace {

std::uint64_t roundUp8(std::uint64_t n) { return (n + 7) & ~std::uint64_t(7); }

template <class T>
void put(unsigned char* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

void checkChannels(const std::vector<BiipChannel>& channels, std::uint32_t recordBytes) {
  if (channels.empty() || channels.size() > kBiipMaxChannels) {
    throw std::invalid_argument("Biip: " + std::to_string(channels.size()) + " channels (1..256 allowed)");
  }
  if (recordBytes == 0 || recordBytes > kBiipMaxRecordBytes) {
    throw std::invalid_argument("Biip: record of " + std::to_string(recordBytes) + " bytes (1..4096 allowed)");
  }
  std::unordered_set<std::string> names;
  for (const auto& c : channels) {
    if (!biipValidChannelName(c.name)) {
      throw std::invalid_argument("Biip: channel name '" + c.name + "' is not 1..24 characters of [a-z0-9_]");
    }
    if (!biipTypeKnown(static_cast<std::uint8_t>(c.type))) {
      throw std::invalid_argument("Biip: channel '" + c.name + "' has an unknown type");
    }
    if (!names.insert(c.name).second) throw std::invalid_argument("Biip: two channels are named '" + c.name + "'");
  }
  for (const char* required : {"x", "y", "z"}) {
    if (names.count(required) == 0) throw std::invalid_argument(std::string("Biip: no '") + required + "' channel");
  }
}

}  // namespace

struct BiipWriter::Impl {
  Impl(const std::string& path) : out(path) {}
  AtomicOutputFile out;
  std::vector<BiipChannel> channels;
};

std::vector<BiipChannel> BiipWriter::layout(const std::vector<std::pair<std::string, BiipType>>& namesAndTypes) {
  std::vector<BiipChannel> channels;
  channels.reserve(namesAndTypes.size());
  std::uint32_t offset = 0;
  for (const auto& [name, type] : namesAndTypes) {
    const std::uint32_t size = static_cast<std::uint32_t>(biipTypeSize(type));
    if (size == 0) throw std::invalid_argument("Biip: channel '" + name + "' has an unknown type");
    offset = (offset + size - 1) / size * size;
    channels.push_back({name, type, offset});
    offset += size;
  }
  return channels;
}

std::uint32_t BiipWriter::recordBytesFor(const std::vector<BiipChannel>& channels) {
  std::uint64_t end = 0;
  for (const auto& c : channels) end = std::max<std::uint64_t>(end, std::uint64_t(c.offset) + biipTypeSize(c.type));
  end = roundUp8(end);
  return end > 0xffffffffu ? 0xffffffffu : static_cast<std::uint32_t>(end);
}

BiipWriter::BiipWriter(const std::string& path, std::vector<BiipChannel> channels, double cycleSeconds,
                       std::string metadataJson, double t0Seconds) {
  recordBytes_ = recordBytesFor(channels);
  checkChannels(channels, recordBytes_);
  if (!std::isfinite(cycleSeconds) || cycleSeconds <= 0) {
    throw std::invalid_argument("Biip: cycle " + std::to_string(cycleSeconds) + " s is not finite and > 0");
  }
  if (!std::isfinite(t0Seconds)) throw std::invalid_argument("Biip: t0 is not finite");
  if (!metadataJson.empty()) {
    const auto parsed = nlohmann::json::parse(metadataJson, nullptr, false);
    if (parsed.is_discarded() || !parsed.is_object()) {
      throw std::invalid_argument("Biip: metadata is not a JSON object");
    }
  }
  if (metadataJson.size() > 0xffffffffu - 64 - 32 * kBiipMaxChannels - 8) {
    throw std::invalid_argument("Biip: metadata too large");
  }
  const auto metadataBytes = static_cast<std::uint32_t>(metadataJson.size());
  const std::uint64_t tableEnd = kBiipFixedHeaderBytes + std::uint64_t(kBiipChannelEntryBytes) * channels.size();
  const std::uint64_t headerBytes = roundUp8(tableEnd + metadataBytes);

  std::vector<unsigned char> header(static_cast<std::size_t>(headerBytes), 0);
  unsigned char* h = header.data();
  std::memcpy(h, "BIIP", 4);
  put<std::uint16_t>(h + 4, kBiipVersionMajor);
  put<std::uint16_t>(h + 6, kBiipVersionMinor);
  put<std::uint32_t>(h + 8, static_cast<std::uint32_t>(headerBytes));
  put<std::uint32_t>(h + 12, static_cast<std::uint32_t>(channels.size()));
  put<std::uint32_t>(h + 16, recordBytes_);
  put<std::uint32_t>(h + 20, 0);
  put<double>(h + 24, cycleSeconds);
  put<std::uint64_t>(h + 32, 0);  // record_count: written by commit()
  put<double>(h + 40, t0Seconds);
  put<std::uint32_t>(h + 48, metadataBytes);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    unsigned char* e = h + kBiipFixedHeaderBytes + kBiipChannelEntryBytes * c;
    std::memcpy(e, channels[c].name.data(), channels[c].name.size());
    e[24] = static_cast<unsigned char>(channels[c].type);
    put<std::uint32_t>(e + 28, channels[c].offset);
  }
  if (metadataBytes > 0) std::memcpy(h + tableEnd, metadataJson.data(), metadataBytes);

  impl_ = std::make_unique<Impl>(path);
  impl_->channels = std::move(channels);
  impl_->out.write(header.data(), header.size());
}

BiipWriter::~BiipWriter() = default;  // an uncommitted AtomicOutputFile removes its temporary

const std::vector<BiipChannel>& BiipWriter::channels() const { return impl_->channels; }

std::uint32_t BiipWriter::offsetOf(const std::string& name) const {
  for (const auto& c : impl_->channels)
    if (c.name == name) return c.offset;
  throw std::out_of_range("Biip: no channel '" + name + "'");
}

void BiipWriter::append(const void* record) {
  impl_->out.write(record, recordBytes_);
  ++count_;
}

void BiipWriter::appendRecords(const void* records, std::size_t count) {
  impl_->out.write(records, std::size_t(recordBytes_) * count);
  count_ += count;
}

void BiipWriter::commit() {
  if (impl_->out.committed()) return;
  // A pipe cannot seek back: its count stays 0, which readers resolve from the size.
  if (count_ > 0 && impl_->out.seekable()) {
    unsigned char count[8];
    put<std::uint64_t>(count, count_);
    impl_->out.writeAt(32, count, sizeof count);
  }
  impl_->out.commit();
}

}  // namespace isurface
