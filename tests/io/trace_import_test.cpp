// Reading recorded machine traces (halsampler text, CSV).
#include <gtest/gtest.h>

#include "isurface/io/biip.h"
#include "isurface/base/diagnostic.h"
#include "isurface/io/trace_import.h"
#include "scratch_files.h"

namespace isurface {
namespace {

using test::writeScratch;

TEST(traceImport, parsesColumnMap) {
  const auto map = parseColumnMap("x=1, y=2,z=3,line=4,spindle_load=9");
  ASSERT_EQ(map.size(), 5u);
  EXPECT_EQ(map[1].role, "y");
  EXPECT_EQ(map[1].column, "2");
  EXPECT_EQ(map[4].role, "spindle_load");
  EXPECT_THROW(parseColumnMap("x=1,y"), InputError);
  EXPECT_THROW(parseColumnMap("x=1,x=2"), InputError);
  EXPECT_THROW(parseColumnMap("=3"), InputError);
}

TEST(traceImport, sanitisesChannelNames) {
  EXPECT_EQ(sanitiseChannelName("X1_ActualPosition"), "x1_actualposition");
  EXPECT_EQ(sanitiseChannelName("Spindle Load (%)"), "spindle_load____");
  EXPECT_EQ(sanitiseChannelName(std::string(40, 'a')).size(), kBiipMaxNameLength);
}

TEST(traceImport, halsamplerSmallFileWithCustomMap) {
  const std::string path = writeScratch("small.hal", "# comment\n0 1.5 2 3 7\n\n1 1.6 2 3 8\n2 1.7 2 3 0\n");
  TraceImportOptions o;
  o.columns = parseColumnMap("x=1,y=2,z=3,line=4");
  o.cycle = 0.002;
  const Trajectory t = importHalsampler(path, o);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_TRUE(t.hasLine);
  EXPECT_EQ(t.line.toVector(), (std::vector<std::uint32_t>{7, 8, 0}));
  EXPECT_DOUBLE_EQ(t.x[2], 1.7);
  EXPECT_DOUBLE_EQ(t.timeAt(2), 0.004);
  EXPECT_TRUE(t.extra.empty());
}

TEST(traceImport, csvTimeColumnAndIrregularSampling) {
  const std::string path = writeScratch("timed.csv", "time,px,py,pz,load\n0,0,0,0,1\n0.1,1,0,0,2\n0.3,2,0,0,3\n");
  TraceImportOptions o;
  o.columns = parseColumnMap("t=time,x=px,y=py,z=pz,load=load");
  const Trajectory t = importCsv(path, o);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_FALSE(t.hasLine);
  EXPECT_DOUBLE_EQ(t.timeAt(2), 0.3);
  EXPECT_NEAR(t.cycle, 0.15, 1e-12);
  EXPECT_TRUE(t.irregularTime);
  ASSERT_NE(t.extraChannel("load"), nullptr);
  EXPECT_DOUBLE_EQ((*t.extraChannel("load"))[1], 2.0);
}

TEST(traceImport, nonNumericCellNamesLineAndColumn) {
  const std::string path = writeScratch("bad.hal", "0 1 2 3 4 5 6 7\n1 1 abc 3 4 5 6 7\n");
  try {
    importHalsampler(path, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().file, path);
    EXPECT_EQ(e.diagnostic().line, 2u);
    EXPECT_EQ(e.diagnostic().column, 5u);
    EXPECT_NE(std::string(e.what()).find("abc"), std::string::npos);
  }
}

TEST(traceImport, shortRowNamesMissingColumn) {
  const std::string path = writeScratch("short.hal", "0 1 2 3 4 5 6 7\n1 1 2\n");
  try {
    importHalsampler(path, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().line, 2u);
    EXPECT_NE(std::string(e.what()).find("missing column 3 (z)"), std::string::npos) << e.what();
  }
}

// The umich preset keeps every other numeric column; one whose header is a role's name ("x",
// "line") becomes a channel of its own instead of feeding that role a second value per row.
TEST(traceImport, keptColumnNamedLikeARoleIsAChannelOfItsOwn) {
  const std::string path = writeScratch(
      "role-named.csv",
      "line,x,X1_CommandPosition,Y1_CommandPosition,Z1_CommandPosition,X1_ActualPosition,Y1_ActualPosition,"
      "Z1_ActualPosition,M1_CURRENT_FEEDRATE\n7,9,1,2,3,1,2,3,100\n8,9,4,5,6,4,5,6,100\n");
  const Trajectory t = importCsv(path, umichPreset());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t.x, (std::vector<double>{1, 4}));
  EXPECT_EQ(t.line, (std::vector<std::uint32_t>{0, 0}));  // no M1_sequence_number column
  ASSERT_NE(t.extraChannel("line_2"), nullptr);
  EXPECT_EQ(*t.extraChannel("line_2"), (std::vector<double>{7, 8}));
  ASSERT_NE(t.extraChannel("x_2"), nullptr);
  EXPECT_EQ(t.extraChannel("x_2")->size(), 2u);
}

TEST(traceImport, feedbackNeedsAllThreeAxes) {
  const std::string path = writeScratch("fb.csv", "x,y,z,a\n0,0,0,0\n1,0,0,1\n");
  TraceImportOptions options;
  options.columns = parseColumnMap("x=x,y=y,z=z,fb_x=a");
  try {
    importCsv(path, options);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fb_x, fb_y and fb_z together"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace isurface
