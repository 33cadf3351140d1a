#include "isurface/io/trace_import.h"
#include "isurface/base/file_read_stream.h"

#include <fmt/format.h>
#include "isurface/base/input_files.h"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <string_view>

#include "isurface/io/biip.h"
#include "isurface/base/diagnostic.h"

namespace isurface {
namespace {

[[noreturn]] void fail(const std::string& file, unsigned line, unsigned column, std::string message) {
  throw InputError(Diagnostic{file, line, column, std::move(message)});
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

bool parseNumber(std::string_view text, double& out) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // fast_float refuses '+'
  if (text.empty()) return false;
  const auto r = fast_float::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

// One cell of a row: its text and the 1-based character column where it starts.
struct Cell {
  std::string_view text;
  unsigned column;
};

void splitWhitespace(std::string_view line, std::vector<Cell>& cells) {
  cells.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) cells.push_back({line.substr(start, i - start), unsigned(start + 1)});
  }
}

// Quoted cells lose their quotes; a comma inside quotes does not split (no escaped quotes in
// the logs this reads, so `""` is not handled specially).
void splitCsv(std::string_view line, std::vector<Cell>& cells) {
  cells.clear();
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i < line.size() && line[i] == '"') quoted = !quoted;
    if (i == line.size() || (line[i] == ',' && !quoted)) {
      std::string_view cell = trim(line.substr(start, i - start));
      if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = cell.substr(1, cell.size() - 2);
      cells.push_back({cell, unsigned(start + 1)});
      start = i + 1;
    }
  }
}

// SampleIndex: halsampler's sample number, the time in cycles (a gap is samples it dropped).
enum class Target { X, Y, Z, FbX, FbY, FbZ, Feed, Line, Time, SampleIndex, Extra };

struct Binding {
  Target target;
  std::size_t column;  // 0-based cell index in a row
  std::string label;   // how errors name the column
  std::size_t extra = 0;
};

// Collects the mapped cells of each row into a Trajectory's channels.
class TrajectoryBuilder {
 public:
  // What a dump has room for beside its own channels (line x y z t fb_x fb_y fb_z feed).
  static constexpr std::size_t kMaxExtraChannels = kBiipMaxChannels - 9;

  explicit TrajectoryBuilder(const std::string& file) : file_(file) { t_.source = file; }

  void bind(const std::string& role, std::size_t column, const std::string& label) {
    static const std::pair<const char*, Target> known[] = {
        {"x", Target::X},       {"y", Target::Y},       {"z", Target::Z},       {"fb_x", Target::FbX},
        {"fb_y", Target::FbY},  {"fb_z", Target::FbZ},  {"feed", Target::Feed}, {"line", Target::Line},
        {"t", Target::Time},    {"index", Target::SampleIndex}};
    for (const auto& [name, target] : known)
      if (role == name) {
        bindings_.push_back({target, column, label});
        return;
      }
    bindExtra(role, column, label);
  }

  // A column kept as a channel of its own, whatever its name: a header named like a role
  // ("x", "line") must not feed that role a second value per row.
  void bindExtra(const std::string& name, std::size_t column, const std::string& label) {
    if (t_.extra.size() == kMaxExtraChannels)
      fail(file_, 0, 0,
           "more than " + std::to_string(kMaxExtraChannels) + " extra channels (column " + label +
               "): a Biip dump holds " + std::to_string(kBiipMaxChannels) + " channels in all");
    t_.extra.emplace_back(uniqueExtraName(sanitiseChannelName(name)), std::vector<double>{});
    bindings_.push_back({Target::Extra, column, label, t_.extra.size() - 1});
  }

  bool bound(std::size_t column) const {
    return std::any_of(bindings_.begin(), bindings_.end(), [&](const Binding& b) { return b.column == column; });
  }

