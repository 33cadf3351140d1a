#include "isurface/optimise/region_optimizer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string_view>

#include <fmt/format.h>

#include "isurface/base/diagnostic.h"
#include "isurface/base/units.h"
#include "isurface/optimise/cross_pass_feeds.h"
#include "isurface/optimise/feed_ramps.h"
#include "isurface/optimise/points_on_grid.h"
#include "isurface/optimise/speeds_across_passes.h"
#include "isurface/optimise/stretch_across_box.h"

#include "pass_plans.h"

namespace isurface {

namespace {

// Of the machine's acceleration (its slowest axis), the ramps' outside the region's box.
constexpr double kOutsideRampShare = 0.5;
// Of a pass's feed, how much faster a point of it may run than the pass beside it.
constexpr double kSpeedStepAcrossPasses = 0.015;

// The program's physical lines, each with its own line end, so unchanged ones are copied
// byte for byte.
std::vector<std::string_view> splitLines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::size_t stop = end == std::string::npos ? text.size() : end + 1;
    lines.emplace_back(text.data() + start, stop - start);
    start = stop;
  }
  return lines;
}

// A line that holds nothing but a straight feed move (G1, coordinates, feed, block number,
// comments): it can be replaced without losing anything else it says.
bool plainFeedLine(std::string_view line) {
  int depth = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ';') break;
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth > 0 || c == ')') continue;
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (std::isalpha(static_cast<unsigned char>(u))) {
      if (u == 'G') {
        std::size_t j = i + 1;
        while (j < line.size() && line[j] == ' ') ++j;
        std::string number;
        while (j < line.size() && (std::isdigit(static_cast<unsigned char>(line[j])) || line[j] == '.')) number += line[j++];
        if (number != "1" && number != "01") return false;
      } else if (u != 'X' && u != 'Y' && u != 'Z' && u != 'F' && u != 'N') {
        return false;
      }
    }
  }
  return true;
}

