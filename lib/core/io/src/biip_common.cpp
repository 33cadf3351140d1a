// Biip pieces shared by the reader and the writer: types, names, value conversion.
#include <cmath>
#include <cstring>
#include <limits>

#include "isurface/io/biip.h"

#include <fmt/format.h>

#include "isurface/base/diagnostic.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "Biip files are little-endian and are read in place: a little-endian host is required");

namespace isurface {

std::size_t biipTypeSize(BiipType type) {
  switch (type) {
    case BiipType::F64:
    case BiipType::I64:
    case BiipType::U64: return 8;
    case BiipType::F32:
    case BiipType::I32:
    case BiipType::U32: return 4;
  }
  return 0;
}

const char* biipTypeName(BiipType type) {
  switch (type) {
    case BiipType::F64: return "f64";
    case BiipType::F32: return "f32";
    case BiipType::I32: return "i32";
    case BiipType::U32: return "u32";
    case BiipType::I64: return "i64";
    case BiipType::U64: return "u64";
  }
  return "?";
}

bool biipTypeKnown(std::uint8_t code) { return code >= 1 && code <= 6; }

bool biipValidChannelName(std::string_view name) {
  if (name.empty() || name.size() > kBiipMaxNameLength) return false;
  for (const char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

namespace {

template <class Int>
Int roundClamped(double value) {
  if (std::isnan(value)) return 0;
  const double r = std::nearbyint(value);
  // Compare in double: the bounds of 64-bit types round up to 2^63 / 2^64, hence ">=".
  if (r <= static_cast<double>(std::numeric_limits<Int>::min())) return std::numeric_limits<Int>::min();
  if (r >= static_cast<double>(std::numeric_limits<Int>::max())) return std::numeric_limits<Int>::max();
  return static_cast<Int>(r);
}

template <class T>
void put(unsigned char* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

}  // namespace

void biipStore(void* record, const BiipChannel& channel, double value) {
  unsigned char* p = static_cast<unsigned char*>(record) + channel.offset;
  switch (channel.type) {
    case BiipType::F64: put(p, value); break;
    case BiipType::F32: put(p, static_cast<float>(value)); break;
    case BiipType::I32: put(p, roundClamped<std::int32_t>(value)); break;
    case BiipType::U32: put(p, roundClamped<std::uint32_t>(value)); break;
    case BiipType::I64: put(p, roundClamped<std::int64_t>(value)); break;
    case BiipType::U64: put(p, roundClamped<std::uint64_t>(value)); break;
  }
}

std::uint64_t BiipChannelView::integer(std::size_t i) const {
  const unsigned char* p = first_ + i * stride_;
  switch (type_) {
    case BiipType::U32: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
    case BiipType::U64: { std::uint64_t v; std::memcpy(&v, p, 8); return v; }
    case BiipType::I32: { std::int32_t v; std::memcpy(&v, p, 4); return v < 0 ? 0 : std::uint64_t(v); }
    case BiipType::I64: { std::int64_t v; std::memcpy(&v, p, 8); return v < 0 ? 0 : std::uint64_t(v); }
    case BiipType::F64:
    case BiipType::F32: {
      const double v = convert(p, type_);
      if (!(v > 0)) return 0;
      if (v >= 18446744073709551616.0) return std::numeric_limits<std::uint64_t>::max();
      return static_cast<std::uint64_t>(v);
    }
  }
  return 0;
}

std::optional<std::uint32_t> BiipChannelView::wholeNumber(std::size_t i) const {
  const unsigned char* p = first_ + i * stride_;
  constexpr std::uint64_t kLargest = std::numeric_limits<std::uint32_t>::max();
  switch (type_) {
    case BiipType::U32: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
    case BiipType::U64: { std::uint64_t v; std::memcpy(&v, p, 8); if (v > kLargest) return std::nullopt; return std::uint32_t(v); }
    case BiipType::I32: { std::int32_t v; std::memcpy(&v, p, 4); if (v < 0) return std::nullopt; return std::uint32_t(v); }
    case BiipType::I64: {
      std::int64_t v;
      std::memcpy(&v, p, 8);
      if (v < 0 || std::uint64_t(v) > kLargest) return std::nullopt;
      return std::uint32_t(v);
    }
    case BiipType::F64:
    case BiipType::F32: {
      const double v = convert(p, type_);
      if (!(v >= 0 && v <= double(kLargest) && v == std::floor(v))) return std::nullopt;
      return std::uint32_t(v);
    }
  }
  return std::nullopt;
}

void requireTimeAdvances(double before, double now, std::size_t record, const std::string& path) {
  if (!std::isfinite(now))
    throw InputError(Diagnostic{path, 0, 0, fmt::format("channel 't', record {}: time {} is not finite", record, now)});
  if (!(now > before))
    throw InputError(Diagnostic{path, 0, 0,
                                fmt::format("channel 't', record {}: time {:.9g} s {} (the record before: {:.9g} s)", record,
                                            now, now < before ? "runs backwards" : "does not advance", before)});
}

std::uint32_t countAt(const BiipChannelView& view, std::size_t i, const std::string& path, const char* channel) {
  if (const std::optional<std::uint32_t> v = view.wholeNumber(i)) return *v;
  throw InputError(Diagnostic{path, 0, 0,
                              fmt::format("channel '{}', record {}: {:.17g} is not a whole number from 0 to 4294967295",
                                          channel, i, view[i])});
}

namespace {
template <class T, class Out>
void copyAs(const unsigned char* p, std::size_t stride, Out* out, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i, p += stride) {
    T v;
    std::memcpy(&v, p, sizeof v);
    out[i] = static_cast<Out>(v);
  }
}

template <class Out>
void copyChannel(const unsigned char* p, std::size_t stride, BiipType type, Out* out, std::size_t count) {
  switch (type) {
    case BiipType::F64: copyAs<double>(p, stride, out, count); break;
    case BiipType::F32: copyAs<float>(p, stride, out, count); break;
    case BiipType::I32: copyAs<std::int32_t>(p, stride, out, count); break;
    case BiipType::U32: copyAs<std::uint32_t>(p, stride, out, count); break;
    case BiipType::I64: copyAs<std::int64_t>(p, stride, out, count); break;
    case BiipType::U64: copyAs<std::uint64_t>(p, stride, out, count); break;
  }
}
}  // namespace

void BiipChannelView::copyTo(double* out, std::size_t begin, std::size_t count) const {
  if (!valid() || begin >= count_) return;
  if (count > count_ - begin) count = count_ - begin;
  copyChannel(first_ + begin * stride_, stride_, type_, out, count);
}

void BiipChannelView::copyTo(float* out, std::size_t begin, std::size_t count) const {
  if (!valid() || begin >= count_) return;
  if (count > count_ - begin) count = count_ - begin;
  copyChannel(first_ + begin * stride_, stride_, type_, out, count);
}

}  // namespace isurface
