// Aligning run B to run A per G-code line by arc length, and the per-sample and per-line
// differences. Grouping lines into ranges and ranking them is in run_comparison_ranges.cpp.
#include "isurface/analysis/run_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "isurface/base/diagnostic.h"
#include "isurface/analysis/quantities.h"
#include "run_comparison_figures.h"

namespace isurface {

namespace {

constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();
// How far along B's path (mm of arc length either side of the aligned point) the nearest
// point of B's path is looked for, on top of the difference between the runs' lengths of the
// line (a blend cutting a corner shortens a line by up to a few mm): more than the line
// handover of blending controllers (LinuxCNC's is under a millimetre at ordinary feeds), less
// than a typical pass.
constexpr double kPathSearchRadius = 2.0;
// At most this much (mm) is added to it for a line one run travels further on than the other:
// a line with others merged into it (see mergeLinesOnlyHere) may be metres longer in one run,
// and the search is linear in its radius.
constexpr double kLargestLengthAllowance = 10.0;

// The samples of every line of a run, grouped by line (CSR layout over the lines that occur,
// so that a line numbered 4294967295 costs what line 1 does), and the run's own timing.
struct LineIndex {
  std::vector<std::uint32_t> lines;  // the line numbers that occur, ascending
  std::vector<std::size_t> offsets;  // per entry of `lines`, plus the end
  std::vector<std::size_t> samples;  // sample indices, by line then in time order
  std::vector<std::uint32_t> order;  // lines in the order of their first sample
  double firstTime = 0, lastTime = 0;

