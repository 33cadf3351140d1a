#pragma once
// The bundled machine whose control plans each chord as programmed, braking at its junctions (no
// compressor, as the paper's NC system): where the paper's speed fluctuations on CAM chords, and
// the optimiser that removes them, are what a test is about. The default machine's control
// smooths chord runs within its tolerance and runs them without those fluctuations.
#include "isurface/machine/machine.h"

#include "test_support.h"

namespace isurface::test {

inline const char* kMachineWithoutChordSmoothing = "resources/machines/without-chord-smoothing.json";

inline Machine machineWithoutChordSmoothing() { return loadMachine(sourcePath(kMachineWithoutChordSmoothing)); }

}  // namespace isurface::test
