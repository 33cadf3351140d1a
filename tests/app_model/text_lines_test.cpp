// The mapped, line-indexed text behind the G-code pane.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/app_model/text_lines.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::app_model;
using namespace isurface::test;

namespace {

std::string writeScratch(const std::string& name, const std::string& content) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

}  // namespace

TEST(textLines, LineFeedEndings) {
  const TextLines text(writeScratch("lf.nc", "G0 X1\nG1 Y2\n\nM30\n"));
  ASSERT_EQ(text.count(), 4u);
  EXPECT_EQ(text.line(1), "G0 X1");
  EXPECT_EQ(text.line(2), "G1 Y2");
  EXPECT_EQ(text.line(3), "");
  EXPECT_EQ(text.line(4), "M30");
}

TEST(textLines, CarriageReturnLineFeedEndingsAreStripped) {
  const TextLines text(writeScratch("crlf.nc", "G0 X1\r\nG1 Y2\r\n\r\nM30\r\n"));
  ASSERT_EQ(text.count(), 4u);
  EXPECT_EQ(text.line(1), "G0 X1");
  EXPECT_EQ(text.line(2), "G1 Y2");
  EXPECT_EQ(text.line(3), "");
  EXPECT_EQ(text.line(4), "M30");
}

// A carriage return alone ends a line, as the interpreter reads it: the pane's line numbers
// are the moves' line numbers.
TEST(textLines, MixedEndingsEndLinesAtLoneCarriageReturns) {
  const TextLines text(writeScratch("mixed.nc", "a\r\nb\nc\rd\r\n"));
  ASSERT_EQ(text.count(), 4u);
  EXPECT_EQ(text.line(1), "a");
  EXPECT_EQ(text.line(2), "b");
  EXPECT_EQ(text.line(3), "c");
  EXPECT_EQ(text.line(4), "d");
}

TEST(textLines, CarriageReturnOnlyEndings) {
  const TextLines text(writeScratch("mac.nc", "G1 X10 F100\rY20\rM30"));
  ASSERT_EQ(text.count(), 3u);
  EXPECT_EQ(text.line(1), "G1 X10 F100");
  EXPECT_EQ(text.line(2), "Y20");
  EXPECT_EQ(text.line(3), "M30");
}

TEST(textLines, LastLineWithoutNewline) {
  const TextLines text(writeScratch("nofinal.nc", "G0 X1\nM30"));
  ASSERT_EQ(text.count(), 2u);
  EXPECT_EQ(text.line(1), "G0 X1");
  EXPECT_EQ(text.line(2), "M30");

  const TextLines single(writeScratch("single.nc", "M30"));
  ASSERT_EQ(single.count(), 1u);
  EXPECT_EQ(single.line(1), "M30");

  const TextLines crOnlyAtEnd(writeScratch("crend.nc", "G0\r\nM30\r"));
  ASSERT_EQ(crOnlyAtEnd.count(), 2u);
  EXPECT_EQ(crOnlyAtEnd.line(2), "M30");
}

TEST(textLines, EmptyFileHasNoLines) {
  const TextLines text(writeScratch("empty.nc", ""));
  EXPECT_EQ(text.count(), 0u);
  EXPECT_EQ(text.line(0), "");
  EXPECT_EQ(text.line(1), "");
}

TEST(textLines, LoneNewlinesAreEmptyLines) {
  const TextLines one(writeScratch("newline.nc", "\n"));
  ASSERT_EQ(one.count(), 1u);
  EXPECT_EQ(one.line(1), "");
  const TextLines three(writeScratch("newlines.nc", "\n\n\n"));
  EXPECT_EQ(three.count(), 3u);
}

TEST(textLines, OutOfRangeLinesAreEmpty) {
  const TextLines text(writeScratch("range.nc", "a\nb\n"));
  EXPECT_EQ(text.line(0), "");
  EXPECT_EQ(text.line(3), "");
  EXPECT_EQ(text.line(static_cast<std::size_t>(-1)), "");
}

TEST(textLines, MillionLineFileIndexedExactly) {
  const std::string path = (scratchDir() / "million.nc").string();
  {
    std::ofstream out(path, std::ios::binary);
    for (int i = 1; i <= 1000000; ++i) out << "N" << i << " G1 X" << (i % 997) << (i % 3 == 0 ? "\r\n" : "\n");
  }
  const TextLines text(path);
  ASSERT_EQ(text.count(), 1000000u);
  EXPECT_EQ(text.line(1), "N1 G1 X1");
  EXPECT_EQ(text.line(500000), "N500000 G1 X" + std::to_string(500000 % 997));
  EXPECT_EQ(text.line(999999), "N999999 G1 X" + std::to_string(999999 % 997));
  EXPECT_EQ(text.line(1000000), "N1000000 G1 X" + std::to_string(1000000 % 997));
  EXPECT_EQ(text.line(1000001), "");
}

TEST(textLines, MissingFileNamesItInTheError) {
  const std::string path = (scratchDir() / "no-such-file.nc").string();
  try {
    TextLines text(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().file, path);
    EXPECT_EQ(e.diagnostic().line, 0u);
    EXPECT_EQ(e.diagnostic().column, 0u);
    EXPECT_EQ(e.diagnostic().message.rfind("cannot open: ", 0), 0u) << e.diagnostic().message;
    EXPECT_NE(e.diagnostic().message.find("No such file"), std::string::npos) << e.diagnostic().message;
  }
}

TEST(textLines, FolderIsAnError) {
  const std::string path = scratchDir().string();
  try {
    TextLines text(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().file, path);
    EXPECT_EQ(e.diagnostic().message.rfind("cannot open: ", 0), 0u) << e.diagnostic().message;
  }
}
