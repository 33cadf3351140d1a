#pragma once
// Machine traces recorded by other tools (LinuxCNC halsampler text, CSV logs) read into a
// Trajectory, so that they can be written as a Biip dump and analysed like a simulation.
//
// Both readers stream the file once, line by line. Every problem with the input throws
// InputError naming the file, the 1-based line and column where it is known, and the problem.
#include <string>
#include <utility>
#include <vector>

#include "isurface/base/trajectory.h"

namespace isurface {

// One `role=column` pair of a column mapping. Roles with a meaning: x y z (commanded position,
// mm, required), fb_x fb_y fb_z (feedback position, mm), feed (mm/min), line (1-based G-code
// line, 0 outside the program), t (time, s). Any other role becomes an extra channel of that
// name. The column is a 0-based index for halsampler text and a header name for CSV.
struct ColumnRole {
  std::string role;
  std::string column;
  bool optional = false;  // a CSV column that may be missing: the role is then dropped
};

struct TraceImportOptions {
  std::vector<ColumnRole> columns;  // empty: the format's defaults (see below)
  double cycle = 0;                 // s, nominal sample period; 0: the format's default
  // CSV: every numeric column not mapped becomes an extra channel named after its header
  // (sanitised to [a-z0-9_]).
  bool keepOtherColumns = false;
};

// Parses `x=1,y=2,z=3` (or `x=X1_CommandPosition,...`). Throws InputError naming `what` (the
// option it came from) when an entry has no `=` or an empty side, or a role repeats.
std::vector<ColumnRole> parseColumnMap(const std::string& text, const std::string& what = "--map");

// The mapping of LinuxCNC's recording in shared realdata: index 0 (ignored), x 1, y 2, z 3,
// line 4, current_vel 5, requested_vel 6 (program units per second), running 7 (0 or 1).
std::vector<ColumnRole> defaultHalsamplerColumns();
constexpr double kHalsamplerDefaultCycle = 0.001;  // s, LinuxCNC's servo period
constexpr double kCsvDefaultCycle = 0.001;         // s, when neither --cycle nor a preset says

// The University of Michigan tool-wear experiments' CSV layout: command positions as x y z,
// actual positions as fb_x fb_y fb_z, M1_sequence_number as line (when present),
// M1_CURRENT_FEEDRATE as feed, every other numeric column kept; 100 ms period.
TraceImportOptions umichPreset();

// Whitespace-separated numbers, one line per servo cycle; blank lines and lines starting with
// `#` are skipped. Time is i * cycle unless a `t` column is mapped.
Trajectory importHalsampler(const std::string& path, const TraceImportOptions& options = {});

// Comma-separated values with a header row; columns are mapped by header name. A header with
// no name (a pandas index) is never kept as an extra channel.
Trajectory importCsv(const std::string& path, const TraceImportOptions& options);

// Lower case, every character outside [a-z0-9_] replaced by `_`, cut to the Biip name limit.
std::string sanitiseChannelName(const std::string& name);

}  // namespace isurface