  void addRow(const std::vector<Cell>& cells, unsigned lineNumber) {
    for (const Binding& b : bindings_) {
      if (b.column >= cells.size())
        fail(file_, lineNumber, 0,
             "missing column " + b.label + ": the line has " + std::to_string(cells.size()) + " values");
      double v = 0;
      const Cell& cell = cells[b.column];
      if (!parseNumber(cell.text, v))
        fail(file_, lineNumber, cell.column,
             "column " + b.label + ": '" + std::string(cell.text.substr(0, 40)) + "' is not a number");
      // Positions may be NaN (geometry skips such samples) but a time cannot: every rate is
      // divided by time differences.
      if (b.target == Target::Time && !std::isfinite(v))
        fail(file_, lineNumber, cell.column, "column " + b.label + ": time '" + std::string(cell.text.substr(0, 40)) + "' is not finite");
      // Every rate is divided by a time difference: a repeated time would make it infinite.
      if (b.target == Target::Time && !time_.empty() && !(v > time_.back()))
        fail(file_, lineNumber, cell.column,
             "column " + b.label + ": time " + std::string(cell.text.substr(0, 40)) +
                 (v < time_.back() ? " runs backwards" : " does not advance") + " (the row before: " +
                 fmt::format("{:.9g}", time_.back()) + ")");
      if (b.target == Target::SampleIndex) checkSampleIndex(v, cell, b, lineNumber);
      // A line number names a line of the program: a whole number, 0 for none.
      if (b.target == Target::Line && !(v >= 0 && v <= 4294967295.0 && v == std::floor(v)))
        fail(file_, lineNumber, cell.column,
             "column " + b.label + ": line number '" + std::string(cell.text.substr(0, 40)) +
                 "' is not a whole number from 0 (no line) to 4294967295");
      target(b).push_back(v);
    }
    ++rows_;
  }

  Trajectory finish(double cycle, bool cycleGiven) {
    if (rows_ == 0) fail(file_, 0, 0, "no samples in the file");
    if (!index_.empty() && !time_.empty()) fail(file_, 0, 0, "the column mapping has both 't' and 'index': map one clock");
    // The sample number counts cycles from the first row: samples the recorder dropped leave a
    // gap in time, not a jump in speed. Without a gap the times are the regular cycle's.
    if (!index_.empty() && index_.back() - index_.front() != double(rows_ - 1)) {
      for (const double k : index_) time_.push_back((k - index_.front()) * cycle);
      cycleGiven = true;
    }
    Trajectory& t = t_;
    if (t.x.empty() || t.y.empty() || t.z.empty()) fail(file_, 0, 0, "the column mapping needs x, y and z");
    // Feedback is a position: one or two of its axes alone would be read past their end.
    const int feedbackAxes = int(!feedback_[0].empty()) + int(!feedback_[1].empty()) + int(!feedback_[2].empty());
    if (feedbackAxes != 0 && feedbackAxes != 3)
      fail(file_, 0, 0, "the column mapping needs fb_x, fb_y and fb_z together, or none of them");
    if (feedbackAxes == 3) {
      for (std::vector<float>* offset : {&t.fbOffsetX, &t.fbOffsetY, &t.fbOffsetZ}) offset->resize(rows_);
      for (std::size_t i = 0; i < rows_; ++i) t.setFeedback(i, Vec3(feedback_[0][i], feedback_[1][i], feedback_[2][i]));
    }
    t.cycle = cycle;
    if (rows_ > 1 && !time_.empty() && !(time_.back() > time_.front()))
      fail(file_, 0, 0, fmt::format("time stands still ({:.9g} s on every row)", time_.front()));
    if (!time_.empty()) {
      // A recorded time column: its mean step is the nominal cycle unless one was given.
      if (!cycleGiven && rows_ > 1 && time_.back() > time_.front()) {
        const double mean = (time_.back() - time_.front()) / double(rows_ - 1);
        // A dump holds a control's or a recorder's period: times in the wrong unit, or far apart,
        // would make every speed zero or infinite.
        if (!(mean >= kBiipShortestCycle && mean <= kBiipLongestCycle))
          fail(file_, 0, 0,
               fmt::format("the time column's mean step, {:g} s over {} rows, is not a sample period (1e-6 to 60 s): "
                           "are its times in seconds?",
                           mean, rows_));
        t.cycle = mean;
      }
      t.time = std::move(time_);
      t.irregularTime = timeIsIrregular(t.time.data(), t.time.size(), t.cycle);
    }
    for (const double f : feedValues_) t.feed.push_back(static_cast<float>(f));
    t.hasLine = !lineValues_.empty();
    for (const double v : lineValues_) {
      // Controllers log line numbers as floats; anything not a positive count is "no line".
      t.line.push_back(std::isfinite(v) && v >= 0.5 ? std::uint32_t(std::min(std::llround(v), 0xffffffffLL)) : 0u);
    }
    t.line.resize(rows_, 0);
    return std::move(t_);
  }

