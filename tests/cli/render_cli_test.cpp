// Screenshot tests of headless quality maps: each bundled sample rendered through the command
// line and compared with its reference image; a changed colour map is caught; bad options refused.
//
// ISURFACE_UPDATE_REFERENCES=1 rewrites the references from the current renders (look at them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "test_support.h"
#include "image_compare.h"
#include "render_references.h"

using namespace isurface::test;

namespace {

const char* kSize = "800x500";

// Renders and returns the output path ("" on failure, with the failure recorded).
std::string render(const std::string& name, const std::string& args) {
  const std::string out = (scratchDir() / (name + ".png")).string();
  const CommandResult r = runCli("render " + args + " --size " + kSize + " -o " + out);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // A render that works says nothing of the OpenGL loader (GLEW failing over to OSMesa).
  EXPECT_EQ(r.err.find("GLEW"), std::string::npos) << r.err;
  return r.exitCode == 0 ? out : "";
}

void expectMatchesReference(const std::string& name, const std::string& rendered) {
  ASSERT_FALSE(rendered.empty());
  const std::string reference = referencePath(name);
  if (std::getenv("ISURFACE_UPDATE_REFERENCES")) {
    std::filesystem::copy_file(rendered, reference, std::filesystem::copy_options::overwrite_existing);
    GTEST_SKIP() << "reference rewritten: " << reference;
  }
  const Image expected = readPng(reference), actual = readPng(rendered);
  ASSERT_FALSE(expected.empty()) << "no reference image " << reference;
  const ImageDifference d = compareImages(expected, actual);
  EXPECT_TRUE(matches(d)) << name << ": worst 32x32 block differs by " << d.worstBlock << ", whole image by "
                          << d.meanDifference << " (rendered " << rendered << ")";
}

}  // namespace

class SampleMaps : public ::testing::TestWithParam<const char*> {};

TEST_P(SampleMaps, SpeedMapMatchesItsReference) {
  const std::string sample = GetParam();
  const std::string name = sample + "-speed-iso";
  expectMatchesReference(name, render(name, sourcePath("samples/" + sample + ".nc") + " --color speed --view iso"));
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleMaps,
                         ::testing::Values("transition-surface", "cola-bottle-bottom", "wuzhishan"));

TEST(RenderOptions, TopViewOfAccelerationWithAHighlightedLineMatchesItsReference) {
  const std::string name = "transition-surface-accel-top-line2000";
  expectMatchesReference(name, render(name, sourcePath("samples/transition-surface.nc") +
                                                " --color accel --view top --cmap coolwarm --highlight-line 2000"));
}

// The tolerance is not so loose that regressions pass (the fixture: render_references.h).
TEST_F(ToleranceCatches, AChangedColourMap) {
  const std::string out =
      render("viridis", sourcePath("samples/transition-surface.nc") + " --color speed --view iso --cmap viridis");
  EXPECT_FALSE(matches(compareImages(reference, readPng(out))));
}

TEST(RenderErrors, BadOptionsExitWithTwoAndWriteNothing) {
  const std::string out = (scratchDir() / "never.png").string();
  const std::string program = sourcePath("samples/transition-surface.nc");
  for (const std::string& bad : {std::string("--color nonsense"), std::string("--view sideways"),
                                 std::string("--cmap plaid"), std::string("--range 5:1"),
                                 std::string("--size 10x10000000"), std::string("--surface feedback --color speed "
                                                                                "--machine /nonexistent.json")}) {
    SCOPED_TRACE(bad);
    const CommandResult r = runCli("render " + program + " " + bad + " -o " + out);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_FALSE(r.err.empty());
    EXPECT_FALSE(fileExists(out));
  }
}

// Ranges the user gives are kept as given, however narrow: the top tenth of a percent, or a
// few mm/min about the programmed feed.
TEST(RenderOptions, NarrowRangesGivenAreKept) {
  const std::string out = (scratchDir() / "narrow.png").string();
  const std::string program = sourcePath("samples/transition-surface.nc");
  EXPECT_EQ(runCli("render " + program + " --percentiles 99.9:100 -o " + out).exitCode, 0);
  const CommandResult fixed = runCli("render " + program + " --range 1999:2000 -o " + out);
  ASSERT_EQ(fixed.exitCode, 0) << fixed.err;
  EXPECT_NE(fixed.out.find("1999 .. 2000,"), std::string::npos) << fixed.out;
}
