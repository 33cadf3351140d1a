// isurface-cli intervals GCODE [--lines A-B]: the constant speed intervals of a program's cutting
// moves, section by section, with one planned feed per interval, as JSON.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "command.h"
#include "json_output.h"
#include "inputs.h"
#include "isurface/fitting/constant_speed_intervals.h"
#include "isurface/fitting/interval_speed_plan.h"
#include "number_options.h"
#include "isurface/base/json_text.h"

namespace isurface::cli {
namespace {


struct IntervalsOptions {
  std::string input, lines, machine;
  double error = 0.1, distanceRatio = 5, curvatureRatio = 2, sectionLength = 50;
};



// The feed an interval is programmed at: the slowest of the moves that reach its points.
double programmedFeed(const PathSection& s, const ConstantSpeedInterval& i) {
  double feed = s.feeds[std::min(i.first + 1, i.last)];
  for (std::size_t k = i.first + 1; k <= i.last; ++k) feed = std::min(feed, s.feeds[k]);
  return feed;
}

Json describeSection(const PathSection& s, const IntervalThresholds& thresholds, const Machine& machine) {
  const IntervalPartition part = partitionConstantSpeedIntervals(s.points, thresholds);
  Json points = Json::array();
  for (const CharacteristicPoint& c : part.characteristic)
    points.push_back({{"index", c.index},
                      {"line", s.lines[c.index]},
                      {"position_mm", triple(c.position)},
                      {"radius_mm", numberOrNull(c.radius)},
                      {"distance_ratio", numberOrNull(c.distanceRatio)},
                      {"curvature_ratio", numberOrNull(c.curvatureRatio)},
                      {"inside", c.inside}});
  std::vector<double> feeds;
  for (const ConstantSpeedInterval& i : part.intervals) feeds.push_back(programmedFeed(s, i));
  Json intervals = Json::array();
  for (const PlannedInterval& p : planIntervalSpeeds(part.intervals, feeds, machine))
    intervals.push_back({{"first", p.first},
                         {"last", p.last},
                         {"first_line", s.lines[p.first]},
                         {"last_line", s.lines[p.last]},
                         {"length_mm", p.lengthMm},
                         {"avg_curvature_per_mm", p.averageCurvature},
                         {"planned_feed_mm_min", p.plannedFeedMmMin},
                         {"transition_time_s", p.transitionTimeS},
                         {"transition_distance_mm", p.transitionDistanceMm}});
  return {{"points", s.points.size()},
          {"first_line", s.lines.front()},
          {"last_line", s.lines.back()},
          {"characteristic_points", points},
          {"intervals", intervals}};
}

int runIntervals(const IntervalsOptions& o) {
  if (!(o.error > 0)) badOption(o.input, "--err must be > 0 mm");
  if (!(o.distanceRatio > 1)) badOption(o.input, "--dist-ratio must be > 1");
  if (!(o.curvatureRatio > 1)) badOption(o.input, "--curv-ratio must be > 1");
  if (!(o.sectionLength > 0)) badOption(o.input, "--section-length must be > 0 mm");
  LineRange range{1, UINT32_MAX};
  try {
    if (!o.lines.empty()) range = parseLineRange(o.lines);
  } catch (const InputError& e) {
    badOption(o.input, "--lines: " + e.diagnostic().message);
  }
  const Machine machine = loadMachineOption(o.machine);
  const Program program = loadProgram(o.input, false, false);
  SectionOptions sectionOptions;
  sectionOptions.distanceThreshold = o.sectionLength;
  const std::vector<PathSection> sections = collectSections(program, range.first, range.last, sectionOptions);
  if (sections.empty())
    badOption(o.input, "no cutting moves (G1, G2, G3) in lines " + (o.lines.empty() ? "of the program" : o.lines));
  const IntervalThresholds thresholds{o.error, o.distanceRatio, o.curvatureRatio};
  Json out;
  out["source"] = o.input;
  out["thresholds"] = {{"error_mm", o.error}, {"distance_ratio", o.distanceRatio},
                       {"curvature_ratio", o.curvatureRatio}, {"section_length_mm", o.sectionLength}};
  const IntervalLimits limits = intervalLimits(machine);
  out["limits"] = {{"normal_accel_mm_s2", limits.acceleration}, {"normal_jerk_mm_s3", limits.jerk}};
  Json list = Json::array();
  for (const PathSection& s : sections) list.push_back(describeSection(s, thresholds, machine));
  out["sections"] = list;
  std::printf("%s\n", jsonText(out, 2).c_str());
  return kExitOk;
}

}  // namespace

Command intervalsCommand() {
  return Command{"intervals", "Constant speed intervals of a program's cutting moves, with planned feeds (JSON)",
    [](CLI::App& sub) {
      auto o = std::make_shared<IntervalsOptions>();
      sub.add_option("program", o->input, "G-code file")->required();
      sub.add_option("--lines", o->lines, "source lines A-B (1-based, inclusive); default: all");
      sub.add_option("--err", o->error, "error threshold for characteristic points, mm")
          ->capture_default_str()
          ->check(numberFrom(0, 1000, true));
      sub.add_option("--dist-ratio", o->distanceRatio, "distance ratio threshold (> 1)")
          ->capture_default_str()
          ->check(numberFrom(1, 1e9, true));
      sub.add_option("--curv-ratio", o->curvatureRatio, "curvature ratio threshold (> 1)")
          ->capture_default_str()
          ->check(numberFrom(1, 1e9, true));
      sub.add_option("--section-length", o->sectionLength,
                     "mm of path per section where passes have no boundary")
          ->capture_default_str()
          ->check(numberFrom(0, 1e6, true));
      sub.add_option("--machine", o->machine, "machine description (JSON); default: built-in");
      return [o] { return runIntervals(*o); };
    }};
}

}  // namespace isurface::cli
