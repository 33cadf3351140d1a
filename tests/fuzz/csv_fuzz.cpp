// Fuzz target: the CSV importer, once with the University of Michigan preset and once with a
// generic mapping by header name that keeps every other numeric column, so that both the
// preset's optional columns and user mappings see the same bytes; then what the import command
// and a quality map do with the samples.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isurface/io/trace_import.h"

namespace {

isurface::TraceImportOptions genericMapping() {
  isurface::TraceImportOptions generic;
  generic.columns = isurface::parseColumnMap("x=x,y=y,z=z,t=t,line=line,feed=f,fb_x=ax,fb_y=ay,fb_z=az");
  generic.keepOtherColumns = true;
  return generic;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = isurface::fuzz::writeScratch(data, size, ".csv");
  static const isurface::TraceImportOptions mappings[] = {isurface::umichPreset(), genericMapping()};
  for (const isurface::TraceImportOptions& options : mappings)
    isurface::fuzz::expectOnlyInputErrors([&] {
      const isurface::Trajectory samples = isurface::importCsv(path, options);
      isurface::fuzz::roundTripThroughBiip(samples);
      isurface::fuzz::exerciseSamples(samples);
    });
  return 0;
}
