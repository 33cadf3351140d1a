#pragma once
// Comparing two runs of the same program (before and after an optimisation, a simulation and a
// machine's recording): run B is aligned to run A line by line, by the arc length travelled
// since each run's first sample of the line, and the differences in time, speed and position
// are reported per line, per range of consecutive lines and per sample of A (for a map).
//
// Differences are B minus A: a positive time difference means B spent longer on the line, a
// positive speed difference that B was faster at the same place.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "isurface/base/trajectory.h"

namespace isurface {

struct RunComparisonOptions {
  // Consecutive lines whose time differences have the same sign (beyond timeTolerance) form a
  // range; a range also ends after this many lines.
  std::size_t maxRangeLines = 20;
  double timeTolerance = 0.002;  // s; a line whose |time difference| is within it counts as equal
  // Lines compared as one, for runs of programs numbered differently (a re-optimised region:
  // its passes replaced by other lines, the lines after them shifted). When not empty,
  // lineKeyA[line] is the key under which run A's line is aligned (lines past the end keep
  // their own number; key 0 leaves the line out), lineKeyB likewise for run B. The samples of a
  // key are aligned by arc length from each run's first sample of it, and the results name
  // keys where they name lines. Empty: every line is its own key.
  std::vector<std::uint32_t> lineKeyA, lineKeyB;
};

// Figures shared by a line and a range of lines.
struct DifferenceFigures {
  double timeA = 0, timeB = 0;      // s spent on the line(s)
  double timeDifference = 0;        // s, B - A
  double lengthA = 0, lengthB = 0;  // mm of path travelled
  double meanSpeedDifference = 0;   // mm/min, B - A, averaged over A's samples
  double maxSpeedDifference = 0;    // mm/min, the signed B - A of largest magnitude
  double maxPositionDistance = 0;   // mm, commanded positions at the same arc length
  double maxPathDistance = 0;       // mm, A's commanded point to B's commanded path nearby
  std::optional<double> maxFeedbackDistance;  // mm, when both runs have feedback
  std::size_t samplesA = 0, samplesB = 0;
  std::size_t comparedSamples = 0;  // samples of A with a finite speed difference
};

struct LineDifference {
  std::uint32_t line = 0;  // 1-based G-code line
  DifferenceFigures figures;
};

struct RangeDifference {
  std::uint32_t firstLine = 0, lastLine = 0;  // inclusive, in A's order
  std::size_t lineCount = 0;
  DifferenceFigures figures;
};

// A line that only one of the runs has samples of (a blending control may run a short line
// inside a blend and never report it). It is compared as part of `mergedInto`, the line both
// runs have that comes before it in its run (the first such line when none comes before), so
// that the totals cover the whole motion of both runs.
struct UnmatchedLine {
  std::uint32_t line = 0;
  std::size_t samples = 0;
  double time = 0;  // s
  std::uint32_t mergedInto = 0;
};

// What the ranges are ranked by (and a map is coloured by).
enum class ComparisonQuantity { Speed, Position, Time };
const char* comparisonQuantityName(ComparisonQuantity q);  // "speed", "position", "time"
std::optional<ComparisonQuantity> parseComparisonQuantity(const std::string& name);
const char* comparisonQuantityLabel(ComparisonQuantity q);  // legend title
const char* comparisonQuantityUnit(ComparisonQuantity q);   // "mm/min", "mm", "s"

struct RunComparison {
  std::vector<LineDifference> lines;        // lines both runs have (with the lines merged into
                                            // them), in A's order
  std::vector<RangeDifference> ranges;      // consecutive common lines grouped, in A's order
  std::vector<UnmatchedLine> onlyInA, onlyInB;
  DifferenceFigures total;                  // over every line: the whole motion of both runs
  double durationA = 0, durationB = 0;      // s, first to last sample with a line
  double coverageA = 0, coverageB = 0;      // share of each run's samples with a line on lines
                                            // both runs have
  bool feedbackCompared = false;
  double cycleA = 0.001;                    // s

  // Per sample of A (NaN where the sample has no line both runs share):
  std::vector<float> speedDifference;       // mm/min, B - A at the same arc length
  std::vector<float> positionDistance;      // mm, commanded, at the same arc length
  std::vector<float> timeDifference;        // s, B's time at that place minus A's, both from
                                            // their first sample with a line

  const std::vector<float>& sampleValues(ComparisonQuantity q) const;
  // Indices into `ranges`, most severe first for the quantity (|time difference|, largest
  // |speed difference|, largest position distance), at most `count`.
  std::vector<std::size_t> worstRanges(ComparisonQuantity q, std::size_t count) const;
};

// Throws InputError naming both sources when either run has no line channel or the runs share
// no line with samples.
RunComparison compareRuns(const Trajectory& a, const Trajectory& b, const RunComparisonOptions& options = {});

}  // namespace isurface
