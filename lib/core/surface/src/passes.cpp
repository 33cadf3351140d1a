// Which samples cut the part, and splitting them into passes (patterns in pass_patterns.cpp).
//
// Samples are first grouped into pieces that stand for moves: the program's moves when it is
// known (by the block channel, else the first move of each sample's line), else runs of one
// G-code line, else runs of samples of one kind (rapid or not, vertical or not). A piece does
// not cut when it is
//   - a rapid: a G0 move; without a program, samples whose feed channel holds the rapid rate
//     (named in the dump's metadata, else a feed at least 3 times the typical one), or without
//     a feed channel, stretches whose speed rises above twice the typical moving speed, taken
//     out to the speed minima on either side (where the move begins and ends);
//   - a plunge or retract: a feed move that goes mostly vertical (|dz| > 0.9 x length), unless
//     it sits inside a pass (a wall crossed by a raster: the moves on both sides are horizontal
//     feed moves heading the same way);
//   - an air move: feed moves between a retract (a vertical link up) and a plunge (down), the
//     way CAM systems link passes at a clearance height without rapids.
// Dwells and moves of zero length take the state of the piece before them.
#include "isurface/surface/passes.h"

#include "isurface/base/diagnostic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "isurface/base/tolerances.h"
#include "isurface/gcode/path_segment.h"
#include "pass_split.h"