  // The entry of `line` in `lines`, or lines.size() when it does not occur.
  std::size_t slot(std::uint32_t line) const {
    const auto it = std::lower_bound(lines.begin(), lines.end(), line);
    return it != lines.end() && *it == line ? std::size_t(it - lines.begin()) : lines.size();
  }
  std::size_t count(std::uint32_t line) const {
    const std::size_t k = slot(line);
    return k < lines.size() ? offsets[k + 1] - offsets[k] : 0;
  }
  const std::size_t* begin(std::uint32_t line) const { return samples.data() + offsets[slot(line)]; }
};

// The key a line of a run is compared under: the caller's (RunComparisonOptions::lineKeyA), then,
// for a key only this run has, the common key it is merged into.
struct LineKeys {
  const std::vector<std::uint32_t>& given;
  std::unordered_map<std::uint32_t, std::uint32_t> mergedInto;
  std::uint32_t operator()(std::uint32_t line) const {
    const std::uint32_t key = line != 0 && line < given.size() ? given[line] : line;
    const auto merged = mergedInto.find(key);
    return merged == mergedInto.end() ? key : merged->second;
  }
};

// The index speaks of keys where it says lines.
LineIndex indexLines(const Trajectory& t, const LineKeys& keyOf) {
  LineIndex index;
  // Samples come in runs of one line: the run's slot is looked up once.
  std::uint32_t lastLine = 0;
  std::size_t lastSlot = 0;
  const auto slotOf = [&](std::uint32_t line) {
    if (line != lastLine) lastLine = line, lastSlot = index.slot(line);
    return lastSlot;
  };
  t.line.forEachRun([&](std::uint32_t value, std::size_t, std::size_t) {
    if (const std::uint32_t line = keyOf(value); line != 0 && (index.lines.empty() || index.lines.back() != line))
      index.lines.push_back(line);
  });
  std::sort(index.lines.begin(), index.lines.end());
  index.lines.erase(std::unique(index.lines.begin(), index.lines.end()), index.lines.end());
  index.offsets.assign(index.lines.size() + 1, 0);
  bool started = false;
  t.line.forEachRun([&](std::uint32_t value, std::size_t begin, std::size_t end) {
    const std::uint32_t line = keyOf(value);
    if (line == 0) return;
    std::size_t& count = index.offsets[slotOf(line) + 1];
    if (count == 0) index.order.push_back(line);
    count += end - begin;
    if (!started) index.firstTime = t.timeAt(begin), started = true;
    index.lastTime = t.timeAt(end - 1);
  });
  for (std::size_t k = 1; k < index.offsets.size(); ++k) index.offsets[k] += index.offsets[k - 1];
  std::vector<std::size_t> fill(index.offsets.begin(), index.offsets.end() - 1);
  index.samples.resize(index.offsets.back());
  t.line.forEachRun([&](std::uint32_t value, std::size_t begin, std::size_t end) {
    if (const std::uint32_t line = keyOf(value); line != 0)
      for (std::size_t i = begin; i < end; ++i) index.samples[fill[slotOf(line)]++] = i;
  });
  return index;
}

// The time sample i stands for: up to the next sample (the last one: one cycle).
double sampleDuration(const Trajectory& t, std::size_t i) {
  const double dt = i + 1 < t.size() ? t.timeAt(i + 1) - t.timeAt(i) : t.cycle;
  return std::isfinite(dt) && dt > 0 ? dt : 0.0;
}

double stepLength(const Trajectory& t, std::size_t from, std::size_t to) {
  const double d = (t.commanded(to) - t.commanded(from)).norm();
  return std::isfinite(d) ? d : 0.0;
}

// Arc length (mm) from the line's first sample; only steps between consecutive samples count,
// so that a line visited twice does not count the jump between its visits.
std::vector<double> lineArcLength(const Trajectory& t, const std::size_t* samples, std::size_t n) {
  std::vector<double> s(n, 0.0);
  for (std::size_t k = 1; k < n; ++k)
    s[k] = s[k - 1] + (samples[k] == samples[k - 1] + 1 ? stepLength(t, samples[k - 1], samples[k]) : 0.0);
  return s;
}

std::vector<double> cumulativeArcLength(const Trajectory& t) {
  std::vector<double> s(t.size(), 0.0);
  for (std::size_t i = 1; i < t.size(); ++i) s[i] = s[i - 1] + stepLength(t, i - 1, i);
  return s;
}

// Where B is at an arc length of a line: between two of its samples, by a fraction.
struct Aligned {
  std::size_t from = 0, to = 0;
  double fraction = 0;
  template <class F>
  double at(F value) const { return value(from) + fraction * (value(to) - value(from)); }
};

// B at arc length s of its line. Where B stands still at s (several samples share it), the
// sample as far through that stand as A's sample is through its own: `stand` is A's sample's
// position in A's stand at s, 0 to 1.
Aligned alignAt(const std::vector<double>& arc, const std::size_t* samples, double s, double stand) {
  const std::size_t n = arc.size();
  const auto first = std::lower_bound(arc.begin(), arc.end(), s);
  const std::size_t k = std::size_t(first - arc.begin());
  // Beyond the end of B's line (A travelled further on it): B's last sample of the line.
  if (k >= n) return {samples[n - 1], samples[n - 1], 0.0};
  if (arc[k] == s || k == 0) {
    const std::size_t last = std::size_t(std::upper_bound(first, arc.end(), arc[k]) - arc.begin()) - 1;
    const std::size_t at = k + std::size_t(std::lround(stand * double(last - k)));
    return {samples[at], samples[at], 0.0};
  }
  const double span = arc[k] - arc[k - 1];
  return {samples[k - 1], samples[k], span > 0 ? std::clamp((s - arc[k - 1]) / span, 0.0, 1.0) : 1.0};
}

// For each sample of a line, how far through a stand (samples sharing its arc length) it is.
std::vector<double> standFractions(const std::vector<double>& arc) {
  std::vector<double> out(arc.size(), 0.0);
  for (std::size_t begin = 0; begin < arc.size();) {
    std::size_t end = begin + 1;
    while (end < arc.size() && arc[end] == arc[begin]) ++end;
    for (std::size_t k = begin; k < end; ++k) out[k] = end - begin > 1 ? double(k - begin) / double(end - begin - 1) : 0.0;
    begin = end;
  }
  return out;
}

class Aligner {
 public:
  Aligner(const Trajectory& a, const Trajectory& b, RunComparison& out)
      : a_(a), b_(b), out_(out), speedA_(sampleQuantity(Quantity::Speed, a)),
        speedB_(sampleQuantity(Quantity::Speed, b)), pathB_(cumulativeArcLength(b)) {
    for (std::size_t j = 0; j + 1 < pathB_.size(); ++j)
      if (pathB_[j + 1] > pathB_[j]) movingB_.push_back(j);
  }

