// BiipWriter: layout, round trips through BiipReader, atomic output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "isurface/io/biip.h"
#include "isurface/base/diagnostic.h"
#include "test_support.h"

namespace isurface {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::scratchDir;

template <class T>
T get(const std::string& s, std::size_t at) {
  T v;
  std::memcpy(&v, s.data() + at, sizeof v);
  return v;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = scratchDir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const std::vector<std::pair<std::string, BiipType>> kExample = {
    {"line", BiipType::U32}, {"x", BiipType::F64},    {"y", BiipType::F64},   {"z", BiipType::F64},
    {"fb_x", BiipType::F64}, {"fb_y", BiipType::F64}, {"fb_z", BiipType::F64}};

TEST(biipWriter, LayoutOfTheFormatExample) {
  const auto channels = BiipWriter::layout(kExample);
  ASSERT_EQ(channels.size(), 7u);
  const std::uint32_t offsets[] = {0, 8, 16, 24, 32, 40, 48};
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(channels[i].name, kExample[i].first);
    EXPECT_EQ(channels[i].type, kExample[i].second);
    EXPECT_EQ(channels[i].offset, offsets[i]);
  }
  EXPECT_EQ(BiipWriter::recordBytesFor(channels), 56u);

  const std::string path = (scratchDir() / "example.biip").string();
  const std::string metadata = R"({"units":"mm"})";  // 14 bytes: 64 + 224 + 14 = 302 -> 304
  BiipWriter w(path, channels, 0.001, metadata);
  EXPECT_EQ(w.recordBytes(), 56u);
  w.commit();
  const std::string bytes = readFile(path);
  ASSERT_EQ(bytes.size(), 304u);
  EXPECT_EQ(get<std::uint32_t>(bytes, 8), 304u);
  EXPECT_EQ(get<std::uint32_t>(bytes, 16), 56u);
  EXPECT_EQ(get<std::uint32_t>(bytes, 48), 14u);
  EXPECT_EQ(bytes.substr(302), std::string(2, '\0'));
}

TEST(biipWriter, LayoutAlignsEachChannelToItsSize) {
  const auto channels = BiipWriter::layout({{"a", BiipType::U32},
                                            {"x", BiipType::F64},
                                            {"b", BiipType::F32},
                                            {"y", BiipType::I64},
                                            {"c", BiipType::I32},
                                            {"d", BiipType::F32},
                                            {"z", BiipType::U64},
                                            {"e", BiipType::F32}});
  const std::uint32_t offsets[] = {0, 8, 16, 24, 32, 36, 40, 48};
  for (std::size_t i = 0; i < channels.size(); ++i) {
    EXPECT_EQ(channels[i].offset, offsets[i]) << channels[i].name;
    EXPECT_EQ(channels[i].offset % biipTypeSize(channels[i].type), 0u);
  }
  EXPECT_EQ(BiipWriter::recordBytesFor(channels), 56u);  // 52 rounded up to 8
  EXPECT_EQ(BiipWriter::recordBytesFor(BiipWriter::layout({{"a", BiipType::F32}})), 8u);
}

TEST(biipWriter, RoundTripsAllSixTypes) {
  const auto channels = BiipWriter::layout({{"line", BiipType::U32},
                                            {"x", BiipType::F64},
                                            {"y", BiipType::F64},
                                            {"z", BiipType::F64},
                                            {"cur_x", BiipType::F32},
                                            {"gain", BiipType::I32},
                                            {"ticks", BiipType::I64},
                                            {"serial", BiipType::U64}});
  const std::string path = (scratchDir() / "all_types.biip").string();
  const std::string metadata = R"({"source":"part.nc","units":"mm","writer":"test 1"})";
  const std::size_t n = 50000;  // 3.2 MB: several buffer flushes
  {
    BiipWriter w(path, channels, 0.0005, metadata, 3.25);
    std::vector<unsigned char> rec(w.recordBytes());
    for (std::size_t i = 0; i < n; ++i) {
      std::fill(rec.begin(), rec.end(), 0);
      biipStore(rec.data(), channels[0], double(i % 1000 + 1));
      biipStore(rec.data(), channels[1], std::sin(i * 1e-3) * 100.0);
      biipStore(rec.data(), channels[2], i * 0.001);
      biipStore(rec.data(), channels[3], -1.0 / (i + 1));
      biipStore(rec.data(), channels[4], 0.5 * i);
      biipStore(rec.data(), channels[5], -double(i));
      biipStore(rec.data(), channels[6], -1e12 - double(i));
      biipStore(rec.data(), channels[7], 4e15 + double(i));
      w.append(rec.data());
    }
    EXPECT_EQ(w.recordCount(), n);
    w.commit();
  }
  const BiipReader r(path);
  EXPECT_TRUE(r.warnings().empty());
  EXPECT_EQ(r.recordCount(), n);
  EXPECT_EQ(r.header().recordCount, n);
  EXPECT_EQ(r.header().versionMajor, 1);
  EXPECT_EQ(r.header().versionMinor, 0);
  EXPECT_EQ(r.header().headerBytes % 8, 0u);
  EXPECT_DOUBLE_EQ(r.header().cycleSeconds, 0.0005);
  EXPECT_DOUBLE_EQ(r.header().t0Seconds, 3.25);
  EXPECT_EQ(r.header().metadataJson, metadata);
  ASSERT_EQ(r.header().channels.size(), channels.size());
  for (std::size_t c = 0; c < channels.size(); ++c) {
    EXPECT_EQ(r.header().channels[c].name, channels[c].name);
    EXPECT_EQ(r.header().channels[c].type, channels[c].type);
    EXPECT_EQ(r.header().channels[c].offset, channels[c].offset);
  }
  const auto line = r.channel("line"), x = r.channel("x"), y = r.channel("y"), z = r.channel("z");
  const auto cur = r.channel("cur_x"), gain = r.channel("gain"), ticks = r.channel("ticks");
  const auto serial = r.channel("serial");
  for (std::size_t i = 0; i < n; i += 7) {
    ASSERT_EQ(line.integer(i), i % 1000 + 1);
    ASSERT_EQ(x[i], std::sin(i * 1e-3) * 100.0);
    ASSERT_EQ(y[i], i * 0.001);
    ASSERT_EQ(z[i], -1.0 / (i + 1));
    ASSERT_EQ(cur[i], double(float(0.5 * i)));
    ASSERT_EQ(gain[i], -double(i));
    ASSERT_EQ(ticks[i], -1e12 - double(i));
    ASSERT_EQ(serial.integer(i), 4000000000000000ull + i);
  }
  EXPECT_DOUBLE_EQ(r.timeAt(n - 1), 3.25 + (n - 1) * 0.0005);
  std::vector<double> ys(10);
  r.copyChannel("y", ys.data(), n - 5, 10);  // clipped to the 5 that exist
  EXPECT_EQ(ys[4], (n - 1) * 0.001);
}

TEST(biipWriter, StoreRoundsAndClampsIntegers) {
  unsigned char rec[8] = {};
  const BiipChannel u32{"a", BiipType::U32, 0}, i32{"b", BiipType::I32, 0}, u64{"c", BiipType::U64, 0};
  const BiipChannelView v32(rec, 8, BiipType::U32, 1), vi32(rec, 8, BiipType::I32, 1), v64(rec, 8, BiipType::U64, 1);
  biipStore(rec, u32, 41.6);
  EXPECT_EQ(v32.integer(0), 42u);
  biipStore(rec, u32, -5);
  EXPECT_EQ(v32.integer(0), 0u);
  biipStore(rec, u32, 1e12);
  EXPECT_EQ(v32.integer(0), 0xffffffffu);
  biipStore(rec, i32, -1e12);
  EXPECT_EQ(vi32[0], double(std::numeric_limits<std::int32_t>::min()));
  biipStore(rec, u64, 1e30);
  EXPECT_EQ(v64.integer(0), std::numeric_limits<std::uint64_t>::max());
  biipStore(rec, u64, std::nan(""));
  EXPECT_EQ(v64.integer(0), 0u);
}

TEST(biipWriter, AppendRecordsWritesManyAtOnce) {
  const auto channels = BiipWriter::layout({{"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}});
  const std::string path = (scratchDir() / "bulk.biip").string();
  std::vector<double> block(3 * 100000);
  for (std::size_t i = 0; i < block.size(); ++i) block[i] = double(i);
  {
    BiipWriter w(path, channels, 0.001, "");
    w.appendRecords(block.data(), 100000);  // larger than the buffer: written straight through
    w.append(block.data());
    w.commit();
  }
  const BiipReader r(path);
  ASSERT_EQ(r.recordCount(), 100001u);
  EXPECT_EQ(r.channel("z")[99999], 299999.0);
  EXPECT_EQ(r.channel("y")[100000], 1.0);
  EXPECT_EQ(r.header().metadataJson, "");
}

TEST(biipWriter, EmptyCommittedFileIsValid) {
  const std::string path = (scratchDir() / "empty_commit.biip").string();
  {
    BiipWriter w(path, BiipWriter::layout(kExample), 0.001, "{}");
    w.commit();
  }
  const BiipReader r(path);
  EXPECT_EQ(r.recordCount(), 0u);
  EXPECT_EQ(r.header().metadataJson, "{}");
}

TEST(biipWriter, UncommittedWriterLeavesNoFile) {
  const fs::path dir = freshDir("uncommitted");
  const std::string path = (dir / "out.biip").string();
  {
    BiipWriter w(path, BiipWriter::layout(kExample), 0.001, "");
    std::vector<unsigned char> rec(56, 0);
    for (int i = 0; i < 100000; ++i) w.append(rec.data());
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(filesIn(dir).empty());
}

TEST(biipWriter, UncommittedWriterKeepsAnExistingFile) {
  const fs::path dir = freshDir("keep_existing");
  const std::string path = (dir / "out.biip").string();
  { std::ofstream(path) << "previous"; }
  {
    BiipWriter w(path, BiipWriter::layout(kExample), 0.001, "");
    std::vector<unsigned char> rec(56, 0);
    w.append(rec.data());
  }
  EXPECT_EQ(readFile(path), "previous");
  EXPECT_EQ(filesIn(dir).size(), 1u);
}

TEST(biipWriter, InterruptedWriterLeavesAReadableTemporaryFile) {
  // Before commit the header says record_count 0: a copy of the temporary file taken while
  // the writer runs (as after a crash) is a valid Biip file whose count comes from its size.
  const fs::path dir = freshDir("interrupted");
  const std::string path = (dir / "out.biip").string();
  BiipWriter w(path, BiipWriter::layout(kExample), 0.001, "");
  std::vector<unsigned char> rec(56, 0);
  for (int i = 0; i < 40000; ++i) {  // 2.2 MB: the buffer has been flushed at least once
    std::memcpy(rec.data() + 8, &i, sizeof i);
    w.append(rec.data());
  }
  const auto names = filesIn(dir);
  ASSERT_EQ(names.size(), 1u);
  EXPECT_EQ(names[0].rfind("out.biip.tmp", 0), 0u) << names[0];
  const fs::path copy = scratchDir() / "interrupted_copy.biip";
  fs::copy_file(dir / names[0], copy, fs::copy_options::overwrite_existing);
  const BiipReader r(copy.string());
  EXPECT_EQ(r.header().recordCount, 0u);
  EXPECT_GT(r.recordCount(), 10000u);
  EXPECT_LT(r.recordCount(), 40000u);
}

TEST(biipWriter, MissingFolderFailsCleanly) {
  const std::string path = (scratchDir() / "no_such_folder" / "out.biip").string();
  try {
    BiipWriter w(path, BiipWriter::layout(kExample), 0.001, "");
    FAIL() << "created";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().file, path);
    EXPECT_NE(std::string(e.what()).find(path + ": cannot write: No such file or directory"), std::string::npos)
        << e.what();
  }
}

TEST(biipWriter, FullDeviceFailsCleanly) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    BiipWriter w("/dev/full", BiipWriter::layout(kExample), 0.001, "");
    std::vector<unsigned char> rec(56, 0);
    for (int i = 0; i < 1000; ++i) w.append(rec.data());
    w.commit();
    FAIL() << "committed to /dev/full";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().file, "/dev/full");
    EXPECT_NE(std::string(e.what()).find("cannot write: "), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST(biipWriter, RefusesChannelsThatBreakTheFormat) {
  const std::string path = (scratchDir() / "never.biip").string();
  const auto make = [&](std::vector<std::pair<std::string, BiipType>> spec, double cycle = 0.001,
                        std::string metadata = "") {
    BiipWriter w(path, BiipWriter::layout(spec), cycle, metadata);
  };
  const std::pair<std::string, BiipType> x{"x", BiipType::F64}, y{"y", BiipType::F64}, z{"z", BiipType::F64};
  EXPECT_THROW(make({x, y}), std::invalid_argument);
  EXPECT_THROW(make({x, y, z, x}), std::invalid_argument);
  EXPECT_THROW(make({x, y, z, {"Feed", BiipType::F64}}), std::invalid_argument);
  EXPECT_THROW(make({x, y, z, {"a_name_longer_than_24_chars", BiipType::F64}}), std::invalid_argument);
  EXPECT_THROW(make({x, y, z}, 0.0), std::invalid_argument);
  EXPECT_THROW(make({x, y, z}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(make({x, y, z}, 0.001, "[1]"), std::invalid_argument);
  EXPECT_THROW(make({x, y, z}, 0.001, "{"), std::invalid_argument);
  std::vector<std::pair<std::string, BiipType>> wide = {x, y, z};
  for (int i = 0; i < 600; ++i) wide.push_back({"c" + std::to_string(i), BiipType::F64});
  EXPECT_THROW(make(wide), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path));
}

}  // namespace
}  // namespace isurface
