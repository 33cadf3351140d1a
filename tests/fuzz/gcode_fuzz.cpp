// Fuzz target: the G-code interpreter (lexer, modal state, motion, arcs, canned cycles) on any
// text. Every bad block must come back as a diagnostic, never as a crash, hang or exception.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "isurface/gcode/gcode_interpreter.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  isurface::fuzz::expectOnlyInputErrors([&] {
    // Both modes: stopping at the first error and reporting every bad block take different
    // paths through the modal state after an error.
    isurface::InterpreterOptions options;
    isurface::interpretGcode(text, "fuzz.nc", options);
    options.keepGoing = true;
    isurface::interpretGcode(text, "fuzz.nc", options);
  });
  return 0;
}
