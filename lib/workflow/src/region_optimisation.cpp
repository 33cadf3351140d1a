// Re-optimising a region: re-fit it, simulate the new program, measure both, and keep the best
// candidate no worse than the program (region_choice.cpp chooses the region).
#include "isurface/workflow/region_optimisation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <tuple>

#include "isurface/analysis/quality_figures.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/servo_response.h"
#include "isurface/optimise/polyline_distance.h"
#include "isurface/workflow/run_inputs.h"

#include "candidate_feed_limits.h"
#include "candidate_choice.h"
#include "surface_required.h"

namespace isurface {

namespace {

constexpr double kRegionMarginMm = 0.5;
constexpr double kFineCharacteristicError = 0.01;  // mm
constexpr int kDeviationRounds = 3;
// Of the program's own deviation (p99), what the bends are planned to: the servo's answer on a
// circle (servo_response.h) is a steady state; entering a bend adds a little.
constexpr double kServoBoundShare = 0.95;
// How many times the eased bends' bound is moved by what the last run deviated: the servo's
// deviation follows the bound only roughly (it also lags while the speed changes), and a bend
// eased in may deviate less than a steady circle says.
constexpr int kBoundRounds = 3;
constexpr double kBoundRoundsWithin = 0.02;  // of the program's time

// The ramps' accelerations tried between the feeds of the bends and the rest, mm/s^2: the
// faster ones cost less time, the gentler ones change the speed more evenly.
constexpr double kRampAccelerations[] = {750.0, 500.0, 350.0, 250.0, 200.0, 150.0, 100.0};
// Twice: the listed ramps are 1.3 to 1.5 times apart, and two halvings bring the step under
// 1.1, finer than the time a run is judged by tells apart; each is one or two more simulations.
constexpr int kRampRefinements = 2;
// Of the spacing of the passes, how far beyond the box the gentle ramps reach: the next pass,
// not the one after.
constexpr double kRampBoxReach = 1.25;

std::vector<Vec3> regionPoints(const Program& program, LineRange lines) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < program.moves.size(); ++i)
    if (program.moves[i].isMotion() && program.moves[i].line >= lines.first && program.moves[i].line <= lines.last) {
      if (points.empty()) points.push_back(program.startOf(i));
      points.push_back(program.moves[i].end);
    }
  return points;
}

std::pair<Vec3, Vec3> boundingBox(const std::vector<Vec3>& points) {
  Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity()), upper = -lower;
  for (const Vec3& p : points) lower = lower.cwiseMin(p), upper = upper.cwiseMax(p);
  if (points.empty()) lower = upper = Vec3::Zero();
  return {lower, upper};
}

// s: how long the samples spend on the lines of `range`.
double timeOnLines(const Trajectory& samples, LineRange range) {
  std::size_t count = 0;
  samples.line.forEachRun([&](std::uint32_t line, std::size_t begin, std::size_t end) {
    if (line >= range.first && line <= range.last) count += end - begin;
  });
  return double(count) * samples.cycle;
}

bool slower(const RegionOptimisation& r) {
  // Half a cycle of slack: the two runs are whole numbers of cycles.
  const double cycle = r.after.samples ? r.after.samples->cycle : 0.0;
  const double allowed = r.objective == Objective::Quality ? kQualitySlowdownAllowed * r.timeBefore : 0.0;
  return r.timeAfter > r.timeBefore + allowed + 0.5 * cycle;
}

// mm: how far apart neighbouring passes lie, seen from above: the median distance from a vertex
// of the surface to its neighbour on the previous pass (of at most kSpacingVertices vertices
// spread over the run). 0 where no pass has a neighbour.
double passSpacing(const SurfaceRun& run) {
  constexpr std::size_t kSpacingVertices = 100'000;
  const Trajectory& t = *run.samples;
  const SurfaceMesh& mesh = *run.mesh;
  const std::size_t stride = std::max<std::size_t>(1, mesh.vertexSample.size() / kSpacingVertices);
  std::vector<double> distances;
  for (std::size_t v = 0; v < mesh.vertexSample.size(); v += stride) {
    if (mesh.previousPassNeighbour[v] == kNoVertex) continue;
    const std::size_t i = mesh.vertexSample[v], j = mesh.vertexSample[mesh.previousPassNeighbour[v]];
    distances.push_back(std::hypot(t.x[i] - t.x[j], t.y[i] - t.y[j]));
  }
  return distances.empty() ? 0.0 : percentileOf(distances, 50);
}

