#pragma once
// A Biip dump's samples copied into a Trajectory (one array per channel).
#include <functional>
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
};

// Copies the channels of a dump (progress 0..1 about every million records). Samples whose
// position is not finite are kept; geometry skips them. A dump whose samples would not fit in
// the memory the machine has free is refused (InputError) before anything is copied.
Trajectory loadTrajectory(const BiipReader& reader, const TrajectoryProgress& progress = {},
                          const TrajectoryChannels& channels = {});

// The machine's rapid rate named in a dump's metadata (machine.rapid_mm_min), 0 when absent.
double rapidFeedFromMetadata(const std::string& metadataJson);

}  // namespace isurface
