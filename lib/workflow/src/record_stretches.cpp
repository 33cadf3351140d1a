// Stretches of a dump's records, one after another in one Trajectory.
#include "isurface/workflow/record_stretches.h"

#include <algorithm>

#include "isurface/io/biip.h"

namespace isurface {

namespace {

// Records on each side of a stretch: the widest stencil of the derivatives (jerk) reaches two
// samples away; one more for good measure.
constexpr std::size_t kWidening = 3;

template <class T>
void appendRuns(RunChannel<T>& to, const RunChannel<T>& from) {
  from.forEachRun(0, from.size(), [&to](const T& value, std::size_t begin, std::size_t end) { to.append(value, end - begin); });
}

void appendSamples(Trajectory& to, const Trajectory& from) {
  for (auto [dst, src] : {std::pair{&to.x, &from.x}, std::pair{&to.y, &from.y}, std::pair{&to.z, &from.z}})
    dst->insert(dst->end(), src->begin(), src->end());
  for (auto [dst, src] : {std::pair{&to.fbOffsetX, &from.fbOffsetX}, std::pair{&to.fbOffsetY, &from.fbOffsetY},
                          std::pair{&to.fbOffsetZ, &from.fbOffsetZ}})
    dst->insert(dst->end(), src->begin(), src->end());
  appendRuns(to.line, from.line);
  appendRuns(to.block, from.block);
  appendRuns(to.feed, from.feed);
  for (std::size_t c = 0; c < to.extra.size() && c < from.extra.size(); ++c)
    to.extra[c].second.insert(to.extra[c].second.end(), from.extra[c].second.begin(), from.extra[c].second.end());
}

}  // namespace

Trajectory loadRecordStretches(const BiipReader& reader, const std::vector<RecordStretch>& stretches,
                               const TrajectoryChannels& channels, PassSet& passes) {
  const std::size_t records = reader.recordCount();
  const std::size_t k = std::max<std::size_t>(1, channels.thinning);
  Trajectory out;
  bool first = true;
  passes.passes.clear();
  for (const RecordStretch& stretch : stretches) {
    if (stretch.first >= records || stretch.count == 0) {
      passes.passes.push_back(Pass{out.size(), out.size()});  // pass p stays stretch p's
      continue;
    }
    const std::size_t before = std::min(stretch.first, kWidening * k);
    const std::size_t end = std::min(records, stretch.first + stretch.count);
    const std::size_t after = std::min(records - end, kWidening * k);
    TrajectoryChannels part = channels;
    part.firstRecord = stretch.first - before;
    part.records = before + (end - stretch.first) + after;
    Trajectory piece = loadTrajectory(reader, {}, part);
    const std::size_t offset = out.size();
    if (first) {
      out = std::move(piece);
      first = false;
    } else {
      appendSamples(out, piece);
      // A dump's recorded times go along; without them the joined run keeps the dump's cycle,
      // which is all its derivatives need inside each stretch.
      out.time.insert(out.time.end(), piece.time.begin(), piece.time.end());
    }
    // Sample i of the piece is its record part.firstRecord + i * k.
    const std::size_t begin = offset + (before + k - 1) / k;
    const std::size_t stop = offset + (before + (end - stretch.first) + k - 1) / k;
    passes.passes.push_back(Pass{begin, std::max(begin, stop)});
  }
  if (!out.time.empty()) out.irregularTime = timeIsIrregular(out.time.data(), out.time.size(), out.cycle);
  return out;
}

}  // namespace isurface