namespace isurface {

namespace passes_detail {
namespace {

constexpr std::uint32_t kNoMove = std::numeric_limits<std::uint32_t>::max();
constexpr double kVerticalShare = 0.9;     // |dz| above this share of a move's length: vertical
constexpr double kSameHeadingCos = 0.5;    // horizontal headings within 60 degrees continue a pass
constexpr double kRapidFeedRatio = 3.0;    // a feed this many times the typical one is the rapid rate
constexpr double kRapidSpeedRatio = 2.0;   // without feeds: faster than this many times typical

enum class PieceKind : std::uint8_t { Feed, Rapid, Still, Unknown };

// One a move: 48 bytes, 2 million of them for a 28-hour raster.
struct Piece {
  std::size_t begin = 0, end = 0;  // samples
  double dz = 0;                   // mm, end minus start
  // Unit horizontal directions (may be zero), only compared with each other: floats suffice.
  Eigen::Vector2f startHeading = Eigen::Vector2f::Zero(), endHeading = Eigen::Vector2f::Zero();
  PieceKind kind = PieceKind::Feed;
  bool vertical = false;
  bool cutting = true;
};

bool finite(const Trajectory& s, std::size_t i) {
  const double v = (s.x[i] - s.x[i]) + (s.y[i] - s.y[i]) + (s.z[i] - s.z[i]);
  return v == 0;
}

Eigen::Vector2f horizontal(const Vec3& v) {
  const double n = std::hypot(v.x(), v.y());
  return n > kLengthEpsilon ? Eigen::Vector2f(float(v.x() / n), float(v.y() / n)) : Eigen::Vector2f::Zero();
}

// --- pieces from the program --------------------------------------------------------------

// Calls f(move, begin, end) for each run of samples of one move (kNoMove: none): the block
// channel's when it matches the program, else the first move of the samples' line. Walks the
// channels' runs, never a copy per sample (400 MB on a 100 M-sample run).
template <typename F>
void forEachMoveRun(const Trajectory& s, const Program& program, F&& f) {
  const std::size_t n = s.size();
  const std::size_t moves = program.moves.size();
  bool blockUsable = s.block.size() == n && n > 0;
  if (blockUsable) {
    // A dump of another program has blocks that are out of range or sit on other lines.
    const std::size_t step = std::max<std::size_t>(1, n / 4096);
    RunChannel<std::uint32_t>::Cursor block = s.block.cursor(), line = s.line.cursor();
    for (std::size_t i = 0; i < n && blockUsable; i += step) {
      const std::uint32_t b = block[i];
      if (b >= moves || (line[i] != 0 && program.moves[b].line != line[i])) blockUsable = false;
    }
  }
  std::vector<std::uint32_t> firstMove;
  if (!blockUsable) {
    std::uint32_t maxLine = 0;
    for (const Move& m : program.moves) maxLine = std::max(maxLine, m.line);
    firstMove.assign(std::size_t(maxLine) + 1, kNoMove);
    for (std::size_t k = moves; k-- > 0;) firstMove[program.moves[k].line] = static_cast<std::uint32_t>(k);
  }
  const auto moveOf = [&](std::uint32_t value) {
    if (blockUsable) return value < moves ? value : kNoMove;
    return value != 0 && value < firstMove.size() ? firstMove[value] : kNoMove;
  };
  std::uint32_t current = kNoMove;
  std::size_t from = 0;
  const RunChannel<std::uint32_t>& channel = blockUsable ? s.block : s.line;
  const auto take = [&](std::uint32_t move, std::size_t begin) {
    if (begin > 0 && move == current) return;
    if (begin > 0) f(current, from, begin);
    current = move;
    from = begin;
  };
  channel.forEachRun(0, n, [&](std::uint32_t value, std::size_t begin, std::size_t) { take(moveOf(value), begin); });
  // Samples past the end of a shorter line channel have no move.
  if (channel.size() < n) take(kNoMove, channel.size());
  if (n > 0) f(current, from, n);
}

std::vector<Piece> piecesFromProgram(const Trajectory& s, const Program& program) {
  std::vector<Piece> pieces;
  // At most a piece a run of the channel the moves are read from: no doubling of 100 MB.
  pieces.reserve(std::max(s.line.runCount(), s.block.runCount()) + 1);
  forEachMoveRun(s, program, [&](std::uint32_t k, std::size_t begin, std::size_t end) {
    Piece p;
    p.begin = begin;
    p.end = end;
    if (k == kNoMove) {
      p.kind = PieceKind::Unknown;
    } else {
      const Move& move = program.moves[k];
      if (!move.isMotion()) {
        p.kind = PieceKind::Still;
      } else {
        const PathSegment geometry = PathSegment::from(program, k);
        p.kind = move.kind == MoveKind::Rapid ? PieceKind::Rapid : PieceKind::Feed;
        if (geometry.length <= kLengthEpsilon && p.kind == PieceKind::Feed) p.kind = PieceKind::Still;
        p.dz = geometry.end.z() - geometry.start.z();
        p.vertical = geometry.length > kLengthEpsilon && std::fabs(p.dz) > kVerticalShare * geometry.length;
        p.startHeading = horizontal(geometry.startTangent());
        p.endHeading = horizontal(geometry.endTangent());
      }
    }
    pieces.push_back(p);
  });
  return pieces;
}

// --- pieces from the samples alone --------------------------------------------------------

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// At most this many values are looked at to find a typical one.
constexpr std::size_t kTypicalSamples = 200000;

std::vector<char> rapidFromFeed(const Trajectory& s) {
  const std::size_t n = s.size();
  double rapid = s.rapidFeed;
  if (!(rapid > 0)) {
    double highest = 0;
    std::vector<double> seen;
    const std::size_t step = std::max<std::size_t>(1, n / kTypicalSamples);
    RunChannel<float>::Cursor feed = s.feed.cursor();
    for (std::size_t i = 0; i < n; ++i) {
      const double f = feed[i];
      if (f > highest) highest = f;
      if (i % step == 0 && f > 0) seen.push_back(f);
    }
    const double typical = median(std::move(seen));
    rapid = typical > 0 && highest >= kRapidFeedRatio * typical ? highest : 0;
  }
  std::vector<char> out(n, 0);
  // The feeds are floats: the rapid rate is compared as one too (12345.678 is not a float). A
  // feed above the rapid rate is a cutting move's (F999 in/min, "as fast as it goes", on a
  // machine whose rapid rate is 24 m/min), not a rapid one.
  // A few steps of a float either side of it (a writer that rounded the rate its own way).
  constexpr double kFloatSteps = 1e-6;
  const double rapidAsStored = static_cast<float>(rapid);
  if (rapid > 0)
    s.feed.forEachRun(0, n, [&](float f, std::size_t begin, std::size_t end) {
      std::fill(out.begin() + static_cast<std::ptrdiff_t>(begin), out.begin() + static_cast<std::ptrdiff_t>(end),
                char(std::fabs(f - rapidAsStored) <= rapidAsStored * kFloatSteps));
    });
  return out;
}

std::vector<char> rapidFromSpeed(const Trajectory& s) {
  const std::size_t n = s.size();
  std::vector<char> out(n, 0);
  if (n < 3) return out;
  std::vector<double> speed(n, 0);  // mm/s, central differences
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double dt = s.timeAt(i + 1) - s.timeAt(i - 1);
    const double d = (s.commanded(i + 1) - s.commanded(i - 1)).norm();
    speed[i] = dt > 0 && std::isfinite(d) ? d / dt : 0;
  }
  speed[0] = speed[1];
  speed[n - 1] = speed[n - 2];
  double highest = 0;
  for (double v : speed) highest = std::max(highest, v);
  std::vector<double> moving;
  const std::size_t step = std::max<std::size_t>(1, n / kTypicalSamples);
  for (std::size_t i = 0; i < n; i += step)
    if (speed[i] > 1e-3 * highest) moving.push_back(speed[i]);
  const double typical = median(std::move(moving));
  if (!(typical > 0)) return out;
  for (std::size_t i = 0; i < n; ++i) {
    if (out[i] || speed[i] <= kRapidSpeedRatio * typical) continue;
    // Out while the speed keeps falling: to where the rapid move starts and stops (a steady
    // speed, such as a cutting feed, is not taken in).
    std::size_t a = i, b = i;
    while (a > 0 && speed[a - 1] < speed[a]) --a;
    while (b + 1 < n && speed[b + 1] < speed[b]) ++b;
    std::fill(out.begin() + static_cast<std::ptrdiff_t>(a), out.begin() + static_cast<std::ptrdiff_t>(b + 1), 1);
  }
  return out;
}

// One piece per run of samples of one line (when lines are known) and one kind; without
// lines, runs where the motion is vertical or not are pieces of their own.
std::vector<Piece> piecesFromSamples(const Trajectory& s) {
  const std::size_t n = s.size();
  const std::vector<char> rapid = s.hasFeed() ? rapidFromFeed(s) : rapidFromSpeed(s);
  bool useLines = false;
  if (s.hasLine)
    s.line.forEachRun(0, n, [&](std::uint32_t line, std::size_t, std::size_t) { useLines = useLines || line != 0; });
  std::vector<char> vertical(n, 0);
  if (!useLines) {
    char state = 0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (finite(s, i) && finite(s, i + 1)) {
        const Vec3 d = s.commanded(i + 1) - s.commanded(i);
        const double length = d.norm();
        if (length > kLengthEpsilon) state = std::fabs(d.z()) > kVerticalShare * length;
      }
      vertical[i] = state;
    }
    if (n > 0) vertical[n - 1] = n > 1 ? vertical[n - 2] : 0;
  }
  std::vector<Piece> pieces;
  RunChannel<std::uint32_t>::Cursor lineOf = s.line.cursor();
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    const std::uint32_t line = useLines ? lineOf[begin] : 0;
    while (end < n && rapid[end] == rapid[begin] && vertical[end] == vertical[begin] && (!useLines || lineOf[end] == line))
      ++end;
    Piece p;
    p.begin = begin;
    p.end = end;
    p.kind = rapid[begin] ? PieceKind::Rapid : PieceKind::Feed;
    // Geometry from the first and last finite samples; the step into the next piece counts.
    std::size_t first = begin, last = std::min(end, n - 1);
    while (first < last && !finite(s, first)) ++first;
    while (last > first && !finite(s, last)) --last;
    double length = 0;
    for (std::size_t i = first; i < last; ++i) {
      const double d = (s.commanded(i + 1) - s.commanded(i)).norm();
      if (std::isfinite(d)) length += d;
    }
    if (length <= kLengthEpsilon) {
      p.kind = p.kind == PieceKind::Rapid ? PieceKind::Rapid : PieceKind::Still;
    } else {
      const Vec3 chord = s.commanded(last) - s.commanded(first);
      p.dz = chord.z();
      p.vertical = std::fabs(p.dz) > kVerticalShare * length;
      p.startHeading = p.endHeading = horizontal(chord);
    }
    pieces.push_back(p);
    begin = end;
  }
  return pieces;
}

