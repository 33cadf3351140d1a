// A dump larger than the memory, seen whole: every k-th record loaded, at k times the cycle,
// each sample the record it stands for; its feedback loaded later reads the same records.
#include <gtest/gtest.h>

#include <cmath>

#include "isurface/io/biip.h"
#include "isurface/io/trajectory_loading.h"
#include "test_support.h"

using namespace isurface;
using isurface::test::scratchDir;

namespace {

double valueOf(const std::string& name, std::size_t r) {
  const double i = double(r);
  if (name == "line") return 10 + r / 37;
  if (name == "block") return r / 37;
  if (name == "t") return 0.5 + 0.001 * i + (r > 900 ? 0.0004 : 0.0);  // a late record: irregular
  if (name == "x") return i * 0.01;
  if (name == "y") return std::cos(i * 0.003);
  if (name == "z") return std::sin(i * 0.01);
  if (name == "fb_x") return i * 0.01 - 0.002;
  if (name == "fb_y") return std::cos(i * 0.003) + 0.001;
  if (name == "fb_z") return std::sin(i * 0.01) - 0.0005;
  if (name == "feed") return 1000 + 100 * double(r / 200);
  if (name == "spindle") return 8000 + i;
  return 0;
}

std::string writeDump(const std::string& name, std::size_t records, bool times) {
  std::vector<std::pair<std::string, BiipType>> channels = {
      {"line", BiipType::U32}, {"block", BiipType::U32}, {"x", BiipType::F64},    {"y", BiipType::F64},
      {"z", BiipType::F64},    {"fb_x", BiipType::F64},  {"fb_y", BiipType::F64}, {"fb_z", BiipType::F64},
      {"feed", BiipType::F64}, {"spindle", BiipType::F32}};
  if (times) channels.push_back({"t", BiipType::F64});
  const std::string path = (scratchDir() / name).string();
  BiipWriter writer(path, BiipWriter::layout(channels), 0.001, "{}", 0.5);
  std::vector<unsigned char> record(writer.recordBytes());
  for (std::size_t r = 0; r < records; ++r) {
    std::fill(record.begin(), record.end(), 0);
    for (const BiipChannel& c : writer.channels()) biipStore(record.data(), c, valueOf(c.name, r));
    writer.append(record.data());
  }
  writer.commit();
  return path;
}

}  // namespace

TEST(thinnedLoading, EveryKthRecordAtKTimesTheCycle) {
  const std::size_t records = 1003;  // not a multiple of k: the last sample is record 1001
  const BiipReader reader(writeDump("thinned.biip", records, false));
  const Trajectory whole = loadTrajectory(reader);
  for (const std::size_t k : {1u, 2u, 7u, 1003u, 5000u}) {
    TrajectoryChannels channels;
    channels.thinning = k;
    const Trajectory t = loadTrajectory(reader, {}, channels);
    const std::size_t n = (records + k - 1) / k;
    ASSERT_EQ(t.size(), n) << k;
    EXPECT_EQ(t.thinning, k);
    EXPECT_DOUBLE_EQ(t.cycle, 0.001 * double(k));
    EXPECT_TRUE(t.hasFeedback());
    ASSERT_EQ(t.extra.size(), 1u);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t r = i * k;
      ASSERT_EQ(t.x[i], whole.x[r]) << k << " " << i;
      ASSERT_EQ(t.y[i], whole.y[r]);
      ASSERT_EQ(t.z[i], whole.z[r]);
      ASSERT_EQ(t.line[i], whole.line[r]);
      ASSERT_EQ(t.block[i], whole.block[r]);
      ASSERT_EQ(t.feed[i], whole.feed[r]);
      ASSERT_EQ(t.fbOffsetX[i], whole.fbOffsetX[r]);
      ASSERT_EQ(t.fbOffsetZ[i], whole.fbOffsetZ[r]);
      ASSERT_EQ(t.extra[0].second[i], whole.extra[0].second[r]);
      ASSERT_NEAR(t.timeAt(i), whole.timeAt(r), 1e-12);
    }
  }
}

TEST(thinnedLoading, RecordedTimesAreThinnedAndJudgedAgainstTheCoarserCycle) {
  const BiipReader reader(writeDump("thinned-times.biip", 1000, true));
  TrajectoryChannels channels;
  channels.thinning = 10;
  const Trajectory t = loadTrajectory(reader, {}, channels);
  ASSERT_EQ(t.size(), 100u);
  EXPECT_EQ(t.time.size(), 100u);
  for (std::size_t i = 0; i < t.size(); ++i) ASSERT_EQ(t.time[i], valueOf("t", i * 10));
  EXPECT_TRUE(t.irregularTime) << "the step after record 900 is 10.4 ms, not 10";
}

TEST(thinnedLoading, FeedbackLoadedLaterReadsTheSameRecords) {
  const BiipReader reader(writeDump("thinned-feedback.biip", 1003, false));
  TrajectoryChannels with, without;
  with.thinning = without.thinning = 7;
  without.feedback = false;
  const Trajectory eager = loadTrajectory(reader, {}, with);
  Trajectory later = loadTrajectory(reader, {}, without);
  EXPECT_FALSE(later.hasFeedback());
  later.attachFeedback(loadFeedbackOffsets(reader, later));
  EXPECT_EQ(later.fbOffsetX, eager.fbOffsetX);
  EXPECT_EQ(later.fbOffsetY, eager.fbOffsetY);
  EXPECT_EQ(later.fbOffsetZ, eager.fbOffsetZ);
}

TEST(thinnedLoading, TheThinningIsTheLeastThatFits) {
  EXPECT_EQ(thinningToFit(100, 10, 1000), 1u);
  EXPECT_EQ(thinningToFit(100, 10, 999), 2u);   // 99 fit: 1 in 2 leaves 50
  EXPECT_EQ(thinningToFit(100, 10, 340), 3u);   // 34 fit: 1 in 3 leaves 34
  EXPECT_EQ(thinningToFit(100, 10, 0), 100u);   // one sample at least
  EXPECT_EQ(thinningToFit(0, 10, 0), 1u);
  // A 3-billion-record dump of 24-byte samples in 12 GB: 1 in 6 (500 M samples, 12 GB).
  EXPECT_EQ(thinningToFit(3'000'000'000ull, 24, 12'000'000'000ull), 6u);
}
