#pragma once
// A small file read whole into memory (a program to re-fit, a report written by another
// process), every read checked.
#include <string>

namespace isurface {

// Throws InputError{path, "cannot read: <reason>"} when the file cannot be opened or read.
std::string readWholeFile(const std::string& path);

}  // namespace isurface