// What every candidate is judged against: the program's own figures, measured once per box.
// Lines of a program's text (a last line without its newline counts).
std::size_t lineCount(const std::string& text) {
  const std::size_t newlines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  return newlines + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

struct Baseline {
  Baseline(const std::string& text, const Program& program, const SurfaceRun& run)
      : program(program), run(run), lines(lineCount(text)), values(figureValues(*run.samples, *run.mesh)),
        whole(measureQualityFigures(values, *run.samples, *run.mesh)), passSpacing(isurface::passSpacing(run)) {}

  const QualityFigures& regionIn(const Vec3& lower, const Vec3& upper, LineRange lines) {
    if (!region || std::get<0>(*region) != lower || std::get<1>(*region) != upper)
      region.emplace(lower, upper, measureQualityFigures(values, *run.samples, *run.mesh, FigureWindow{lines, lower, upper}));
    return std::get<2>(*region);
  }

  const Program& program;
  const SurfaceRun& run;
  std::size_t lines;  // of the program's text
  FigureValues values;
  QualityFigures whole;
  double passSpacing;  // mm
  std::optional<std::tuple<Vec3, Vec3, QualityFigures>> region;
};

// The box a candidate is judged in and the program's own figures there: the box asked for (or
// the first candidate's, see ClosedLoop::judge), else where the path was re-fitted; a re-fitted part that holds no surface
// sample (one pass, a flat box) gives way to the region. InputError where nothing between
// passes can be measured there (the candidate would be judged on nothing).
void measureBefore(RegionOptimisation& r, Baseline& before, const RegionRequest& request) {
  std::tie(r.lower, r.upper) = request.box ? *request.box : std::make_pair(r.result.fittedLower, r.result.fittedUpper);
  r.regionBefore = before.regionIn(r.lower, r.upper, request.lines);
  if (!request.box && r.regionBefore.samples == 0) {
    std::tie(r.lower, r.upper) = boundingBox(regionPoints(before.program, request.lines));
    // Only the region's lines are measured: the margin takes in no other line, and gives the
    // box of a single straight pass the height its samples need.
    r.lower -= Vec3::Constant(kRegionMarginMm);
    r.upper += Vec3::Constant(kRegionMarginMm);
    r.regionBefore = before.regionIn(r.lower, r.upper, request.lines);
  }
  if (r.regionBefore.betweenPasses > 0) return;
  throw InputError(Diagnostic{
      before.program.source, r.lines.first, 0,
      fmt::format("lines {}-{}: {}", r.lines.first, r.lines.last,
                  r.regionBefore.samples == 0
                      ? std::string("no surface sample lies in the region to measure it by")
                      : fmt::format("no sample of the region has a neighbouring pass on the surface (its passes are "
                                    "further apart than the gap limit of {:g} mm, or run on from one another as one "
                                    "pass): nothing between passes can be measured there (passes further apart are "
                                    "joined by raising the gap: --gap-limit or the window's Colour panel)",
                                    before.run.gapLimit))});
}

// One candidate's re-fitted program, simulated on the machine, measured and judged.
RegionOptimisation evaluateCandidate(OptimizeResult result, Baseline& before, const Machine& machine,
                                     const RegionRequest& request, const ProgressCallback& progress) {
  const Program& program = before.program;
  RegionOptimisation r;
  r.lines = request.lines;
  r.objective = request.objective;
  r.result = std::move(result);
  InterpretResult reread = interpretGcode(r.result.text, program.source);
  if (!reread.ok()) throw std::runtime_error("the new program does not interpret: " + reread.errors.front().str());
  r.program = std::make_shared<const Program>(std::move(reread.program));
  measureBefore(r, before, request);
  // The paths' distance needs no simulation: it is measured on a second core meanwhile.
  std::future<double> pathDistance = std::async(std::launch::async, [&] {
    return polylineDistance(regionPoints(program, request.lines), regionPoints(*r.program, r.result.newRange));
  });
  r.after = surfaceRun(std::make_shared<const Trajectory>(simulateRun(*r.program, machine, progressStage(progress, 0.1, 0.9))),
                       r.program.get(), before.run.gapLimit);
  {
    const FigureValues after = figureValues(*r.after.samples, *r.after.mesh);
    r.regionAfter = measureQualityFigures(after, *r.after.samples, *r.after.mesh, FigureWindow{r.result.newRange, r.lower, r.upper});
    r.wholeAfter = measureQualityFigures(after, *r.after.samples, *r.after.mesh);
  }
  r.wholeBefore = before.whole;
  r.maxPathDistance = pathDistance.get();
  r.linesBefore = before.lines;
  r.linesAfter = lineCount(r.result.text);
  r.timeBefore = machiningTime(*before.run.samples);
  r.timeAfter = machiningTime(*r.after.samples);
  r.regionTimeBefore = timeOnLines(*before.run.samples, request.lines);
  r.regionTimeAfter = timeOnLines(*r.after.samples, r.result.newRange);
  if (const auto why = whyNotKept(r)) {
    r.kept = false;
    r.reason = *why;
  }
  if (progress) progress(1.0);
  return r;
}

struct Candidate {
  CrossPassRule rule;
  double share;                   // of the planned feeds
  bool fine = false;              // characteristic points at kFineCharacteristicError
  std::vector<double> ceilings;   // mm/min per source line, where deviation was held
  double normalAcceleration = 0;  // mm/s^2, no bend run faster: the servo's deviation held
  double ramp = 0;                // mm/s^2, ramps between interval feeds
  PathShape shape = PathShape::Fitted;
  bool programmedFeed = false;    // the program's feed kept: the NC's planner sets the speed
  double feedCap = 0;             // mm/min, with programmedFeed: no faster (0: no cap)
};

// `tube`: mm, how far a path drawn taut or rounded may stray.
std::string describe(const Candidate& c, double tube) {
  return fmt::format("{}{}{}{}{}{}{}",
                     c.programmedFeed && c.feedCap > 0 ? fmt::format("the program's feed capped at {:.0f} mm/min", std::floor(c.feedCap))
                     : c.programmedFeed                ? std::string("the program's feed kept")
                     : c.rule == CrossPassRule::None   ? "each pass its own interval feeds"
                     : c.rule == CrossPassRule::Median ? "interval feeds planned across passes (median)"
                                                       : "interval feeds planned across passes (slowest)",
                     c.fine ? fmt::format(", characteristic points within {:g} mm", kFineCharacteristicError) : "",
                     c.ceilings.empty() ? "" : ", slowed where the servo deviated more than before",
                     c.normalAcceleration > 0
                         ? fmt::format(", bends within the servo's deviation ({:.0f} mm/s^2)", c.normalAcceleration)
                         : "",
                     c.ramp > 0 ? fmt::format(", ramps of {:g} mm/s^2", c.ramp) : "",
                     c.shape == PathShape::DrawnTaut        ? fmt::format(", points drawn taut within {:g} mm", tube)
                     : c.shape == PathShape::Eased          ? fmt::format(", bends eased in and out within {:g} mm", tube)
                     : c.shape == PathShape::CornersRounded ? fmt::format(", corners rounded within {:g} mm", tube)
                                                            : "",
                     c.share < 1 ? fmt::format(", at {:.0f} %", 100 * c.share) : "");
}

// The candidates tried, their outcomes, and the choice among those kept.
class ClosedLoop {
 public:
  ClosedLoop(const std::string& text, Baseline& baseline, const Machine& machine, const RegionRequest& request,
             const ProgressCallback& progress)
      : text_(text), baseline_(baseline), machine_(machine), request_(request), progress_(progress) {}

  // Simulates and judges a candidate unless it writes a program already judged; returns it
  // when it was simulated.
  const RegionOptimisation* judge(const Candidate& c, bool evenIfRepeated = false) {
    RegionRequest candidate = request_;
    // Every candidate is measured in one box, so that their figures compare: the one asked
    // for, else the first candidate's (where the paper's steps re-fit the path).
    if (!candidate.box) candidate.box = judgedBox_;
    // Gentle ramps where the figures are taken, and on the pass beyond each side of the box, so
    // that the passes measured there have neighbours ramped as they are; elsewhere quicker ones
    // cost less time.
    candidate.options.rampBox = candidate.box;
    if (candidate.box) {
      const Vec3 reach = Vec3(1, 1, 0) * kRampBoxReach * baseline_.passSpacing;
      candidate.options.rampBox = std::make_pair(candidate.box->first - reach, candidate.box->second + reach);
    }
    // A box asked for (or the worst region's) is also the stretch of a raster's passes re-planned
    // (a loop around a part has no stretch across a box).
    if (baseline_.run.passes.pattern == PathPattern::DirectionParallel) candidate.options.planBox = request_.box;
    candidate.options.feedScale = request_.options.feedScale * c.share;
    candidate.options.crossPass = c.rule;
    candidate.options.lineFeedCeiling = c.ceilings;
    candidate.options.normalAccelerationLimit = c.normalAcceleration;
    candidate.options.rampAcceleration = c.ramp;
    candidate.options.shape = c.shape;
    candidate.options.programmedFeed = c.programmedFeed;
    candidate.options.feedCap = c.feedCap;
    if (c.fine) candidate.options.thresholds.error = std::min(candidate.options.thresholds.error, kFineCharacteristicError);
    OptimizeResult result = optimizeRegion(text_, baseline_.program, request_.lines, machine_, candidate.options);
    const bool repeated = std::find(judged_.begin(), judged_.end(), result.text) != judged_.end();
    if (repeated && !evenIfRepeated) return nullptr;
    const double step = 1.0 / kExpectedCandidates;
    const double at = std::min(1.0 - step, step * double(judged_.size()));
    if (!repeated) judged_.push_back(result.text);
    if (request_.onCandidate)
      request_.onCandidate(fmt::format("candidate {}: {}", ++simulated_, describe(c, candidate.options.maximumDeviation)));
    last_ = RegionOptimisation{};  // its run is let go (unless kept as the best) before the next one is made
    last_ = evaluateCandidate(std::move(result), baseline_, machine_, candidate, progressStage(progress_, at, at + step));
    last_.plan = describe(c, candidate.options.maximumDeviation);
    if (!judgedBox_) judgedBox_ = std::make_pair(last_.lower, last_.upper);
    if (!repeated) outcomes_.push_back({last_.plan, last_.kept, last_.reason, last_.timeAfter, last_.regionAfter, last_.wholeAfter});
    if (last_.kept && (!best_ || betterFor(request_.objective, last_, *best_))) best_ = last_;
    // The first candidate is reported only when none is kept: its run is not held beside them.
    if (!first_ && !best_ && !last_.kept) first_ = last_;
    if (best_) first_.reset();
    return &last_;
  }

  RegionOptimisation result() {
    RegionOptimisation chosen = best_ ? std::move(*best_) : std::move(*first_);
    chosen.candidates = std::move(outcomes_);
    return chosen;
  }

 private:
  static constexpr std::size_t kExpectedCandidates = 40;
  const std::string& text_;
  Baseline& baseline_;
  const Machine& machine_;
  const RegionRequest& request_;
  const ProgressCallback& progress_;
  std::size_t simulated_ = 0;
  std::vector<std::string> judged_;  // texts already simulated: a rule that changes no feed repeats one
  std::vector<RegionOptimisation::Outcome> outcomes_;
  RegionOptimisation last_;
  std::optional<RegionOptimisation> best_, first_;
  std::optional<std::pair<Vec3, Vec3>> judgedBox_;  // mm, where the candidates are measured
};

Candidate shapeCandidate(PathShape shape, double feedCap = 0) {
  Candidate c{CrossPassRule::None, 1.0, false, {}};
  c.shape = shape;
  c.programmedFeed = true;
  c.feedCap = feedCap;
  return c;
}

// Last, the program's own path drawn anew within the tube and its feed kept: no longer the
// paper's fit, but what makes a program whose corners the machine brakes at (a relief whose
// points step up and down at every point, a grid of points whose slope changes at each) any
// smoother and faster. Where that run is faster, its speed now peaks between the corners it
// no longer brakes at, and swings more: the peaks are trimmed by capping the feed
// (speedPeakCaps), from the highest cap down, until a cap makes the program slower (a lower
// one would be slower still).
void judgeShapeCandidates(ClosedLoop& loop, PathShape shape) {
  const RegionOptimisation* drawn = loop.judge(shapeCandidate(shape));
  if (!drawn || !(drawn->timeAfter < drawn->timeBefore)) return;
  for (const double cap : speedPeakCaps(*drawn)) {
    const RegionOptimisation* capped = loop.judge(shapeCandidate(shape, cap));
    if (capped && slower(*capped)) return;
  }
}

// The bends eased in and out (eased_path.h), the program's feed kept but no bend run faster than
// `limit` (mm/s^2), with ramps of `ramp`. The servo deviates in proportion to the normal
// acceleration, and eased bends, which it enters without a step, may leave it below what the
// program deviated: the bound is then raised by the room left (a faster program, figures that
// may still hold); where they deviated more (the servo also lags while the speed changes in a
// bend), it is lowered by the excess; each run judged, kBoundRounds times at most. Returns
// whether every run was slower than the objective allows: gentler ramps would take longer still.
bool judgeEasedBends(ClosedLoop& loop, double limit, double ramp) {
  auto candidate = [&](double bound) { return Candidate{CrossPassRule::None, 1.0, false, {}, bound, ramp, PathShape::Eased, true}; };
  const RegionOptimisation* eased = loop.judge(candidate(limit));
  if (!eased) return false;
  bool allSlower = slower(*eased);
  auto room = [](const QualityFigures& before, const QualityFigures& after) {
    return after.deviationP99 > 0 ? before.deviationP99 / after.deviationP99 : 1.0;
  };
  for (int round = 0; round < kBoundRounds; ++round) {
    // Past the first move, only a run close to the program's time is worth moving again: each
    // round is a simulation, and one that took much longer (cameo.nc's eased bends: +8 % after
    // the first) is not brought back by a bound that moves by the deviation's room.
    if (round > 0 && eased->timeAfter > eased->timeBefore * (1 + kBoundRoundsWithin)) break;
    const double scale = eased->regionAfter.hasDeviation ? std::min(room(eased->regionBefore, eased->regionAfter),
                                                                     room(eased->wholeBefore, eased->wholeAfter))
                                                         : 1.0;
    if (!(scale > 0) || !(std::fabs(scale - 1) > kGainRequired)) break;
    limit *= scale;
    eased = loop.judge(candidate(limit));
    // A bound that binds nowhere either way writes the same program again: nothing more to learn.
    if (!eased) break;
    allSlower = allSlower && slower(*eased);
  }
  return allSlower;
}

// The eased bends with ramps from the fastest to the gentlest, until a run is slower than the
// objective allows; then the step between the gentlest ramps in time and the first too slow
// halved (in ratio) kRampRefinements times. The time a program's own braking loses is what the
// ramps may spend, and it is not a step of the list: the gentlest ramps that spend no more
// even the speed the most.
void judgeGentlestEasedRamps(ClosedLoop& loop, double limit) {
  double inTime = 0, tooSlow = 0;  // mm/s^2
  for (const double ramp : kRampAccelerations) {
    if (judgeEasedBends(loop, limit, ramp)) {
      tooSlow = ramp;
      break;
    }
    inTime = ramp;
  }
  for (int k = 0; k < kRampRefinements && inTime > 0 && tooSlow > 0; ++k) {
    const double ramp = std::round(std::sqrt(inTime * tooSlow));
    if (ramp >= inTime || ramp <= tooSlow) break;
    (judgeEasedBends(loop, limit, ramp) ? tooSlow : inTime) = ramp;
  }
}

}  // namespace

