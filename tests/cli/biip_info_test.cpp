// isurface-cli info on generated and damaged Biip files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "isurface/io/biip.h"
#include "test_support.h"

namespace isurface {
namespace {

using nlohmann::json;
using test::runCli;
using test::scratchDir;

// 1000 samples at 1 ms: 20 mm/s (1200 mm/min) along X from (10, 2, -1); line 0 for the first
// 10 samples, then lines 3..12.
std::string writeLineFile(const std::string& name, std::size_t badSample = std::size_t(-1)) {
  const std::string path = (scratchDir() / name).string();
  const auto channels = BiipWriter::layout({{"line", BiipType::U32},
                                            {"x", BiipType::F64},
                                            {"y", BiipType::F64},
                                            {"z", BiipType::F64},
                                            {"feed", BiipType::F64}});
  BiipWriter w(path, channels, 0.001, R"({"source":"part.nc","units":"mm","extra":[1,2]})", 0.5);
  std::vector<unsigned char> rec(w.recordBytes());
  for (std::size_t i = 0; i < 1000; ++i) {
    biipStore(rec.data(), channels[0], i < 10 ? 0.0 : double(3 + (i - 10) / 99));
    biipStore(rec.data(), channels[1], i == badSample ? std::numeric_limits<double>::quiet_NaN() : 10 + 0.02 * i);
    biipStore(rec.data(), channels[2], 2);
    biipStore(rec.data(), channels[3], -1);
    biipStore(rec.data(), channels[4], 1200);
    w.append(rec.data());
  }
  w.commit();
  return path;
}

TEST(biipInfo, DescribesAGeneratedFile) {
  const std::string path = writeLineFile("info_line.biip");
  const auto r = runCli("info " + path);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const json j = json::parse(r.out);
  // Pretty with 2 spaces, keys in a fixed reading order.
  EXPECT_EQ(r.out, nlohmann::ordered_json::parse(r.out).dump(2) + "\n");
  EXPECT_EQ(r.out.rfind("{\n  \"file\": ", 0), 0u) << r.out.substr(0, 40);
  EXPECT_LT(r.out.find("\"version\""), r.out.find("\"record_count\""));
  EXPECT_EQ(j["file"], path);
  EXPECT_EQ(j["version"], "1.0");
  EXPECT_EQ(j["record_count"], 1000);
  EXPECT_DOUBLE_EQ(j["cycle_s"].get<double>(), 0.001);
  EXPECT_DOUBLE_EQ(j["t0_s"].get<double>(), 0.5);
  EXPECT_NEAR(j["duration_s"].get<double>(), 0.999, 1e-12);
  ASSERT_EQ(j["channels"].size(), 5u);
  EXPECT_EQ(j["channels"][0], json({{"name", "line"}, {"type", "u32"}, {"offset", 0}}));
  EXPECT_EQ(j["channels"][4], json({{"name", "feed"}, {"type", "f64"}, {"offset", 32}}));
  EXPECT_EQ(j["metadata"]["source"], "part.nc");
  EXPECT_EQ(j["metadata"]["extra"], json({1, 2}));
  EXPECT_EQ(j["bounding_box"]["min"], json({10.0, 2.0, -1.0}));
  EXPECT_NEAR(j["bounding_box"]["max"][0].get<double>(), 10 + 0.02 * 999, 1e-12);
  EXPECT_EQ(j["line_range"]["first"], 3);
  EXPECT_EQ(j["line_range"]["last"], 12);
  EXPECT_NEAR(j["max_speed_mm_min"].get<double>(), 1200, 1e-6);
  EXPECT_LT(j["max_accel_mm_s2"].get<double>(), 1e-3);
  EXPECT_LT(j["max_jerk_mm_s3"].get<double>(), 10);
  EXPECT_NEAR(j["axes"]["x"]["max_speed_mm_min"].get<double>(), 1200, 1e-6);
  EXPECT_EQ(j["axes"]["y"]["max_speed_mm_min"], 0.0);
  EXPECT_TRUE(j["axes"]["z"].contains("max_jerk_mm_s3"));
  EXPECT_EQ(j["non_finite_samples"], 0);
  EXPECT_EQ(j["warnings"], json::array());
}

TEST(biipInfo, ReportsNonFiniteSamples) {
  const std::string path = writeLineFile("info_nan.biip", 500);
  const auto r = runCli("info " + path);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["non_finite_samples"], 1);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0], "1 sample with non-finite x/y/z is kept out of geometry");
  EXPECT_EQ(r.err, "warning: " + path + ": 1 sample with non-finite x/y/z is kept out of geometry\n");
  EXPECT_NEAR(j["max_speed_mm_min"].get<double>(), 1200, 1e-6);  // the NaN stays local
  EXPECT_NEAR(j["bounding_box"]["max"][0].get<double>(), 10 + 0.02 * 999, 1e-12);
}

TEST(biipInfo, FileWithoutLineChannel) {
  const std::string path = (scratchDir() / "info_xyz.biip").string();
  {
    BiipWriter w(path, BiipWriter::layout({{"x", BiipType::F64}, {"y", BiipType::F64}, {"z", BiipType::F64}}),
                 0.002, "");
    const double p[3] = {1, 2, 3};
    w.append(p);
    w.commit();
  }
  const auto r = runCli("info " + path);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j["line_range"].is_null());
  EXPECT_TRUE(j["metadata"].is_null());
  EXPECT_EQ(j["record_count"], 1);
  EXPECT_EQ(j["bounding_box"]["min"], json({1.0, 2.0, 3.0}));
  EXPECT_EQ(j["duration_s"], 0.0);
}

TEST(biipInfo, TruncatedFileWarnsAndLoadsTheRest) {
  const std::string good = writeLineFile("info_cut_src.biip");
  std::string bytes = test::readFile(good);
  bytes.resize(bytes.size() - 20);
  const std::string path = (scratchDir() / "info_cut.biip").string();
  std::ofstream(path, std::ios::binary) << bytes;
  const auto r = runCli("info " + path);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["record_count"], 999);
  EXPECT_EQ(j["warnings"].size(), 2u);  // count too large, last record cut short
  EXPECT_NE(r.err.find("warning: " + path + ": "), std::string::npos) << r.err;
}

TEST(biipInfo, DamagedFileExitsWithTwoNamingTheFile) {
  const std::string path = (scratchDir() / "info_damaged.biip").string();
  std::ofstream(path, std::ios::binary) << "this is not a Biip file at all, just some text; long enough to be a header";
  const auto r = runCli("info " + path);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "error: " + path + ": not a Biip file (wrong magic: expected \"BIIP\")\n");

  std::string bytes = test::readFile(writeLineFile("info_major.biip"));
  bytes[4] = 9;
  std::ofstream(path, std::ios::binary) << bytes;
  const auto v = runCli("info " + path);
  EXPECT_EQ(v.exitCode, 2);
  EXPECT_NE(v.err.find("error: " + path + ": unsupported Biip major version 9"), std::string::npos) << v.err;

  const auto missing = runCli("info " + path + ".missing");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find(path + ".missing: cannot read"), std::string::npos) << missing.err;
}

TEST(biipInfo, WritesToAFileWithOutput) {
  const std::string path = writeLineFile("info_out_src.biip");
  const std::string out = (scratchDir() / "info.json").string();
  const auto r = runCli("info " + path + " -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(json::parse(test::readFile(out))["record_count"], 1000);
  EXPECT_EQ(runCli("info " + path + " -o " + (scratchDir() / "nope" / "x.json").string()).exitCode, 2);
}

}  // namespace
}  // namespace isurface
