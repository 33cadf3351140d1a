// Telling files apart by their first bytes.
#include "isurface/workflow/file_kinds.h"
#include "isurface/base/file_read_stream.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <cerrno>
#include <filesystem>
#include <optional>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/io/trace_import.h"

namespace isurface {

namespace {

constexpr std::size_t kLinesLooked = 20;
const std::set<std::string> kProgramExtensions = {".nc", ".ngc", ".gcode", ".gc", ".tap", ".cnc", ".mpf", ".min", ".eia", ".iso"};

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw InputError(Diagnostic{path, 0, 0, message});
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Where the head stops being text: its first NUL byte, or its first control character when
// there are more than a few and more than 1 % of it (a tape-control or end-of-file character
// in an old program is still text).
std::optional<std::size_t> firstBinaryByte(const std::string& head) {
  std::size_t controls = 0;
  std::optional<std::size_t> first;
  for (std::size_t i = 0; i < head.size(); ++i) {
    const auto c = static_cast<unsigned char>(head[i]);
    if (c == 0) return i;
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') || c == 0x7f) {
      ++controls;
      if (!first) first = i;
    }
  }
  if (controls > 8 && controls * 100 > head.size()) return first;
  return std::nullopt;
}

// `cut`: the file goes on after the head.
std::vector<std::string> firstLines(const std::string& head, bool cut) {
  std::vector<std::string> lines;
  std::istringstream in(head);
  for (std::string line; lines.size() < kLinesLooked && std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    lines.push_back(line);
  }
  // The last line of a head cut short may be cut too.
  if (cut && lines.size() > 1) lines.pop_back();
  return lines;
}

bool isNumber(const std::string& field) {
  if (field.empty()) return false;
  char* end = nullptr;
  std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size();
}

std::vector<std::string> split(const std::string& line, bool commas) {
  std::vector<std::string> fields;
  if (commas) {
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) {
      const std::size_t a = field.find_first_not_of(" \t\""), b = field.find_last_not_of(" \t\"");
      fields.push_back(a == std::string::npos ? "" : field.substr(a, b - a + 1));
    }
  } else {
    std::istringstream in(line);
    for (std::string field; in >> field;) fields.push_back(field);
  }
  return fields;
}

// Every line several numbers apart from blanks: halsampler's recording.
bool looksLikeHalsampler(const std::vector<std::string>& lines) {
  if (lines.size() < 2) return false;
  for (const std::string& line : lines) {
    const std::vector<std::string> fields = split(line, false);
    if (fields.size() < 4 || !std::all_of(fields.begin(), fields.end(), isNumber)) return false;
  }
  return true;
}

// A header of names, then rows of comma-separated numbers.
bool looksLikeCsv(const std::vector<std::string>& lines) {
  if (lines.size() < 2) return false;
  const std::vector<std::string> header = split(lines[0], true);
  if (header.size() < 3) return false;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> row = split(lines[i], true);
    if (row.size() != header.size()) return false;
    if (std::count_if(row.begin(), row.end(), isNumber) * 2 < static_cast<long>(row.size())) return false;
  }
  return true;
}

// A line as G-code starts: a word letter and a number, a block number, a comment, a parameter,
// an O-word, a tape mark or a sender command.
bool looksLikeGcode(const std::string& line) {
  const std::size_t at = line.find_first_not_of(" \t/");
  if (at == std::string::npos) return false;
  const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(line[at])));
  if (c == '%' || c == '(' || c == ';' || c == '$') return true;
  const char next = at + 1 < line.size() ? line[at + 1] : '\0';
  if (c == '#') return next == '<' || std::isdigit(static_cast<unsigned char>(next)) || next == '[';
  if (c == 'O' && next == '<') return true;
  if (!std::strchr("ABCDFGHIJKLMNOPQRSTXYZ", c) || c == '\0') return false;
  const std::size_t value = line.find_first_not_of(" \t", at + 1);
  return value != std::string::npos && (std::isdigit(static_cast<unsigned char>(line[value])) ||
                                        std::strchr("+-.#[", line[value]));
}

}  // namespace

FileKind fileKind(const std::string& path, std::size_t headBytes) {
  FileReadStream in(path);
  if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
  std::string head(std::max<std::size_t>(headBytes, 4), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const auto got = static_cast<std::size_t>(in.gcount());
  const bool cut = got == head.size() && in.peek() != EOF;
  head.resize(got);
  if (head.size() >= 4 && head.compare(0, 4, "BIIP") == 0) return FileKind::Dump;
  const std::string ext = lowerExtension(path);
  if (ext == ".biip") fail(path, "is not a Biip dump: it does not begin with the bytes 'BIIP'");
  if (const auto at = firstBinaryByte(head))
    fail(path, fmt::format("is neither a G-code program, a Biip dump nor a trace: byte 0x{:02x} at offset {} is not text",
                           static_cast<unsigned char>(head[*at]), *at));
  const std::vector<std::string> lines = firstLines(head, cut);
  if (looksLikeHalsampler(lines)) return FileKind::HalsamplerTrace;
  if (ext == ".csv" || looksLikeCsv(lines)) return FileKind::CsvTrace;
  // Most lines of a program read as G-code; a log or a note may have a few that do ("(done)",
  // "% complete", "X1 Y2" quoted).
  const auto gcodeLines = std::count_if(lines.begin(), lines.end(), looksLikeGcode);
  // An empty file says nothing of itself: a program only if its name says so. (A head of
  // '#' lines only, LinuxCNC's parameters, reads as a program's.)
  if (lines.empty()) {
    const bool blank = head.find_first_not_of(" \t\r\n\f\v") == std::string::npos;
    if (!blank || kProgramExtensions.count(ext)) return FileKind::Program;
    fail(path, "is empty, and its name does not say it is a G-code program (.nc, .ngc, .gcode, .gc, .tap, .cnc, .mpf, .min, .eia, .iso)");
  }
  if (std::size_t(2 * gcodeLines) >= lines.size()) return FileKind::Program;
  fail(path, fmt::format("is not a G-code program: {} of its first {} lines read as G-code (a word such as G1, X10 "
                         "or M3), fewer than half",
                         gcodeLines, lines.size()));
}

const char* fileKindName(FileKind kind) {
  switch (kind) {
    case FileKind::Program: return "G-code program";
    case FileKind::Dump: return "Biip dump";
    case FileKind::HalsamplerTrace: return "halsampler trace";
    case FileKind::CsvTrace: return "CSV trace";
  }
  return "file";
}

Trajectory readTrace(const std::string& path, FileKind kind) {
  if (kind == FileKind::HalsamplerTrace) return importHalsampler(path);
  FileReadStream in(path);
  std::string headerLine;
  std::getline(in, headerLine);
  if (!headerLine.empty() && headerLine.back() == '\r') headerLine.pop_back();
  std::set<std::string> names;
  for (const std::string& f : split(headerLine, true)) names.insert(f);
  TraceImportOptions options;
  if (names.count("x") && names.count("y") && names.count("z")) {
    for (const char* role : {"x", "y", "z", "fb_x", "fb_y", "fb_z", "feed", "line", "t"})
      if (names.count(role)) options.columns.push_back(ColumnRole{role, role, false});
    options.keepOtherColumns = true;
  } else if (names.count("X1_CommandPosition")) {
    options = umichPreset();
  } else {
    fail(path, "a CSV trace whose columns are not named x, y and z: import it with `isurface-cli import csv " + path +
                   " --map x=COLUMN,y=COLUMN,z=COLUMN -o trace.biip` and open the dump");
  }
  return importCsv(path, options);
}

}  // namespace isurface
