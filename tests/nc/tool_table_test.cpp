// LinuxCNC tool tables as the cutter compensation reads them: what a table may say, and the
// entries no table of real tools has, refused with the line.
#include <gtest/gtest.h>

#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/machine/tool_table.h"

using namespace isurface;

namespace {

std::string refusal(const std::string& table) {
  try {
    parseToolTable(table, "t.tbl", false);
  } catch (const InputError& e) {
    return e.what();
  }
  return "<accepted>";
}

}  // namespace

TEST(toolTable, ReadsLinuxCncEntries) {
  const ToolDiameters tools = parseToolTable("; tools\nT1 P1 D6.0 Z+0.511 ;6 mm\nT2 P2 D0.25\n\n", "t.tbl", false);
  ASSERT_EQ(tools.size(), 2u);
  EXPECT_DOUBLE_EQ(tools.at(1), 6.0);
  EXPECT_DOUBLE_EQ(tools.at(2), 0.25);
  EXPECT_DOUBLE_EQ(parseToolTable("T3 D0.5\n", "t.tbl", true).at(3), 12.7);  // inch
}

TEST(toolTable, RefusesWhatNoTableOfRealToolsSays) {
  EXPECT_NE(refusal("T1 P1 D1e308\n").find("t.tbl:1: a tool diameter (D) of 1e+308 mm is more than any tool has"),
            std::string::npos)
      << refusal("T1 P1 D1e308\n");
  EXPECT_NE(refusal("T1 P1 D100 ;\nT2 D6 D8\n").find("t.tbl:2: the D word is twice in one tool table entry"),
            std::string::npos);
  EXPECT_NE(refusal("T1 P-1 D6\n").find("a pocket number (P) must be a whole number, 0 or more"), std::string::npos);
  EXPECT_NE(refusal("T1 P1.5 D6\n").find("a pocket number (P)"), std::string::npos);
  EXPECT_NE(refusal("T1 D6\nT1 D8\n").find("tool 1 is in the table twice"), std::string::npos);
}
