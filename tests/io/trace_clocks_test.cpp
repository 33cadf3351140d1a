// The clocks and line numbers of recorded runs: a trace's sample numbers and times, a dump's `t`
// and `line` channels. A time that does not advance makes every speed infinite, and a line
// number that is not a whole number names no line: both are refused with the record, never read.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/io/biip.h"
#include "isurface/io/trace_import.h"
#include "isurface/io/trajectory_loading.h"
#include "scratch_files.h"

namespace isurface {
namespace {

using test::scratchDir;
using test::writeScratch;

std::string refusalOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// halsampler numbers its samples: samples it dropped leave a gap in time, not a jump in speed.
TEST(traceClocks, HalsamplerSampleNumbersAreTheClock) {
  const std::string path = writeScratch("gap.hal", "0 0 0 0 1 0 0 1\n1 0.05 0 0 1 0 0 1\n1000 50 0 0 1 0 0 1\n1001 50.05 0 0 1 0 0 1\n");
  const Trajectory t = importHalsampler(path, {});
  ASSERT_EQ(t.size(), 4u);
  EXPECT_DOUBLE_EQ(t.timeAt(2), 1.0);
  EXPECT_DOUBLE_EQ(t.timeAt(3), 1.001);
  EXPECT_TRUE(t.irregularTime);
  // 50 mm in the second between samples 1 and 1000: 3,000 mm/min, not 60,000.
  EXPECT_NEAR((t.x[2] - t.x[1]) / (t.timeAt(2) - t.timeAt(1)) * 60.0, 3000.0, 0.01);
  // Without a gap the samples are the regular cycle's (no time channel is kept).
  const Trajectory regular = importHalsampler(writeScratch("regular.hal", "7 0 0 0 1 0 0 1\n8 1 0 0 1 0 0 1\n9 2 0 0 1 0 0 1\n"), {});
  EXPECT_TRUE(regular.time.empty());
  EXPECT_DOUBLE_EQ(regular.timeAt(2), 0.002);
}

TEST(traceClocks, AHalsamplerSampleNumberThatRepeatsOrRunsBackIsRefusedWithItsLine) {
  const std::string repeated = writeScratch("repeat.hal", "0 0 0 0 1 0 0 1\n1 1 0 0 1 0 0 1\n1 2 0 0 1 0 0 1\n");
  const std::string why = refusalOf([&] { importHalsampler(repeated, {}); });
  EXPECT_NE(why.find(":3:"), std::string::npos) << why;
  EXPECT_NE(why.find("repeats"), std::string::npos) << why;
  const std::string back = writeScratch("back.hal", "5 0 0 0 1 0 0 1\n4 1 0 0 1 0 0 1\n");
  EXPECT_NE(refusalOf([&] { importHalsampler(back, {}); }).find("runs backwards"), std::string::npos);
  EXPECT_NE(refusalOf([&] { importHalsampler(writeScratch("half.hal", "0 0 0 0 1 0 0 1\n1.5 1 0 0 1 0 0 1\n"), {}); })
                .find("not a whole number"),
            std::string::npos);
}

TEST(traceClocks, ACsvTimeThatDoesNotAdvanceIsRefused) {
  const std::string path = writeScratch("still.csv", "t,x,y,z\n0,0,0,0\n0.1,1,0,0\n0.1,2,0,0\n0.2,3,0,0\n");
  TraceImportOptions o;
  o.columns = parseColumnMap("t=t,x=x,y=y,z=z");
  const std::string why = refusalOf([&] { importCsv(path, o); });
  EXPECT_NE(why.find(":4:"), std::string::npos) << why;
  EXPECT_NE(why.find("does not advance"), std::string::npos) << why;
}

TEST(traceClocks, ACsvRowLongerThanItsHeaderOrAHeaderNamingAColumnTwiceIsRefused) {
  TraceImportOptions o;
  o.columns = parseColumnMap("x=x,y=y,z=z");
  const std::string longRow = writeScratch("long.csv", "x,y,z\n0,0,0\n1,0,0,9\n");
  const std::string why = refusalOf([&] { importCsv(longRow, o); });
  EXPECT_NE(why.find(":3:"), std::string::npos) << why;
  EXPECT_NE(why.find("4 values where the header names 3 columns"), std::string::npos) << why;
  const std::string twice = writeScratch("twice.csv", "x,y,z,x\n0,0,0,5\n1,0,0,6\n");
  EXPECT_NE(refusalOf([&] { importCsv(twice, o); }).find("names 'x' (for x) more than once"), std::string::npos);
}

// A dump whose `line` channel is f64 and whose `t` channel holds the given times.
std::string dumpWith(const std::string& name, const std::vector<double>& lines, const std::vector<double>& times) {
  const auto channels = BiipWriter::layout({{"line", BiipType::F64},
                                            {"t", BiipType::F64},
                                            {"x", BiipType::F64},
                                            {"y", BiipType::F64},
                                            {"z", BiipType::F64}});
  const std::string path = (scratchDir() / name).string();
  BiipWriter w(path, channels, 0.001, "");
  std::vector<unsigned char> rec(w.recordBytes());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    biipStore(rec.data(), channels[0], lines[i]);
    biipStore(rec.data(), channels[1], times[i]);
    biipStore(rec.data(), channels[2], double(i));
    biipStore(rec.data(), channels[3], 0.0);
    biipStore(rec.data(), channels[4], 0.0);
    w.append(rec.data());
  }
  w.commit();
  return path;
}

TEST(traceClocks, ADumpLineThatIsNotAWholeNumberIsRefusedWithItsRecord) {
  const std::vector<double> times = {0, 0.001, 0.002};
  EXPECT_EQ(loadTrajectory(BiipReader(dumpWith("whole.biip", {3, 4, 0}, times))).line.toVector(),
            (std::vector<std::uint32_t>{3, 4, 0}));
  for (const double bad : {1.5, -3.0, 1e20, std::numeric_limits<double>::quiet_NaN()}) {
    const std::string path = dumpWith("bad-line.biip", {3, bad, 4}, times);
    const std::string why = refusalOf([&] { loadTrajectory(BiipReader(path)); });
    EXPECT_NE(why.find("channel 'line', record 1"), std::string::npos) << bad << ": " << why;
    EXPECT_NE(why.find("not a whole number"), std::string::npos) << why;
  }
}

TEST(traceClocks, ADumpTimeThatDoesNotAdvanceIsRefused) {
  const std::string path = dumpWith("still.biip", {1, 1, 1, 1}, {0, 0.001, 0.001, 0.002});
  const std::string why = refusalOf([&] { loadTrajectory(BiipReader(path)); });
  EXPECT_NE(why.find("channel 't', record 2"), std::string::npos) << why;
  EXPECT_NE(why.find("does not advance"), std::string::npos) << why;
}

}  // namespace
}  // namespace isurface
