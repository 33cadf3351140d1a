#pragma once
// What a file a user brings is, told by its content (a name's extension can lie): a G-code
// program, a Biip dump, or a machine trace (LinuxCNC halsampler text, a CSV log).
#include <string>

#include "isurface/base/trajectory.h"

namespace isurface {

enum class FileKind { Program, Dump, HalsamplerTrace, CsvTrace };

// Throws InputError naming the file when it cannot be read, is binary but not a dump, or is
// named as a dump (.biip) without being one.
// `headBytes`: how much of the start is read to decide (64 KB; less when listing many files).
FileKind fileKind(const std::string& path, std::size_t headBytes = 64 * 1024);

// "G-code program", "Biip dump", "halsampler trace", "CSV trace".
const char* fileKindName(FileKind kind);

inline bool isTrace(FileKind kind) { return kind == FileKind::HalsamplerTrace || kind == FileKind::CsvTrace; }

// A trace's samples: halsampler text in LinuxCNC's column order; a CSV log whose header names
// x, y and z (and any of fb_x fb_y fb_z, feed, line, t), or the University of Michigan layout.
// Throws InputError, naming `isurface-cli import` for a CSV whose columns must be mapped.
Trajectory readTrace(const std::string& path, FileKind kind);

}  // namespace isurface