// --- deciding which pieces cut --------------------------------------------------------------

bool isLink(const Piece& p) { return p.kind == PieceKind::Feed && p.vertical && !p.cutting; }

// Whether the samples between retract `k` and plunge `j` stay above where the retract started.
// A short climb of a steep relief taken for a retract is followed by cutting below it: the
// passes up to the next descent are not air moves (on stellabee1.ngc's dump, a climb of 0.3 mm
// judged vertical from its samples took a million samples of cutting out). A link that comes
// part of the way down before its plunge stays above it.
bool staysUp(const Trajectory& s, const std::vector<Piece>& pieces, std::size_t k, std::size_t j) {
  const std::size_t begin = pieces[k + 1].begin, end = pieces[j].begin;
  std::size_t first = begin;
  while (first < end && !finite(s, first)) ++first;
  if (first == end) return true;
  const double floor = s.z[first] - pieces[k].dz;
  for (std::size_t i = first; i < end; ++i)
    if (s.z[i] < floor) return false;
  return true;
}

void markCutting(const Trajectory& s, std::vector<Piece>& pieces) {
  const std::size_t m = pieces.size();
  // Nearest piece with motion on either side (dwells and zero-length moves are looked through).
  std::vector<std::size_t> before(m, m), after(m, m);
  for (std::size_t k = 0, last = m; k < m; ++k) {
    before[k] = last;
    if (pieces[k].kind == PieceKind::Feed || pieces[k].kind == PieceKind::Rapid) last = k;
  }
  for (std::size_t k = m, next = m; k-- > 0;) {
    after[k] = next;
    if (pieces[k].kind == PieceKind::Feed || pieces[k].kind == PieceKind::Rapid) next = k;
  }
  const auto horizontalFeed = [&](std::size_t k) {
    return k < m && pieces[k].kind == PieceKind::Feed && !pieces[k].vertical;
  };
  const auto verticalFeed = [&](std::size_t k) {
    return pieces[k].kind == PieceKind::Feed && pieces[k].vertical;
  };
  for (std::size_t k = 0; k < m; ++k) {
    Piece& p = pieces[k];
    if (p.kind == PieceKind::Rapid || p.kind == PieceKind::Unknown) p.cutting = false;
    if (!verticalFeed(k)) continue;
    // A run of vertical moves (a steep wall may take several) is judged by the moves around it.
    std::size_t last = k;
    while (after[last] < m && verticalFeed(after[last])) last = after[last];
    const std::size_t a = before[k], b = after[last];
    const bool insidePass = horizontalFeed(a) && horizontalFeed(b) &&
                            pieces[a].endHeading.dot(pieces[b].startHeading) > kSameHeadingCos;
    for (std::size_t q = k; q <= last; ++q)
      if (verticalFeed(q)) pieces[q].cutting = insidePass;
    k = last;
  }
  // Air moves: feed moves between a retract and the next plunge, up where the retract left them.
  for (std::size_t k = 0; k < m; ++k) {
    if (!(isLink(pieces[k]) && pieces[k].dz > 0)) continue;
    std::size_t j = k + 1;
    while (j < m && pieces[j].kind != PieceKind::Rapid && !isLink(pieces[j])) ++j;
    if (j < m && isLink(pieces[j]) && pieces[j].dz < 0 && staysUp(s, pieces, k, j))
      for (std::size_t q = k + 1; q < j; ++q) pieces[q].cutting = false;
    k = j - 1;
  }
  // Standstill belongs to whatever it interrupts.
  for (std::size_t k = 0; k < m; ++k)
    if (pieces[k].kind == PieceKind::Still) pieces[k].cutting = k > 0 ? pieces[k - 1].cutting : false;
}

}  // namespace