RegionOptimisation optimiseRegion(const std::string& text, const Program& program, const SurfaceRun& before,
                                  const Machine& machine, const RegionRequest& request, const ProgressCallback& progress) {
  requireSurface(before, program.source);
  // The closed loop. The paper's plan first (each pass its own interval feeds); when the
  // simulation finds it worse, the feeds planned across passes (the median of the passes
  // around, then their slowest). Then every bend planned to the normal acceleration at which
  // the machine's servo deviates as much as the program's own run did, with ramps into and out
  // of the bends (feed_ramps.h), from the fastest to the gentlest; the same with the bends eased
  // in and out of their straights (eased_path.h) and the program's feed, down to the gentlest
  // ramps in time (judgeGentlestEasedRamps). Then, where the servo deviated
  // more than before (the smooth new path is run faster through bends where the old one braked
  // at every point), characteristic points at a finer scale, so that a bend between long moves is an interval
  // of its own, and its bends slowed until the deviation is back (kDeviationRounds at most).
  // Then a little below the plan, and last the corners rounded and the points drawn taut
  // (rounded_corners.h, taut_path.h), each with its speed peaks trimmed. Each distinct
  // candidate is simulated and judged; the objective chooses among those no worse than the
  // program. When none is, the first one's figures and reason are reported.
  Baseline baseline(text, program, before);
  ClosedLoop loop(text, baseline, machine, request, progress);
  std::vector<CrossPassRule> tooSlow;  // rules whose full feeds already took longer
  std::optional<double> deviationTarget;  // um: what the program's own run deviates by (p99)
  for (const CrossPassRule rule : {CrossPassRule::None, CrossPassRule::Median, CrossPassRule::Envelope}) {
    const RegionOptimisation* r = loop.judge({rule, 1.0, false, {}});
    if (r && !r->kept && slower(*r)) tooSlow.push_back(rule);
    if (r && !deviationTarget && r->regionBefore.hasDeviation)
      deviationTarget = std::min(r->regionBefore.deviationP99, r->wholeBefore.deviationP99);
  }
  const double limit = deviationTarget ? kServoBoundShare * *deviationTarget / servoDeviationPerNormalAcceleration(machine) : 0.0;
  // A run that deviated by nothing (feedback equal to the command) gives no bound to plan to.
  // From the fastest ramps to the gentlest, until a run is slower than the objective allows:
  // gentler ramps would only take longer still.
  if (std::isfinite(limit) && limit > 0) {
    for (const double ramp : kRampAccelerations) {
      const RegionOptimisation* bends = loop.judge({CrossPassRule::None, 1.0, true, {}, limit, ramp});
      if (bends && slower(*bends)) break;
    }
    judgeGentlestEasedRamps(loop, limit);
  }
  const RegionOptimisation* fine = loop.judge({CrossPassRule::None, 1.0, true, {}}, true);
  if (fine && fine->regionBefore.hasDeviation) {
    const double target = std::min(fine->regionBefore.deviationP99, fine->wholeBefore.deviationP99);
    std::vector<double> ceilings;
    for (int round = 0; round < kDeviationRounds && fine; ++round) {
      ceilings = deviationCeilings(*fine, target, ceilings);
      fine = loop.judge({CrossPassRule::None, 1.0, true, ceilings});
    }
  }
  for (const CrossPassRule rule : {CrossPassRule::None, CrossPassRule::Median}) {
    // Lower feeds can only take longer still.
    if (std::find(tooSlow.begin(), tooSlow.end(), rule) != tooSlow.end()) continue;
    loop.judge({rule, 0.95, false, {}});
  }
  judgeShapeCandidates(loop, PathShape::CornersRounded);
  judgeShapeCandidates(loop, PathShape::DrawnTaut);
  if (progress) progress(1.0);
  return loop.result();
}

