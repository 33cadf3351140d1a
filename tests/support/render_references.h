#pragma once
// The reference pictures of the screenshot tests (tests/data/reference/NAME.png) and the fixture
// that shows their tolerance catches real regressions.
#include <gtest/gtest.h>

#include <string>

#include "image_compare.h"
#include "test_support.h"

namespace isurface::test {

inline std::string referencePath(const std::string& name) { return sourcePath("tests/data/reference/" + name + ".png"); }

// The tolerance is not so loose that regressions pass: each of these must be caught.
class ToleranceCatches : public ::testing::Test {
 protected:
  void SetUp() override {
    reference = readPng(referencePath("transition-surface-speed-iso"));
    if (reference.empty()) GTEST_SKIP() << "no reference image yet";
  }
  Image reference;
};

}  // namespace isurface::test
