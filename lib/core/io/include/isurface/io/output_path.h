// Where writing an output name lands: the file its symbolic links lead to.
#pragma once

#include <string>

namespace isurface {

// The path an output named `target` is written to: `target` with every symbolic link along its
// last component followed, a dangling one too (as a shell's `>` writes the file a link names, not
// the link). Throws InputError naming `target` when the links loop or the name is not one this
// file system can hold (a component too long, a folder that is a file).
std::string outputDestination(const std::string& target);

}  // namespace isurface
