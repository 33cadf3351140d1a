#pragma once
// Stretches of a dump's records loaded one after another into one Trajectory: the passes of a
// thinned dump where the camera looks, at the dump's own resolution (or a finer thinning).
#include <cstddef>
#include <vector>

#include "isurface/base/trajectory.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/surface/passes.h"

namespace isurface {

class BiipReader;

struct RecordStretch {
  std::size_t first = 0, count = 0;  // records [first, first + count) of the dump
};

// The stretches' records (every channels.thinning-th of each), each stretch widened by a few
// records on both sides so that speeds, accelerations and jerks at its ends are taken from its
// true neighbours, and `passes` set to one pass a stretch without the widening (pass p is
// stretch p's, empty where the stretch lies outside the dump; its first sample is the stretch's
// first record when that is a multiple of the thinning from the widened start, as it is when the
// stretch starts 3 * thinning records or more into the dump).
// channels.firstRecord and channels.records are ignored.
Trajectory loadRecordStretches(const BiipReader& reader, const std::vector<RecordStretch>& stretches,
                               const TrajectoryChannels& channels, PassSet& passes);

}  // namespace isurface