std::vector<Pass> cuttingRuns(const Trajectory& samples, const PassOptions& options) {
  std::vector<Piece> pieces =
      options.program != nullptr ? piecesFromProgram(samples, *options.program) : piecesFromSamples(samples);
  markCutting(samples, pieces);
  std::vector<Pass> runs;
  for (const Piece& p : pieces) {
    if (!p.cutting) continue;
    if (!runs.empty() && runs.back().end == p.begin) {
      runs.back().end = p.end;
    } else {
      runs.push_back({p.begin, p.end});
    }
  }
  return runs;
}

double pathLength(const Trajectory& s, std::size_t begin, std::size_t end) {
  double length = 0;
  for (std::size_t i = begin; i + 1 < end; ++i) {
    const double dx = s.x[i + 1] - s.x[i], dy = s.y[i + 1] - s.y[i], dz = s.z[i + 1] - s.z[i];
    const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (d == d && d - d == 0) length += d;
  }
  return length;
}

}  // namespace passes_detail

const char* pathPatternName(PathPattern pattern) {
  switch (pattern) {
    case PathPattern::Auto: return "auto";
    case PathPattern::DirectionParallel: return "direction-parallel";
    case PathPattern::ContourParallel: return "contour-parallel";
    case PathPattern::NoBoundary: return "no-boundary";
  }
  return "?";
}