bool mentions(const std::string& text, const char* code) {
  std::string upper(text.size(), ' ');
  std::transform(text.begin(), text.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  std::size_t at = 0;
  const std::size_t n = std::string_view(code).size();
  while ((at = upper.find(code, at)) != std::string::npos) {
    const char next = at + n < upper.size() ? upper[at + n] : ' ';
    if (!std::isdigit(static_cast<unsigned char>(next)) && next != '.') return true;
    at += n;
  }
  return false;
}

// Whether unit directions `a` and `b` turn sharply seen from above, or either runs (nearly)
// vertically: a step-over, a plunge or a lift, where a pass ends even though its points may
// step up and down in Z at every point.
bool sharpTurnInPlan(const Vec3& a, const Vec3& b) {
  constexpr double kSteep = 0.1;  // of a unit direction's length: steeper than 84 degrees
  const Eigen::Vector2d inPlanA = a.head<2>(), inPlanB = b.head<2>();
  if (inPlanA.norm() < kSteep || inPlanB.norm() < kSteep) return true;
  return inPlanA.normalized().dot(inPlanB.normalized()) < 0.5;
}

// Runs of consecutive plain G1 moves in the range, split where the path turns back in XY (the
// end of a raster pass) and at sharp corners (a step-over), around which a spline would swing.
// A path drawn taut or rounded softens a corner within its tube like any other point, so for
// them only a corner seen from above ends a run, not one in Z.
std::vector<std::vector<std::size_t>> findRuns(const Program& program, const std::vector<std::string_view>& lines,
                                               LineRange range, bool onlyCornersInPlanEndRuns) {
  std::vector<std::vector<std::size_t>> runs;
  std::vector<std::size_t> run;
  auto close = [&] {
    if (!run.empty()) runs.push_back(run);
    run.clear();
  };
  for (std::size_t i = 0; i < program.moves.size(); ++i) {
    const Move& m = program.moves[i];
    const bool sharesLine = (i > 0 && program.moves[i - 1].line == m.line) ||
                            (i + 1 < program.moves.size() && program.moves[i + 1].line == m.line);
    const bool usable = m.kind == MoveKind::Linear && m.line >= range.first && m.line <= range.last &&
                        m.line <= lines.size() && !sharesLine && !(m.flags & (kExactStop | kStopAfter)) &&
                        plainFeedLine(lines[m.line - 1]);
    if (!usable) {
      close();
      continue;
    }
    if (!run.empty()) {
      const Move& previous = program.moves[run.back()];
      const Vec3 a = (previous.end - program.startOf(run.back())).normalized();
      const Vec3 b = (m.end - program.startOf(i)).normalized();
      const Vec3 main = program.moves[run.front()].end - program.startOf(run.front());
      // A run is written in one frame (G92 / G52 offset, G68 rotation): a change ends it.
      const bool consecutive = m.line == previous.line + 1 && program.frameOf(i).sameAs(program.frameOf(run.back()));
      const bool corner = onlyCornersInPlanEndRuns ? sharpTurnInPlan(a, b) : a.dot(b) < 0.5;
      const bool turnsBack = main.x() * b.x() + main.y() * b.y() < 0;
      if (!consecutive || corner || turnsBack || m.feed != previous.feed) close();
    }
    run.push_back(i);
  }
  close();
  return runs;
}

// New blocks in the program's own units: mm with 4 decimals and whole mm/min, or inches with
// 5 decimals (0.25 um) and in/min with 2.
struct BlockUnits {
  double perMm;  // program units per mm
  int positionDecimals, feedDecimals;
  std::string position(const Vec3& p) const {
    return fmt::format("X{:.{}f} Y{:.{}f} Z{:.{}f}", p.x() * perMm, positionDecimals, p.y() * perMm, positionDecimals,
                       p.z() * perMm, positionDecimals);
  }
  std::string feed(double mmPerMin) const { return fmt::format("{:.{}f}", mmPerMin * perMm, feedDecimals); }
  double grid() const { return std::pow(10.0, -positionDecimals) / perMm; }  // mm, the last decimal's step
};

// How a pass's feeds are ramped: inside the region's box at the ramp's acceleration, outside at
// half the machine's (its slowest axis), if that is faster. `feed`: the pass's, mm/min.
RampOptions rampOptions(const OptimizeOptions& options, double feed, const Machine& machine) {
  double slowestAxis = INFINITY;  // mm/s^2
  for (const AxisLimits& axis : machine.axes) slowestAxis = std::min(slowestAxis, axis.maxAcceleration);
  RampOptions ramps;
  ramps.programmedFeed = feed;
  ramps.normalAccelerationLimit = options.normalAccelerationLimit;
  ramps.rampAcceleration = options.rampAcceleration;
  ramps.within = options.rampBox;
  ramps.outsideAcceleration = kOutsideRampShare * slowestAxis;
  return ramps;
}

// Each pass's feeds per move, its bends' ramps held where they would run faster than the
// passes beside them (speeds_across_passes.h).
std::vector<FeedPerMove> feedsAgreeingAcrossPasses(const std::vector<PassFeeds>& plans, const std::vector<std::vector<std::size_t>>& runs,
                                                   const Program& program, const OptimizeOptions& options, const Machine& machine) {
  std::vector<double> programmedFeeds;  // mm/min
  std::vector<FeedPerMove> moves;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    programmedFeeds.push_back(program.moves[runs[r].front()].feed);
    moves.push_back(feedPerMove(plans[r], rampOptions(options, programmedFeeds[r], machine)));
  }
  if (!(options.rampAcceleration > 0 && options.normalAccelerationLimit > 0)) return moves;
  const std::vector<std::vector<double>> caps = speedCapsAcrossPasses(moves, programmedFeeds, {kSpeedStepAcrossPasses});
  for (std::size_t r = 0; r < runs.size(); ++r)
    // A pass no neighbour holds ramps as it did.
    if (std::any_of(caps[r].begin(), caps[r].end(), [](double cap) { return std::isfinite(cap); }))
      moves[r] = feedPerMoveHeldTo(plans[r], moves[r], caps[r], rampOptions(options, programmedFeeds[r], machine));
  return moves;
}

}  // namespace