 private:
  std::vector<double>& target(const Binding& b) {
    switch (b.target) {
      case Target::X: return t_.x;
      case Target::Y: return t_.y;
      case Target::Z: return t_.z;
      case Target::FbX: return feedback_[0];
      case Target::FbY: return feedback_[1];
      case Target::FbZ: return feedback_[2];
      case Target::Feed: return feedValues_;
      case Target::Line: return lineValues_;
      case Target::Time: return time_;
      case Target::SampleIndex: return index_;
      case Target::Extra: break;
    }
    return t_.extra[b.extra].second;
  }

  // Extra channels must not take a name the dump already uses, nor repeat one.
  std::string uniqueExtraName(std::string name) {
    static const char* reserved[] = {"x", "y", "z", "t", "line", "fb_x", "fb_y", "fb_z", "feed", "block"};
    if (name.empty()) name = "channel";
    auto taken = [&](const std::string& n) {
      if (std::find(std::begin(reserved), std::end(reserved), n) != std::end(reserved)) return true;
      return std::any_of(t_.extra.begin(), t_.extra.end(), [&](const auto& e) { return e.first == n; });
    };
    std::string candidate = name;
    for (int k = 2; taken(candidate); ++k) {
      const std::string suffix = "_" + std::to_string(k);
      candidate = name.substr(0, kBiipMaxNameLength - suffix.size()) + suffix;
    }
    return candidate;
  }

  std::string file_;
  Trajectory t_;
  std::vector<Binding> bindings_;
  void checkSampleIndex(double v, const Cell& cell, const Binding& b, unsigned lineNumber) const {
    const std::string text(cell.text.substr(0, 40));
    if (!(v >= 0 && v <= 9007199254740992.0 && v == std::floor(v)))
      fail(file_, lineNumber, cell.column, "column " + b.label + ": sample number '" + text + "' is not a whole number from 0 to 9007199254740992");
    if (!index_.empty() && !(v > index_.back()))
      fail(file_, lineNumber, cell.column,
           "column " + b.label + ": sample number " + text + (v < index_.back() ? " runs backwards" : " repeats") +
               fmt::format(" (the row before: {:.0f})", index_.back()));
  }

  std::vector<double> lineValues_, feedValues_, time_, index_;
  std::vector<double> feedback_[3];  // positions, mm, until the commanded ones are complete
  std::size_t rows_ = 0;
};

std::unique_ptr<FileReadStream> openTrace(const std::string& path) {
  auto in = std::make_unique<FileReadStream>(path);
  const int error = errno;
  noteInputFile(path);
  if (!*in) fail(path, 0, 0, std::string("cannot open: ") + std::strerror(error));
  return in;
}

void checkPositionsMapped(const std::vector<ColumnRole>& columns, const std::string& file) {
  for (const char* axis : {"x", "y", "z"})
    if (std::none_of(columns.begin(), columns.end(), [&](const ColumnRole& c) { return c.role == axis; }))
      fail(file, 0, 0, std::string("the column mapping has no '") + axis + "' column");
}

}  // namespace

std::string sanitiseChannelName(const std::string& name) {
  std::string out;
  for (char c : name) {
    const char l = char(std::tolower(static_cast<unsigned char>(c)));
    out += (std::isalnum(static_cast<unsigned char>(l)) && static_cast<unsigned char>(l) < 128) ? l : '_';
    if (out.size() == kBiipMaxNameLength) break;
  }
  return out;
}

std::vector<ColumnRole> parseColumnMap(const std::string& text, const std::string& what) {
  std::vector<ColumnRole> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view entry = trim(std::string_view(text).substr(start, end - start));
    start = end + 1;
    if (entry.empty()) continue;
    const std::size_t eq = entry.find('=');
    const std::string role = eq == std::string_view::npos ? "" : std::string(trim(entry.substr(0, eq)));
    const std::string column = eq == std::string_view::npos ? "" : std::string(trim(entry.substr(eq + 1)));
    if (role.empty() || column.empty())
      fail(what, 0, 0, "'" + std::string(entry) + "' is not role=column");
    if (std::any_of(out.begin(), out.end(), [&](const ColumnRole& c) { return c.role == role; }))
      fail(what, 0, 0, "role '" + role + "' is mapped twice");
    out.push_back({role, column});
  }
  return out;
}

std::vector<ColumnRole> defaultHalsamplerColumns() {
  return {{"index", "0"},       {"x", "1"},           {"y", "2"},           {"z", "3"},
          {"line", "4"},        {"current_vel", "5"}, {"requested_vel", "6"}, {"running", "7"}};
}

