// Fuzz target: the Biip reader on any bytes, and what a quality map does with a dump that it
// accepts.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isurface/io/biip.h"
#include "isurface/io/trajectory_loading.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = isurface::fuzz::writeScratch(data, size, ".biip");
  isurface::fuzz::expectOnlyInputErrors([&] {
    const isurface::BiipReader reader(path);
    isurface::fuzz::exerciseSamples(isurface::loadTrajectory(reader));
  });
  return 0;
}
