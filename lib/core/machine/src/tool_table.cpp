// LinuxCNC's tool table format: words of a letter and a number, a ';' comment to the line end.
#include "isurface/machine/tool_table.h"
#include "isurface/base/input_files.h"

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "isurface/base/bounded_file.h"
#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"

namespace isurface {

namespace {

constexpr const char* kTableLetters = "TPXYZABCUVWDIJQ";
// The largest tool diameter taken, mm: a face mill is a few hundred; beyond this a number is a
// typing error that would throw cutter compensation's offsets far off the part.
constexpr double kLargestDiameterMm = 2000;

[[noreturn]] void fail(const std::string& source, std::uint32_t line, const std::string& message) {
  throw InputError(Diagnostic{source, line, 0, message});
}

}  // namespace

ToolDiameters parseToolTable(const std::string& text, const std::string& sourceName, bool inch) {
  ToolDiameters tools;
  std::istringstream lines(text);
  std::string line;
  std::uint32_t number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::string words = line.substr(0, line.find(';'));
    int tool = -1;
    double diameter = 0;
    std::string seen;  // the letters of this entry so far
    for (std::size_t i = 0; i < words.size();) {
      const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(words[i])));
      if (std::isspace(static_cast<unsigned char>(c)) || c == '\r') {
        ++i;
        continue;
      }
      if (!std::isalpha(static_cast<unsigned char>(c)) || std::string(kTableLetters).find(c) == std::string::npos)
        fail(sourceName, number, std::string("unexpected '") + words[i] + "' in a tool table entry");
      if (seen.find(c) != std::string::npos)
        fail(sourceName, number, std::string("the ") + c + " word is twice in one tool table entry");
      seen += c;
      double value = 0;
      const char* first = words.data() + i + 1;
      if (first < words.data() + words.size() && *first == '+') ++first;  // LinuxCNC writes Z+0.511000
      const auto parsed = fast_float::from_chars(first, words.data() + words.size(), value);
      if (parsed.ec != std::errc() || !std::isfinite(value))
        fail(sourceName, number, std::string("the ") + c + " word of a tool table entry has no number");
      i = static_cast<std::size_t>(parsed.ptr - words.data());
      if (c == 'T') {
        if (value < 0 || value != std::floor(value) || value > 1e9)
          fail(sourceName, number, "a tool number (T) must be a whole number, 0 or more");
        tool = static_cast<int>(value);
      } else if (c == 'P') {
        if (value < 0 || value != std::floor(value) || value > 1e9)
          fail(sourceName, number, "a pocket number (P) must be a whole number, 0 or more");
      } else if (c == 'D') {
        if (value < 0) fail(sourceName, number, "a tool diameter (D) must not be negative");
        diameter = inch ? value * kMmPerInch : value;
        if (diameter > kLargestDiameterMm)
          fail(sourceName, number,
               fmt::format("a tool diameter (D) of {:g} mm is more than any tool has (at most {:g} mm)", diameter,
                           kLargestDiameterMm));
      }
    }
    if (words.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank or comment only
    if (tool < 0) fail(sourceName, number, "a tool table entry without a tool number (T)");
    if (tools.count(tool)) fail(sourceName, number, "tool " + std::to_string(tool) + " is in the table twice");
    tools[tool] = diameter;
  }
  return tools;
}

ToolDiameters readToolTable(const std::string& path, bool inch) {
  noteInputFile(path);
  // A table of ten thousand tools is a megabyte; a larger file (or /dev/zero) is refused at the
  // bound before anything is parsed.
  return parseToolTable(readBoundedFile(path, BoundedRead{16 << 20, "tool table"}), path, inch);
}

}  // namespace isurface
