#pragma once
// A control's tool table: the diameter of each tool, for cutter radius compensation.
#include <map>
#include <string>

namespace isurface {

// Tool diameters by tool number, mm.
using ToolDiameters = std::map<int, double>;

// Reads a LinuxCNC tool table (`T1 P1 D0.25 Z1.5 ;comment`, one tool a line). Its lengths are
// in the control's machine units: inch when `inch`. Throws InputError naming the file and line
// of a malformed entry.
ToolDiameters readToolTable(const std::string& path, bool inch);
ToolDiameters parseToolTable(const std::string& text, const std::string& sourceName, bool inch);

}  // namespace isurface