OptimizeResult optimizeRegion(const std::string& text, const Program& program, LineRange range,
                              const Machine& machine, const OptimizeOptions& options) {
  if (mentions(text, "G91")) throw InputError(Diagnostic{program.source, 0, 0, "incremental programs (G91) are not re-optimised"});
  // An inch program is re-fitted in mm, as it was read, and its new blocks are written back in
  // inches; one that switches units part way is refused rather than guessed at.
  const bool inch = mentions(text, "G20");
  if (inch && mentions(text, "G21"))
    throw InputError(Diagnostic{program.source, 0, 0,
                                "programs that switch between inches and millimetres (G20 and G21) are not re-optimised"});
  const BlockUnits units = inch ? BlockUnits{1.0 / kMmPerInch, 5, 2} : BlockUnits{1.0, 4, 0};
  // Its moves would be re-fitted through the tool tip alone, and written without A, B and C.
  if (!program.rotary.empty()) {
    const Move& first = program.moves.at(static_cast<std::size_t>(program.rotary.front().move));
    throw InputError(Diagnostic{program.source, first.line, first.column,
                                "five-axis programs (A, B or C turn here) are not re-optimised: the optimiser re-fits "
                                "the tool tip's path and would drop the rotary axes"});
  }
  if (mentions(text, "G93")) throw InputError(Diagnostic{program.source, 0, 0, "inverse-time programs (G93) are not re-optimised"});
  const std::vector<std::string_view> lines = splitLines(text);
  std::vector<std::vector<std::size_t>> runs =
      findRuns(program, lines, range, options.shape == PathShape::DrawnTaut || options.shape == PathShape::CornersRounded);
  if (options.planBox)
    for (auto& run : runs) run = stretchAcrossBox(program, run, *options.planBox);
  runs.erase(std::remove_if(runs.begin(), runs.end(), [&](const auto& r) { return r.size() < options.minimumMoves; }),
             runs.end());
  if (runs.empty())
    throw InputError(Diagnostic{program.source, range.first, 0,
                                fmt::format("lines {}-{} hold no run of {} or more plain G1 moves to re-optimise",
                                            range.first, range.last, options.minimumMoves)});
  OptimizeResult result;
  FittedBox fittedBox;
  std::uint32_t written = 0;  // lines of the output so far
  std::size_t nextSource = 1; // next source line to copy
  const char* lineEnd = text.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  auto copyUntil = [&](std::size_t lastLine) {
    for (; nextSource <= lastLine && nextSource <= lines.size(); ++nextSource) {
      result.text.append(lines[nextSource - 1]);
      ++written;
    }
  };
  // First every pass is re-fitted and its interval feeds planned; then the feeds are planned
  // across passes; then the passes are written.
  const std::string how = options.shape == PathShape::DrawnTaut
                             ? fmt::format("points drawn taut within {:g} mm", options.maximumDeviation)
                         : options.shape == PathShape::CornersRounded
                             ? fmt::format("corners rounded within {:g} mm", options.maximumDeviation)
                         : options.shape == PathShape::Eased
                             ? fmt::format("Akima spline in arc length, bends eased in and out within {:g} mm", options.maximumDeviation)
                             : std::string("Akima spline in arc length");
  std::vector<PassFeeds> plans = planPasses(program, runs, machine, options, fittedBox);
  result.fittedLower = fittedBox.lower;
  result.fittedUpper = fittedBox.upper;
  harmonizeFeedsAcrossPasses(plans, options.crossPass);
  const std::vector<FeedPerMove> movesOfPasses = feedsAgreeingAcrossPasses(plans, runs, program, options, machine);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto& run = runs[r];
    const Move& first = program.moves[run.front()];
    const Move& last = program.moves[run.back()];
    const FeedPerMove& moves = movesOfPasses[r];
    const double feed = first.feed;
    const std::vector<double>& feeds = plans[r].feeds;
    copyUntil(first.line - 1);
    OptimizedPass pass;
    pass.firstLine = first.line;
    pass.lastLine = last.line;
    pass.oldMoves = run.size();
    pass.intervalFeeds = feeds;
    // One feed per interval, or the program's own (perhaps capped) for the whole pass.
    std::string feedList = options.programmedFeed ? ", feed F" + units.feed(feeds.front()) : ", constant speed intervals";
    if (!options.programmedFeed)
      for (double f : feeds) feedList += " F" + units.feed(f);
    result.text += fmt::format("(iSurface: lines {}-{} re-fitted: {}{}{}){}", first.line, last.line, how, feedList,
                               options.rampAcceleration > 0 ? fmt::format(", ramps of {:g} mm/s^2", options.rampAcceleration) : "",
                               lineEnd);
    pass.newFirstLine = ++written;
    // An eased path is smooth and written in short pieces: its points are placed where their
    // rounding keeps them on it. (The paper's fit is written as it is: placed so, its runs on
    // samples/wuzhishan.nc ran 4 % faster instead of 2 % and the servo deviated 6 % more. A
    // taut or rounded path keeps corners a parabola would cut.)
    // The points were fitted on the moves, in workpiece coordinates; the blocks say them in the
    // program's own, under the G92 / G52 offset and G68 rotation in effect there.
    const CoordinateFrame frame = program.frameOf(run.front());
    std::vector<Vec3> inProgram(moves.points.size());
    std::transform(moves.points.begin(), moves.points.end(), inProgram.begin(),
                   [&](const Vec3& p) { return frame.toProgram(p); });
    const std::vector<Vec3> onGrid =
        options.shape == PathShape::Eased ? pointsOnGrid(inProgram, units.grid()) : inProgram;
    std::string current;
    for (std::size_t k = 1; k < moves.points.size(); ++k) {
      const std::string f = units.feed(moves.feeds[k - 1]);
      std::string block = "G1 " + units.position(onGrid[k]);
      if (f != current) block += " F" + f, current = f;
      result.text += block + lineEnd;
      pass.sourceLines.push_back(moves.sourceLines[k]);
      ++written;
      ++pass.newMoves;
    }
    // The lines after keep the feed they had.
    if (current != units.feed(feed)) {
      result.text += "F" + units.feed(feed) + lineEnd;
      ++written;
    }
    pass.newLastLine = written;
    nextSource = last.line + 1;
    result.passes.push_back(pass);
  }
  copyUntil(lines.size());
  // Lines of the range before its first pass keep their numbers; those after its last pass
  // moved by what the passes added.
  const OptimizedPass& lastPass = result.passes.back();
  result.newRange.first = std::min(range.first, result.passes.front().newFirstLine);
  result.newRange.last = range.last > lastPass.lastLine
                             ? static_cast<std::uint32_t>(range.last + (lastPass.newLastLine - lastPass.lastLine))
                             : lastPass.newLastLine;
  return result;
}

LineRange linesOfPass(const Trajectory& samples, const Pass& pass) {
  LineRange r{UINT32_MAX, 0};
  samples.line.forEachRun(pass.begin, pass.end, [&](std::uint32_t line, std::size_t, std::size_t) {
    if (line != 0) r.first = std::min(r.first, line), r.last = std::max(r.last, line);
  });
  return r;
}

LineRange widenToWholePasses(const Trajectory& samples, const PassSet& passSet, LineRange lines) {
  const std::vector<Pass>& passes = passSet.passes;
  auto lineRangeOf = [&](const Pass& p) { return linesOfPass(samples, p); };
  std::size_t first = passes.size(), last = 0;
  for (std::size_t k = 0; k < passes.size(); ++k) {
    const LineRange r = lineRangeOf(passes[k]);
    if (r.last < lines.first || r.first > lines.last) continue;
    first = std::min(first, k), last = std::max(last, k);
  }
  if (first > last) return lines;
  const LineRange from = lineRangeOf(passes[first > 0 ? first - 1 : first]);
  const LineRange to = lineRangeOf(passes[last + 1 < passes.size() ? last + 1 : last]);
  return {std::min(lines.first, from.first), std::max(lines.last, to.last)};
}

}  // namespace isurface