std::optional<std::string> whyNotKept(const RegionOptimisation& r) {
  if (slower(r)) return fmt::format("the program would take longer ({:.3f} -> {:.3f} s)", r.timeBefore, r.timeAfter);
  if (r.maxPathDistance > kPathMoveAllowed)
    return fmt::format("the path would move by {:.4f} mm, more than {:g} mm", r.maxPathDistance, kPathMoveAllowed);
  // A region that cannot be measured after cannot be said to be no worse.
  if (r.regionBefore.samples > 0 && r.regionAfter.samples == 0) return std::string("the region has no surface after");
  if (const std::string worse = worseFigure(r.regionBefore, r.regionAfter, kWorseningAllowed); !worse.empty())
    return "in the region, " + worse;
  if (const std::string worse = worseFigure(r.wholeBefore, r.wholeAfter, kWorseningAllowed); !worse.empty())
    return "over the whole program, " + worse;
  if (r.regionTimeAfter > r.regionTimeBefore * (1 - kGainRequired) &&
      betterFigure(r.regionBefore, r.regionAfter, kGainRequired).empty())
    return fmt::format("it would help nothing: neither the time on the region's lines ({:.3f} -> {:.3f} s) nor any "
                       "figure of the region is better by {:g} % or more",
                       r.regionTimeBefore, r.regionTimeAfter, 100 * kGainRequired);
  return std::nullopt;
}

