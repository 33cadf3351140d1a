// The bundled samples simulated on the default machine make whole surfaces: every loop joined to
// the next. Where the control rounds the corner into a loop's link, the sample nearest the loop's
// start lies a few micrometres into the link, heading its way; the link must still be found
// where the heading comes back, not a loop's length later.
#include <gtest/gtest.h>

#include "isurface/surface/passes.h"
#include "isurface/surface/surface_mesh.h"
#include "workflow_fixtures.h"

using namespace isurface;
using namespace isurface::test;

TEST(sampleSurfaces, EveryLoopOfTheColaBottleIsJoinedToTheNext) {
  const Program program = readProgram(sourcePath("samples/cola-bottle-bottom.nc"));
  const Trajectory samples = simulateRun(program, defaultMachine(), {}, false);
  const PassSet passes = splitPasses(samples);
  EXPECT_EQ(passes.pattern, PathPattern::ContourParallel);
  ASSERT_EQ(passes.passes.size(), 88u);
  // Each loop starts on the line that starts it (the loops start on the +X axis).
  for (const Pass& pass : passes.passes) EXPECT_LT(std::abs(samples.y[pass.begin]), 0.3) << pass.begin;
  const SurfaceMesh mesh = buildSurfaceMesh(samples, passes);
  EXPECT_EQ(mesh.foldedStrips(), 0u);
}
