// Writes the CAM-style transition program (tests/support/cam_style_transition.h) to standard
// output, so that it can be measured from the command line:
//   make_cam_style_transition [chord tolerance, mm] > part.nc
#include <cstdio>
#include <cstdlib>

#include "cam_style_transition.h"

int main(int argc, char** argv) {
  isurface::testing::CamStyleTransition part;
  if (argc > 1) part.chordTolerance = std::atof(argv[1]);
  if (!(part.chordTolerance > 0 && part.chordTolerance < 1)) {
    std::fprintf(stderr, "make_cam_style_transition: the chord tolerance must be between 0 and 1 mm\n");
    return 2;
  }
  std::fputs(isurface::testing::camStyleTransitionProgram(part).c_str(), stdout);
  return 0;
}