const char* objectiveName(Objective objective) {
  switch (objective) {
    case Objective::Time: return "time";
    case Objective::Quality: return "quality";
    case Objective::Balanced: break;
  }
  return "balanced";
}

std::string regionFigures(const RegionOptimisation& r) {
  const QualityFigures &a = r.regionBefore, &b = r.regionAfter;
  return fmt::format(
      "lines {}-{}: {} re-fitted. Machining time {:.3f} -> {:.3f} s. In the region: speed fluctuation "
      "{:.1f} -> {:.1f} mm/min, inconsistency between passes p99 {:.1f} -> {:.1f} mm/min (mean {:.1f} -> {:.1f}), "
      "jerk p99 {:.0f} -> {:.0f} mm/s^3{}; programmed path moved {:.4f} mm at most; program {} -> {} lines{} ({})",
      r.lines.first, r.lines.last,
      r.result.passes.size() == 1 ? std::string("1 pass") : fmt::format("{} passes", r.result.passes.size()), r.timeBefore, r.timeAfter, a.speedFluctuation,
      b.speedFluctuation, a.inconsistencyP99, b.inconsistencyP99, a.inconsistencyMean, b.inconsistencyMean, a.jerkP99,
      b.jerkP99,
      a.hasDeviation && b.hasDeviation
          ? fmt::format(", predicted deviation p99 {:.2f} -> {:.2f} \u00b5m", a.deviationP99, b.deviationP99)
          : "",
      r.maxPathDistance, r.linesBefore, r.linesAfter,
      r.linesBefore > 0 && r.linesAfter > r.linesBefore ? fmt::format(" (x{:.1f})", double(r.linesAfter) / double(r.linesBefore))
                                                         : "",
      r.plan);
}

std::string regionVerdict(const RegionOptimisation& r) {
  return r.kept ? fmt::format("Kept ({}): {}no figure worse by more than {:g} %", objectiveName(r.objective),
                              r.objective == Objective::Quality
                                  ? fmt::format("at most {:g} % slower, ", 100 * kQualitySlowdownAllowed)
                                  : std::string("not slower, "),
                              100 * kWorseningAllowed)
                : fmt::format("Not kept ({}): {}; the program is left as it was", objectiveName(r.objective), r.reason);
}

std::string regionSummary(const RegionOptimisation& r) { return regionFigures(r) + ". " + regionVerdict(r); }

}  // namespace isurface