TraceImportOptions umichPreset() {
  TraceImportOptions o;
  o.columns = {{"x", "X1_CommandPosition"},  {"y", "Y1_CommandPosition"}, {"z", "Z1_CommandPosition"},
               {"fb_x", "X1_ActualPosition"}, {"fb_y", "Y1_ActualPosition"}, {"fb_z", "Z1_ActualPosition"},
               {"feed", "M1_CURRENT_FEEDRATE"}, {"line", "M1_sequence_number", true}};
  o.cycle = 0.1;  // s, the experiments' logging period
  o.keepOtherColumns = true;
  return o;
}

Trajectory importHalsampler(const std::string& path, const TraceImportOptions& options) {
  const std::vector<ColumnRole> columns = options.columns.empty() ? defaultHalsamplerColumns() : options.columns;
  checkPositionsMapped(columns, path);
  TrajectoryBuilder builder(path);
  for (const ColumnRole& c : columns) {
    double index = -1;
    if (!parseNumber(c.column, index) || index < 0 || index != std::floor(index) || index > 1e6)
      fail(path, 0, 0, "column '" + c.column + "' of role '" + c.role + "' is not a column index (0, 1, ...)");
    builder.bind(c.role, std::size_t(index), c.column + " (" + c.role + ")");
  }
  const std::unique_ptr<FileReadStream> stream = openTrace(path);
  std::istream& in = *stream;
  std::string text;
  std::vector<Cell> cells;
  unsigned lineNumber = 0;
  while (std::getline(in, text)) {
    ++lineNumber;
    splitWhitespace(text, cells);
    if (cells.empty() || cells[0].text.front() == '#') continue;
    builder.addRow(cells, lineNumber);
  }
  if (in.bad()) fail(path, lineNumber, 0, "read error");
  return builder.finish(options.cycle > 0 ? options.cycle : kHalsamplerDefaultCycle, options.cycle > 0);
}

Trajectory importCsv(const std::string& path, const TraceImportOptions& options) {
  checkPositionsMapped(options.columns, path);
  const std::unique_ptr<FileReadStream> stream = openTrace(path);
  std::istream& in = *stream;
  std::string text;
  std::vector<Cell> cells;
  unsigned lineNumber = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, text)) {
    if (lineNumber == 0 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a UTF-8 byte order mark
    ++lineNumber;
    if (trim(text).empty()) continue;
    splitCsv(text, cells);
    for (const Cell& c : cells) header.emplace_back(c.text);
  }
  if (header.empty()) fail(path, 0, 0, "empty file: no header row");
  const unsigned headerLine = lineNumber;

  TrajectoryBuilder builder(path);
  for (const ColumnRole& c : options.columns) {
    const auto it = std::find(header.begin(), header.end(), c.column);
    if (it == header.end()) {
      if (c.optional) continue;
      fail(path, headerLine, 0, "no column named '" + c.column + "' (for " + c.role + ") in the header");
    }
    if (std::count(header.begin(), header.end(), c.column) > 1)
      fail(path, headerLine, 0,
           "the header names '" + c.column + "' (for " + c.role + ") more than once: which column is meant is not clear");
    builder.bind(c.role, std::size_t(it - header.begin()), "'" + c.column + "'");
  }
  bool firstRow = true;
  while (std::getline(in, text)) {
    ++lineNumber;
    if (trim(text).empty()) continue;
    splitCsv(text, cells);
    if (firstRow && options.keepOtherColumns) {
      // Text columns (a process name, a wear label) are recognised on the first row and left out.
      double v = 0;
      for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k)
        if (!header[k].empty() && !builder.bound(k) && parseNumber(cells[k].text, v))
          builder.bindExtra(header[k], k, "'" + header[k] + "'");
    }
    firstRow = false;
    // A row with more values than the header has names: its columns cannot be told apart.
    if (cells.size() > header.size())
      fail(path, lineNumber, cells[header.size()].column,
           fmt::format("{} values where the header names {} columns", cells.size(), header.size()));
    builder.addRow(cells, lineNumber);
  }
  if (in.bad()) fail(path, lineNumber, 0, "read error");
  const double cycle = options.cycle > 0 ? options.cycle : kCsvDefaultCycle;
  return builder.finish(cycle, options.cycle > 0);
}

}  // namespace isurface