  LineDifference compareLine(std::uint32_t line, const LineIndex& ia, const LineIndex& ib) {
    const std::size_t* sa = ia.begin(line);
    const std::size_t* sb = ib.begin(line);
    const std::size_t na = ia.count(line), nb = ib.count(line);
    const std::vector<double> arcA = lineArcLength(a_, sa, na), arcB = lineArcLength(b_, sb, nb);
    const std::vector<double> standA = standFractions(arcA);
    searchRadius_ = kPathSearchRadius + std::min(std::abs(arcA.back() - arcB.back()), kLargestLengthAllowance);
    FigureAccumulator acc;
    for (std::size_t k = 0; k < na; ++k) acc.addTime(sampleDuration(a_, sa[k]), 0.0);
    for (std::size_t k = 0; k < nb; ++k) acc.addTime(0.0, sampleDuration(b_, sb[k]));
    acc.setLengths(arcA.back(), arcB.back(), na, nb);
    for (std::size_t k = 0; k < na; ++k) {
      const std::size_t i = sa[k];
      const Aligned at = alignAt(arcB, sb, arcA[k], standA[k]);
      const Vec3 pb(at.at([&](std::size_t j) { return b_.x[j]; }), at.at([&](std::size_t j) { return b_.y[j]; }),
                    at.at([&](std::size_t j) { return b_.z[j]; }));
      const double speed = at.at([&](std::size_t j) { return speedB_[j]; }) - speedA_[i];
      const double position = (pb - a_.commanded(i)).norm();
      const double timeB = at.at([&](std::size_t j) { return b_.timeAt(j); }) - ib.firstTime;
      const double time = timeB - (a_.timeAt(i) - ia.firstTime);
      out_.speedDifference[i] = std::isfinite(speed) ? float(speed) : kNoValue;
      out_.positionDistance[i] = std::isfinite(position) ? float(position) : kNoValue;
      out_.timeDifference[i] = std::isfinite(time) ? float(time) : kNoValue;
      acc.addSample(speed, position, pathDistance(a_.commanded(i), at));
      if (out_.feedbackCompared) {
        const Vec3 fb(at.at([&](std::size_t j) { return b_.feedback(j).x(); }),
                      at.at([&](std::size_t j) { return b_.feedback(j).y(); }),
                      at.at([&](std::size_t j) { return b_.feedback(j).z(); }));
        acc.addFeedbackDistance((fb - a_.feedback(i)).norm());
      }
    }
    return LineDifference{line, acc.figures(out_.feedbackCompared)};
  }

 private:
  // Distance from A's point to B's commanded path within searchRadius_ of arc length of the
  // aligned point: how far the paths themselves differ, whatever the timing along them.
  double pathDistance(const Vec3& p, const Aligned& at) const {
    if (!p.allFinite()) return std::numeric_limits<double>::quiet_NaN();
    const double s = at.at([&](std::size_t j) { return pathB_[j]; });
    // Only the steps where B moved are segments: a run standing at one point for a million
    // samples must not be walked for each of A's samples.
    auto k = std::lower_bound(movingB_.begin(), movingB_.end(), s - searchRadius_,
                              [&](std::size_t j, double value) { return pathB_[j + 1] < value; });
    double best = (p - b_.commanded(at.from)).norm();
    for (; k != movingB_.end() && pathB_[*k] <= s + searchRadius_; ++k)
      best = std::min(best, distanceToSegment(p, b_.commanded(*k), b_.commanded(*k + 1)));
    return best;
  }

