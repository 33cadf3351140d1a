// Fuzz target: the LinuxCNC halsampler importer with the shared recording's column mapping,
// followed by what the import command and a quality map do with the samples.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isurface/io/trace_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = isurface::fuzz::writeScratch(data, size, ".txt");
  isurface::fuzz::expectOnlyInputErrors([&] {
    const isurface::Trajectory samples = isurface::importHalsampler(path);
    isurface::fuzz::roundTripThroughBiip(samples);
    isurface::fuzz::exerciseSamples(samples);
  });
  return 0;
}
