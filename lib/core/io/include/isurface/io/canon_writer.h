#pragma once
// A G-code program interpreted into its canonical move listing (docs/canon-format.md), one
// line per move, streamed: memory stays the same whatever the size of the file. The lines are
// formatted and written on a second thread while the program is interpreted. When
// options.callStack is set (to anything), each move made inside calls has them after its line:
// " @ " and the stack the interpreter tells (docs/canon-format.md).
#include <string>

#include "isurface/gcode/gcode_stream.h"

namespace isurface {

// Writes to standard output; `error` gets the errno of the first failed write.
StreamedInterpretation interpretToStdout(const std::string& input, const InterpreterOptions& options, int& error);

// Writes through a temporary file renamed into place when the program has no error or
// options.keepGoing: a failed run leaves no partial file. `writeError` gets the message of a
// failed write; the program is still interpreted, so that its own errors are reported.
StreamedInterpretation interpretToPath(const std::string& input, const InterpreterOptions& options,
                                       const std::string& path, std::string& writeError);

}  // namespace isurface
