// BiipReader against files assembled byte by byte, as another program would write them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "isurface/io/biip.h"
#include "isurface/base/diagnostic.h"
#include "test_support.h"

namespace isurface {
namespace {

using test::scratchDir;

template <class T>
void put(std::string& s, std::size_t at, T v) {
  std::memcpy(&s[at], &v, sizeof v);
}

// A Biip header written field by field, independently of BiipWriter.
struct RawBiip {
  struct Channel {
    std::string name;  // written as is (up to 24 bytes)
    std::uint8_t type;
    std::uint32_t offset;
  };
  std::string magic = "BIIP";
  std::uint16_t major = 1, minor = 0;
  std::uint32_t recordBytes = 24;
  std::uint32_t flags = 0;
  double cycle = 0.001;
  std::uint64_t count = 0;
  double t0 = 0;
  std::vector<Channel> channels = {{"x", 1, 0}, {"y", 1, 8}, {"z", 1, 16}};
  std::string metadata;
  std::optional<std::uint32_t> headerBytes, channelCount;

  std::size_t computedHeaderBytes() const { return (64 + 32 * channels.size() + metadata.size() + 7) / 8 * 8; }

  std::string header() const {
    std::string s(computedHeaderBytes(), '\0');
    std::memcpy(&s[0], magic.data(), 4);
    put(s, 4, major);
    put(s, 6, minor);
    put(s, 8, headerBytes.value_or(static_cast<std::uint32_t>(s.size())));
    put(s, 12, channelCount.value_or(static_cast<std::uint32_t>(channels.size())));
    put(s, 16, recordBytes);
    put(s, 20, flags);
    put(s, 24, cycle);
    put(s, 32, count);
    put(s, 40, t0);
    put(s, 48, static_cast<std::uint32_t>(metadata.size()));
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const std::size_t e = 64 + 32 * c;
      std::memcpy(&s[e], channels[c].name.data(), std::min<std::size_t>(channels[c].name.size(), 24));
      s[e + 24] = static_cast<char>(channels[c].type);
      put(s, e + 28, channels[c].offset);
    }
    if (!metadata.empty()) std::memcpy(&s[64 + 32 * channels.size()], metadata.data(), metadata.size());
    return s;
  }
};

// n records of the default layout: x = i, y = 2i, z = -i.
std::string xyzRecords(std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    std::string rec(24, '\0');
    put(rec, 0, double(i));
    put(rec, 8, double(i) * 2);
    put(rec, 16, -double(i));
    out += rec;
  }
  return out;
}

std::string writeBytes(const std::string& name, const std::string& bytes) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