  const Trajectory& a_;
  const Trajectory& b_;
  RunComparison& out_;
  std::vector<double> speedA_, speedB_;  // mm/min, path speed per sample of each run
  std::vector<double> pathB_;            // mm, B's arc length at each sample
  std::vector<std::size_t> movingB_;     // the samples j where B moves on to j + 1
  double searchRadius_ = kPathSearchRadius;  // mm, for the line being compared
};

void requireLines(const Trajectory& t) {
  if (t.size() == 0) throw InputError(Diagnostic{t.source, 0, 0, "has no samples: there is no run to compare"});
  bool any = false;
  for (std::size_t r = 0; r < t.line.runCount(); ++r) any = any || t.line.runValue(r) != 0;
  if (!t.hasLine)
    throw InputError(Diagnostic{t.source, 0, 0,
                                "no G-code line channel to align by (import the trace with --gcode to map its samples to lines)"});
  if (!any)
    throw InputError(Diagnostic{t.source, 0, 0,
                                "its line channel is 0 (no line) on every sample: nothing to align by (import the trace "
                                "with --gcode to map its samples to lines)"});
}

// The share of a run's samples with a line that lie on lines both runs have.
double coverage(const LineIndex& index, const std::vector<UnmatchedLine>& onlyHere) {
  std::size_t alone = 0;
  for (const UnmatchedLine& u : onlyHere) alone += u.samples;
  const std::size_t all = index.samples.size();
  return all > 0 ? double(all - alone) / double(all) : 0.0;
}

UnmatchedLine unmatched(const Trajectory& t, const LineIndex& index, std::uint32_t line, std::uint32_t into) {
  UnmatchedLine u{line, index.count(line), 0.0, into};
  for (std::size_t k = 0; k < u.samples; ++k) u.time += sampleDuration(t, index.begin(line)[k]);
  return u;
}

// A blending control runs a short line inside a blend with its neighbours and may never report
// it, so a line (key) one run has and the other has not is compared as part of the common line
// before it in that run's order (the first common one when none comes before): the totals
// then cover the whole motion of both runs. Returns the lines merged, in the run's order.
std::vector<UnmatchedLine> mergeLinesOnlyHere(const Trajectory& t, const LineIndex& here, const LineIndex& there,
                                              LineKeys& keys) {
  std::vector<UnmatchedLine> merged;
  std::uint32_t lastCommon = 0;
  std::vector<std::uint32_t> beforeFirstCommon;
  for (std::uint32_t line : here.order) {
    if (there.count(line) != 0) {
      if (lastCommon == 0)
        for (std::uint32_t early : beforeFirstCommon) keys.mergedInto[early] = line;
      lastCommon = line;
      continue;
    }
    if (lastCommon == 0) beforeFirstCommon.push_back(line);
    else keys.mergedInto[line] = lastCommon;
  }
  for (std::uint32_t line : here.order)
    if (const auto into = keys.mergedInto.find(line); into != keys.mergedInto.end())
      merged.push_back(unmatched(t, here, line, into->second));
  return merged;
}

// Both runs indexed by keys that both have.
RunComparison compareMerged(const Trajectory& a, const Trajectory& b, const LineIndex& ia, const LineIndex& ib,
                            const RunComparisonOptions& options) {
  RunComparison out;
  out.cycleA = a.cycle;
  out.durationA = ia.lastTime - ia.firstTime;
  out.durationB = ib.lastTime - ib.firstTime;
  out.feedbackCompared = a.hasFeedback() && b.hasFeedback();
  out.speedDifference.assign(a.size(), kNoValue);
  out.positionDistance.assign(a.size(), kNoValue);
  out.timeDifference.assign(a.size(), kNoValue);
  Aligner aligner(a, b, out);
  for (std::uint32_t line : ia.order) out.lines.push_back(aligner.compareLine(line, ia, ib));
  groupRanges(out, options);
  return out;
}

}  // namespace

RunComparison compareRuns(const Trajectory& a, const Trajectory& b, const RunComparisonOptions& options) {
  requireLines(a);
  requireLines(b);
  LineKeys keysA{options.lineKeyA, {}}, keysB{options.lineKeyB, {}};
  const LineIndex givenA = indexLines(a, keysA), givenB = indexLines(b, keysB);
  if (!std::any_of(givenA.lines.begin(), givenA.lines.end(), [&](std::uint32_t key) { return givenB.count(key) != 0; }))
    throw InputError(Diagnostic{b.source, 0, 0, "shares no G-code line with " + a.source + ": nothing to compare"});
  std::vector<UnmatchedLine> onlyInA = mergeLinesOnlyHere(a, givenA, givenB, keysA);
  std::vector<UnmatchedLine> onlyInB = mergeLinesOnlyHere(b, givenB, givenA, keysB);
  RunComparison out = onlyInA.empty() && onlyInB.empty()
                          ? compareMerged(a, b, givenA, givenB, options)
                          : compareMerged(a, b, indexLines(a, keysA), indexLines(b, keysB), options);
  out.coverageA = coverage(givenA, onlyInA);
  out.coverageB = coverage(givenB, onlyInB);
  out.onlyInA = std::move(onlyInA);
  out.onlyInB = std::move(onlyInB);
  return out;
}

}  // namespace isurface
