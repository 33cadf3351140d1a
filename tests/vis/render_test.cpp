// Screenshot tests of headless quality maps: each bundled sample rendered through the command
// line and compared with its reference image; the tolerance is shown to catch real regressions.
//
// ISURFACE_UPDATE_REFERENCES=1 rewrites the references from the current renders (look at them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "test_support.h"
#include "image_compare.h"

using namespace isurface::test;

namespace {

const char* kSize = "800x500";

std::string referencePath(const std::string& name) { return sourcePath("tests/data/reference/" + name + ".png"); }

// Renders and returns the output path ("" on failure, with the failure recorded).
std::string render(const std::string& name, const std::string& args) {
  const std::string out = (scratchDir() / (name + ".png")).string();
  const CommandResult r = runCli("render " + args + " --size " + kSize + " -o " + out);
  EXPECT_EQ(r.exitCode, 0) << r.err;
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

// The tolerance is not so loose that regressions pass: each of these must be caught.
class ToleranceCatches : public ::testing::Test {
 protected:
  void SetUp() override {
    reference = readPng(referencePath("transition-surface-speed-iso"));
    if (reference.empty()) GTEST_SKIP() << "no reference image yet";
  }
  Image reference;
};

TEST_F(ToleranceCatches, AChangedColourMap) {
  const std::string out =
      render("viridis", sourcePath("samples/transition-surface.nc") + " --color speed --view iso --cmap viridis");
  EXPECT_FALSE(matches(compareImages(reference, readPng(out))));
}

TEST_F(ToleranceCatches, AMissingLegend) {
  Image damaged = reference;
  // The legend stands at the right edge: paint it over with the background beside it.
  for (int y = 0; y < damaged.height; ++y)
    for (int x = damaged.width * 88 / 100; x < damaged.width; ++x)
      std::copy(damaged.at(damaged.width - 1, y), damaged.at(damaged.width - 1, y) + 3, damaged.at(x, y));
  EXPECT_FALSE(matches(compareImages(reference, damaged)));
}

TEST_F(ToleranceCatches, AHoleInTheSurface) {
  Image damaged = reference;
  // A 40x40 pixel hole in the middle of the surface showing the background.
  const int cx = damaged.width / 2, cy = damaged.height / 2;
  for (int y = cy - 20; y < cy + 20; ++y)
    for (int x = cx - 20; x < cx + 20; ++x) damaged.at(x, y)[0] = damaged.at(x, y)[1] = damaged.at(x, y)[2] = 235;
  EXPECT_FALSE(matches(compareImages(reference, damaged)));
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
