#pragma once
// The programs the streaming suites compare on: the bundled samples and, when present, the real
// programs of ../shared/realdata.
#include <string>
#include <vector>

#include "test_support.h"

namespace isurface::test {

inline std::vector<std::string> samplesAndRealPrograms() {
  std::vector<std::string> paths = {sourcePath("samples/transition-surface.nc"),
                                    sourcePath("samples/cola-bottle-bottom.nc"), sourcePath("samples/wuzhishan.nc")};
  for (const char* name : {"linuxcnc_test.ngc", "communicator.nc", "cameo.nc", "stellabee1.ngc"})
    if (fileExists(realdataPath(name))) paths.push_back(realdataPath(name));
  return paths;
}

}  // namespace isurface::test