TEST(biipReader, LoadsAFileAnotherProgramWrote) {
  // Channels in an unusual order, packed without alignment, f32 positions, a t channel,
  // metadata with unknown keys, minor version 3, unknown flag bits, padding in the record.
  RawBiip raw;
  raw.minor = 3;
  raw.flags = 0xdead0000u;
  raw.cycle = 0.002;
  raw.t0 = 12.5;
  raw.channels = {{"t", 1, 1},       {"z", 2, 9},        {"my_gauge_7", 5, 13}, {"y", 2, 21},
                  {"x", 2, 25},      {"line", 4, 29},    {"cur_x", 2, 33},      {"u_count", 6, 37},
                  {"tool", 3, 45}};
  raw.recordBytes = 52;  // byte 0 and bytes 49..51 unused
  raw.metadata = R"({"source":"part.nc","units":"mm","vendor_extension":{"a":[1,2,3]},"zz":null})";
  raw.count = 3;
  std::string bytes = raw.header();
  for (int i = 0; i < 3; ++i) {
    std::string rec(52, '\x7f');
    put(rec, 1, 12.5 + 0.002 * i * i);  // irregular times
    put(rec, 9, float(-1.5f * i));
    put(rec, 13, std::int64_t(-5'000'000'000LL + i));
    put(rec, 21, float(0.25f * i));
    put(rec, 25, float(10.0f + i));
    put(rec, 29, std::uint32_t(100 + i));
    put(rec, 33, float(0.5f));
    put(rec, 37, std::uint64_t(1) << 60);
    put(rec, 45, std::int32_t(-7));
    bytes += rec;
  }
  const std::string path = writeBytes("foreign.biip", bytes);
  const BiipReader r(path);
  EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
  EXPECT_EQ(r.header().versionMinor, 3);
  EXPECT_EQ(r.header().flags, 0xdead0000u);
  EXPECT_EQ(r.recordCount(), 3u);
  EXPECT_EQ(r.header().channels.size(), 9u);
  EXPECT_EQ(r.header().channels[2].name, "my_gauge_7");
  EXPECT_EQ(r.header().metadataJson, raw.metadata);
  const auto x = r.channel("x"), y = r.channel("y"), z = r.channel("z");
  ASSERT_TRUE(x.valid());
  EXPECT_EQ(x.type(), BiipType::F32);
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(x[i], 10.0 + i);
    EXPECT_DOUBLE_EQ(y[i], 0.25 * i);
    EXPECT_DOUBLE_EQ(z[i], -1.5 * i);
    EXPECT_DOUBLE_EQ(r.timeAt(i), 12.5 + 0.002 * i * i);
    EXPECT_DOUBLE_EQ(r.channel("my_gauge_7")[i], -5'000'000'000.0 + i);
    EXPECT_EQ(r.channel("line").wholeNumber(i), std::optional<std::uint32_t>(100u + i));
    EXPECT_DOUBLE_EQ(r.channel("u_count")[i], double(std::uint64_t(1) << 60));
    EXPECT_FALSE(r.channel("u_count").wholeNumber(i).has_value());  // beyond 32 bits: no line number
    EXPECT_DOUBLE_EQ(r.channel("tool")[i], -7.0);
    EXPECT_FLOAT_EQ(float(r.channel("cur_x")[i]), 0.5f);
  }
  std::vector<double> copy(3);
  ASSERT_TRUE(r.copyChannel("x", copy.data(), 0, 3));
  EXPECT_EQ(copy, (std::vector<double>{10, 11, 12}));
  EXPECT_FALSE(r.copyChannel("nope", copy.data(), 0, 3));
  EXPECT_FALSE(r.channel("nope").valid());
  EXPECT_EQ(r.nonFiniteSampleCount(), 0u);
}

TEST(biipReader, TimeFromCycleWithoutTChannel) {
  RawBiip raw;
  raw.cycle = 0.004;
  raw.t0 = 2;
  const BiipReader r(writeBytes("cycle.biip", raw.header() + xyzRecords(5)));
  EXPECT_EQ(r.recordCount(), 5u);
  EXPECT_DOUBLE_EQ(r.timeAt(0), 2.0);
  EXPECT_DOUBLE_EQ(r.timeAt(4), 2.016);
  EXPECT_DOUBLE_EQ(r.channel("y")[3], 6.0);
}

TEST(biipReader, RecordCountZeroIsDerivedFromTheSize) {
  RawBiip raw;
  raw.count = 0;
  const BiipReader r(writeBytes("count0.biip", raw.header() + xyzRecords(7)));
  EXPECT_EQ(r.recordCount(), 7u);
  EXPECT_TRUE(r.warnings().empty());
}

TEST(biipReader, TruncatedLastRecordIsDroppedWithAWarning) {
  RawBiip raw;
  raw.count = 0;
  std::string bytes = raw.header() + xyzRecords(6);
  bytes.resize(bytes.size() - 10);
  const BiipReader r(writeBytes("cut.biip", bytes));
  EXPECT_EQ(r.recordCount(), 5u);
  ASSERT_EQ(r.warnings().size(), 1u);
  EXPECT_NE(r.warnings()[0].find("cut short"), std::string::npos) << r.warnings()[0];
  EXPECT_DOUBLE_EQ(r.channel("x")[4], 4.0);
}

TEST(biipReader, RecordCountLargerThanTheFileLoadsWhatItHolds) {
  RawBiip raw;
  raw.count = 1000;
  const BiipReader r(writeBytes("short.biip", raw.header() + xyzRecords(4)));
  EXPECT_EQ(r.recordCount(), 4u);
  EXPECT_EQ(r.header().recordCount, 1000u);
  ASSERT_EQ(r.warnings().size(), 1u);
  EXPECT_NE(r.warnings()[0].find("1000"), std::string::npos) << r.warnings()[0];

  std::string cut = raw.header() + xyzRecords(4);
  cut.resize(cut.size() - 3);
  const BiipReader r2(writeBytes("short_cut.biip", cut));
  EXPECT_EQ(r2.recordCount(), 3u);
  EXPECT_EQ(r2.warnings().size(), 2u);
}

TEST(biipReader, TrailingBytesAfterTheCountedRecordsAreIgnored) {
  RawBiip raw;
  raw.count = 2;
  const BiipReader r(writeBytes("trailing.biip", raw.header() + xyzRecords(3) + "junk"));
  EXPECT_EQ(r.recordCount(), 2u);
  EXPECT_TRUE(r.warnings().empty());
}

TEST(biipReader, HeaderOnlyFileHasNoRecords) {
  const BiipReader r(writeBytes("header_only.biip", RawBiip().header()));
  EXPECT_EQ(r.recordCount(), 0u);
  EXPECT_EQ(r.channel("x").size(), 0u);
}

TEST(biipReader, PaddedHeaderIsSkipped) {
  RawBiip raw;
  raw.headerBytes = static_cast<std::uint32_t>(raw.computedHeaderBytes() + 40);
  const BiipReader r(writeBytes("padded.biip", raw.header() + std::string(40, '\0') + xyzRecords(2)));
  EXPECT_EQ(r.recordCount(), 2u);
  EXPECT_DOUBLE_EQ(r.channel("y")[1], 2.0);
}

TEST(biipReader, NonFinitePositionsAreCounted) {
  RawBiip raw;
  std::string records = xyzRecords(10);
  put(records, 24 * 2 + 0, std::numeric_limits<double>::quiet_NaN());
  put(records, 24 * 5 + 8, std::numeric_limits<double>::infinity());
  put(records, 24 * 5 + 16, -std::numeric_limits<double>::infinity());
  put(records, 24 * 9 + 16, std::numeric_limits<double>::quiet_NaN());
  const BiipReader r(writeBytes("nonfinite.biip", raw.header() + records));
  EXPECT_EQ(r.recordCount(), 10u);
  EXPECT_EQ(r.nonFiniteSampleCount(), 3u);
  ASSERT_EQ(r.warnings().size(), 1u);
  EXPECT_EQ(r.warnings()[0], "3 samples with non-finite x/y/z are kept out of geometry");
}

TEST(biipReader, BadMetadataIsIgnoredWithAWarning) {
  for (const std::string& metadata : {std::string("{\"source\": "), std::string("[1, 2]"),
                                      std::string("{\"source\": \"\xff\xfe.nc\"}")}) {
    RawBiip raw;
    raw.metadata = metadata;
    const BiipReader r(writeBytes("badmeta.biip", raw.header() + xyzRecords(2)));
    EXPECT_EQ(r.recordCount(), 2u);
    EXPECT_EQ(r.header().metadataJson, "");
    ASSERT_EQ(r.warnings().size(), 1u) << metadata;
    EXPECT_NE(r.warnings()[0].find("metadata"), std::string::npos);
  }
}

TEST(biipReader, MetadataWithTrailingNulsIsAccepted) {
  RawBiip raw;
  raw.metadata = std::string("{\"units\":\"mm\"}") + std::string(5, '\0');
  const BiipReader r(writeBytes("nulmeta.biip", raw.header() + xyzRecords(1)));
  EXPECT_TRUE(r.warnings().empty());
  EXPECT_EQ(r.header().metadataJson, "{\"units\":\"mm\"}");
}

// Every refusal: InputError whose message names the file and the problem.
struct Refusal {
  std::string name;
  std::function<std::string()> bytes;
  std::string problem;
};

std::string withHeader(const std::function<void(RawBiip&)>& edit, std::size_t records = 2) {
  RawBiip raw;
  edit(raw);
  return raw.header() + xyzRecords(records);
}

TEST(biipReader, RefusesDamagedFilesNamingFileAndProblem) {
  const std::vector<Refusal> cases = {
      {"empty", [] { return std::string(); }, "empty"},
      {"tiny", [] { return std::string("BI"); }, "too short"},
      {"short_header", [] { return RawBiip().header().substr(0, 40); }, "too short"},
      {"magic", [] { return withHeader([](RawBiip& r) { r.magic = "BIIQ"; }); }, "magic"},
      {"text", [] { return std::string(200, 'a'); }, "magic"},
      {"major2", [] { return withHeader([](RawBiip& r) { r.major = 2; }); }, "major version 2"},
      {"major0", [] { return withHeader([](RawBiip& r) { r.major = 0; }); }, "major version 0"},
      {"channels0", [] { return withHeader([](RawBiip& r) { r.channelCount = 0; }); }, "channel_count 0"},
      {"channels257", [] { return withHeader([](RawBiip& r) { r.channelCount = 257; }); }, "channel_count 257"},
      {"record0", [] { return withHeader([](RawBiip& r) { r.recordBytes = 0; }); }, "record_bytes 0"},
      {"record4097", [] { return withHeader([](RawBiip& r) { r.recordBytes = 4097; }); }, "record_bytes 4097"},
      {"outside", [] { return withHeader([](RawBiip& r) { r.channels[2].offset = 20; }); }, "'z' (f64 at offset 20) lies outside the 24-byte record"},
      {"outside_huge", [] { return withHeader([](RawBiip& r) { r.channels[0].offset = 0xfffffffcu; }); }, "lies outside"},
      {"type0", [] { return withHeader([](RawBiip& r) { r.channels[1].type = 0; }); }, "'y' has unknown type 0"},
      {"type7", [] { return withHeader([](RawBiip& r) { r.channels[1].type = 7; }); }, "unknown type 7"},
      {"upper", [] { return withHeader([](RawBiip& r) { r.channels.push_back({"Feed", 1, 0}); }); }, "'Feed' is not made of [a-z0-9_]"},
      {"space", [] { return withHeader([](RawBiip& r) { r.channels.push_back({"a b", 1, 0}); }); }, "[a-z0-9_]"},
      {"control", [] { return withHeader([](RawBiip& r) { r.channels.push_back({"a\x01", 1, 0}); }); }, "a\\x01"},
      {"empty_name", [] { return withHeader([](RawBiip& r) { r.channels.push_back({"", 1, 0}); }); }, "channel 4 has an empty name"},
      {"duplicate", [] { return withHeader([](RawBiip& r) { r.channels.push_back({"y", 1, 0}); }); }, "two channels are named 'y'"},
      {"past_end", [] { return withHeader([](RawBiip& r) { r.headerBytes = 100000; }); }, "header runs past the end of the file"},
      {"table_past_end", [] { return withHeader([](RawBiip& r) { r.channelCount = 200; r.headerBytes = 64 + 32 * 200; }, 0); }, "past the end"},
      {"header_small", [] { return withHeader([](RawBiip& r) { r.headerBytes = 64; }); }, "header_bytes 64 is smaller than"},
      {"cycle0", [] { return withHeader([](RawBiip& r) { r.cycle = 0; }); }, "cycle_s"},
      {"cycle_neg", [] { return withHeader([](RawBiip& r) { r.cycle = -0.001; }); }, "cycle_s"},
      {"cycle_nan", [] { return withHeader([](RawBiip& r) { r.cycle = std::nan(""); }); }, "cycle_s"},
      {"cycle_inf", [] { return withHeader([](RawBiip& r) { r.cycle = HUGE_VAL; }); }, "cycle_s"},
      {"no_z", [] { return withHeader([](RawBiip& r) { r.channels.pop_back(); }); }, "no 'z' channel"},
      {"no_xyz", [] { return withHeader([](RawBiip& r) { r.channels = {{"line", 4, 0}}; }); }, "no 'x' channel"},
  };
  for (const auto& c : cases) {
    const std::string path = writeBytes("refuse_" + c.name + ".biip", c.bytes());
    try {
      BiipReader r(path);
      ADD_FAILURE() << c.name << ": accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.diagnostic().file, path) << c.name;
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << c.name << ": " << what;
      EXPECT_NE(what.find(c.problem), std::string::npos) << c.name << ": " << what;
    } catch (const std::exception& e) {
      ADD_FAILURE() << c.name << ": unexpected " << e.what();
    }
  }
}

TEST(biipReader, RefusesMissingFilesAndFolders) {
  const std::string missing = (scratchDir() / "no_such.biip").string();
  try {
    BiipReader r(missing);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing + ": cannot read: No such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(BiipReader r(scratchDir().string()), InputError);
}

TEST(biipReader, RandomCorruptionNeverCrashes) {
  RawBiip raw;
  raw.metadata = R"({"units":"mm"})";
  const std::string good = raw.header() + xyzRecords(20);
  unsigned state = 12345;
  const auto next = [&] { return state = state * 1103515245u + 12345u, (state >> 16) & 0x7fff; };
  int accepted = 0, refused = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::string bytes = good;
    const int flips = 1 + int(next() % 4);
    for (int f = 0; f < flips; ++f) bytes[next() % 200] = static_cast<char>(next() & 0xff);
    if (trial % 7 == 0) bytes.resize(next() % bytes.size());
    const std::string path = writeBytes("fuzz.biip", bytes);
    try {
      BiipReader r(path);
      double sum = 0;
      for (const auto& ch : r.header().channels) {
        const auto v = r.channel(ch.name);
        for (std::size_t i = 0; i < v.size(); ++i) sum += v[i];
      }
      (void)sum;
      ++accepted;
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_EQ(accepted + refused, 400);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace isurface
