#pragma once
// A program file's text, however it comes: a regular file mapped, a pipe or a device copied to
// an unlinked temporary file first (disk, not memory), a named pipe nobody writes to read as
// empty at once.
#include <functional>
#include <string>
#include <string_view>

namespace isurface::gcode {

// Called with the text and whether it is mapped from the file itself (its pages may be dropped).
using TextUse = std::function<void(std::string_view text, bool mapped)>;

// Opens `path` and calls use(text, mapped) with its contents: a regular file mapped (read in
// ahead when `readAhead`), a pipe or a device copied to a temporary file first. Returns why the
// file could not be read, or an empty string.
std::string withFileText(const std::string& path, bool readAhead, const TextUse& use);

}  // namespace isurface::gcode
