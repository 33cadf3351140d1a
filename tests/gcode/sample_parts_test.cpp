// The bundled samples are what their generators write, and they are real programs.
#include <gtest/gtest.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/sample_parts.h"
#include "test_support.h"

using namespace isurface;

TEST(SampleParts, BundledFilesAreExactlyWhatTheGeneratorsWrite) {
  for (const SamplePart& part : sampleParts()) {
    SCOPED_TRACE(part.name);
    const std::string bundled = test::readFile(test::sourcePath("samples/" + part.name + ".nc"));
    ASSERT_FALSE(bundled.empty()) << "samples/" << part.name << ".nc is missing";
    EXPECT_TRUE(bundled == generateSamplePart(part.name))
        << "regenerate with: build/bin/isurface-cli sample " << part.name << " -o samples/" << part.name << ".nc";
  }
}

TEST(SampleParts, EverySampleInterpretsAndCutsAtF3000) {
  for (const SamplePart& part : sampleParts()) {
    SCOPED_TRACE(part.name);
    const InterpretResult r = interpretGcodeFile(test::sourcePath("samples/" + part.name + ".nc"));
    ASSERT_TRUE(r.ok()) << r.errors.front().str();
    std::size_t cutting = 0;
    for (const Move& m : r.program.moves)
      if (m.kind == MoveKind::Linear && m.feed == 3000.0f) ++cutting;
    EXPECT_GT(cutting, 4000u);
  }
}
