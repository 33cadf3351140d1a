#pragma once
// Biip dumps the suites open as fixtures, written in process with the library (what
// `isurface-cli simulate` and `isurface-cli sts --biip` write), no command line needed.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/io/trajectory_writing.h"
#include "isurface/machine/machine.h"
#include "isurface/sts/sts_interpolation.h"
#include "isurface/sts/sts_report.h"
#include "isurface/sts/sts_samples.h"
#include "isurface/sts/sts_surface.h"
#include "isurface/workflow/simulation_dump.h"

namespace isurface::test {

// Simulates a G-code file on the built-in machine into a Biip dump, as `isurface-cli simulate
// PROGRAM -o DUMP` does. False (with the program's errors recorded as failures) when it has errors.
inline bool simulateToDump(const std::string& program, const std::string& dump) {
  const StreamedSimulation s = simulateGcodeFileToBiip(program, defaultMachine(), dump);
  for (const Diagnostic& e : s.interpretation.errors) ADD_FAILURE() << e.str();
  return s.interpretation.ok();
}

// The slow tool servo path of one of the paper's surfaces ("toric" or "sinusoid", its spiral
// as in the paper) as a Biip dump, one sample a node with the error channels, as `isurface-cli
// sts --surface SURFACE --interp INTERP --biip DUMP` writes it. False when an error is not finite.
inline bool stsToDump(const std::string& surfaceName, const std::string& interpolation, const std::string& dump) {
  const std::unique_ptr<StsSurface> surface = makeStsSurface(surfaceName);
  const SpiralParameters p = (surfaceName == "sinusoid" ? paperSinusoidCase() : paperToricCase()).spiral;
  StsJobOptions job;
  job.interpolation = parseStsInterpolation(interpolation);
  const StsJobResult r = runStsJob(*surface, p, job);
  if (!std::isfinite(r.discrete.max) || !std::isfinite(r.interpolation.max)) return false;
  const std::string program = formatStsNcProgram(*surface, p, job, r);
  writeTrajectoryBiip(stsTrajectory(r, job, program, surface->name()), dump);
  return true;
}

}  // namespace isurface::test