PathPattern parsePathPattern(const std::string& name, const std::string& option) {
  for (PathPattern p : {PathPattern::Auto, PathPattern::DirectionParallel, PathPattern::ContourParallel, PathPattern::NoBoundary})
    if (name == pathPatternName(p)) return p;
  throw InputError(Diagnostic{option, 0, 0, "unknown pattern '" + name +
                                                "' (auto, direction-parallel, contour-parallel, no-boundary)"});
}

PassSet splitPasses(const Trajectory& samples, const PassOptions& options) {
  using namespace passes_detail;
  // Share of the cutting path that must look like a pattern for Auto to choose it.
  constexpr double kDirectionParallelShare = 0.7;
  constexpr double kContourParallelShare = 0.5;

  const std::vector<Pass> runs = cuttingRuns(samples, options);
  PassSet out;
  switch (options.pattern) {
    case PathPattern::DirectionParallel:
      out.pattern = PathPattern::DirectionParallel;
      out.passes = splitDirectionParallel(samples, runs, options);
      return out;
    case PathPattern::ContourParallel:
      out.pattern = PathPattern::ContourParallel;
      out.passes = splitContourParallel(samples, runs, options);
      return out;
    case PathPattern::NoBoundary:
      out.pattern = PathPattern::NoBoundary;
      out.passes = splitNoBoundary(samples, runs, options);
      return out;
    case PathPattern::Auto: break;
  }
  PatternFit fit;
  std::vector<Pass> passes = splitDirectionParallel(samples, runs, options, &fit);
  if (fit.fittingPasses >= 2 && fit.fraction() >= kDirectionParallelShare) {
    out.pattern = PathPattern::DirectionParallel;
    out.passes = std::move(passes);
    return out;
  }
  fit = PatternFit{};
  passes = splitContourParallel(samples, runs, options, &fit);
  if (fit.fittingPasses >= 1 && fit.fraction() >= kContourParallelShare) {
    out.pattern = PathPattern::ContourParallel;
    out.passes = std::move(passes);
    return out;
  }
  out.pattern = PathPattern::NoBoundary;
  out.passes = splitNoBoundary(samples, runs, options);
  return out;
}

}  // namespace isurface
