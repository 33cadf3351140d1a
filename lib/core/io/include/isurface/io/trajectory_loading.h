#pragma once
// A Biip dump's samples copied into a Trajectory (one array per channel).
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

#include "isurface/base/trajectory.h"

namespace isurface {

class BiipReader;

using TrajectoryProgress = std::function<void(double)>;

// Which channels loadTrajectory copies besides line, x y z and feed (36 bytes a sample; the
// time only when the dump records it in a t channel).
struct TrajectoryChannels {
  bool block = true;     // the move index, used only to join a program's moves
  bool feedback = true;  // fb_x fb_y fb_z: 12 bytes a sample (float offsets)
  bool extra = true;     // every other channel of the dump: 8 bytes a sample each
  // Every thinning-th record only (1: all of them), for a dump larger than the memory.
  std::size_t thinning = 1;
  // Only the records [firstRecord, firstRecord + records) (clipped to the dump): a close-up of
  // a thinned dump where the camera looks. Sample 0 is then record firstRecord.
  std::size_t firstRecord = 0;
  std::size_t records = std::numeric_limits<std::size_t>::max();
};

// Bytes a sample of this dump takes in memory once loaded with `channels`.
std::uint64_t bytesPerSample(const BiipReader& reader, const TrajectoryChannels& channels);

// The least k such that every k-th of `records` samples of `bytesPerSample` bytes fit in
// `budget` bytes (1 when all of them do; at least 1 sample is always kept).
std::size_t thinningToFit(std::uint64_t records, std::uint64_t bytesPerSample, std::uint64_t budget);

// Copies the channels of a dump (progress 0..1 about every million records), or every
// channels.thinning-th record of them. Samples whose position is not finite are kept; geometry
// skips them. A dump whose samples would not fit in the memory the machine has free is refused
// (InputError) before anything is copied.
Trajectory loadTrajectory(const BiipReader& reader, const TrajectoryProgress& progress = {},
                          const TrajectoryChannels& channels = {});

// The feedback channels (fb_x fb_y fb_z) of the dump `samples` were loaded from without them
// (every samples.thinning-th record), as offsets from their commanded positions: the values
// loadTrajectory gives. InputError when
// the dump has no feedback, holds another number of records, or needs more memory than is free.
FeedbackOffsets loadFeedbackOffsets(const BiipReader& reader, const Trajectory& samples,
                                    const TrajectoryProgress& progress = {});

// The machine's rapid rate named in a dump's metadata (machine.rapid_mm_min), 0 when absent.
double rapidFeedFromMetadata(const std::string& metadataJson);

}  // namespace isurface
