#pragma once
// Interpolation samples in memory, one array per channel: what analysis and the surface work on.
// Loaded from a Biip dump (a simulation's or a machine trace's) or taken from a simulation.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "isurface/base/geometry.h"
#include "isurface/base/run_channel.h"

namespace isurface {

// The servo's positions of a run as offsets from its commanded ones (mm), loaded apart from
// the samples when a view first needs them (see Trajectory::attachFeedback).
struct FeedbackOffsets {
  std::vector<float> x, y, z;
  std::size_t size() const { return x.size(); }
};

struct Trajectory {
  std::string source;                // file the samples came from
  double cycle = 0.001;              // s, nominal sample period
  double startTime = 0;              // s, time of sample 0 when `time` is empty
  // s, per sample, only where the source recorded times (a dump's `t` channel, a trace's time
  // column); empty when sample i is at startTime + i * cycle, which saves 8 bytes a sample.
  std::vector<double> time;
  RunChannel<std::uint32_t> line;    // 1-based G-code line, 0 unknown (all 0 when absent)
  RunChannel<std::uint32_t> block;   // move index, when the dump has one (else empty)
  std::vector<double> x, y, z;       // commanded position, mm
  // Feedback position minus the commanded one, mm (empty when absent): a float keeps a servo's
  // lag of a millimetre to a ten-thousandth of a micrometre, in half the room of a position.
  std::vector<float> fbOffsetX, fbOffsetY, fbOffsetZ;
  RunChannel<float> feed;            // programmed feed, mm/min (empty when absent; 7 digits suffice)
  // Any other numeric channel of the dump, kept to colour by.
  std::vector<std::pair<std::string, std::vector<double>>> extra;
  bool hasLine = false;              // the dump had a `line` channel
  // The time channel departs from a regular cycle: derivatives then use divided differences.
  bool irregularTime = false;
  double rapidFeed = 0;              // mm/min, the machine's rapid rate when the dump names it (0 unknown)
  // Sample i is record i * thinning of the source: a dump larger than the memory, seen whole at
  // a coarser cycle (`cycle` is then thinning times the dump's own).
  std::size_t thinning = 1;

  std::size_t size() const { return x.size(); }
  bool hasFeedback() const { return !fbOffsetX.empty(); }
  bool hasFeed() const { return !feed.empty(); }
  double timeAt(std::size_t i) const { return time.empty() ? startTime + double(i) * cycle : time[i]; }
  // The `extra` channel of that name, nullptr when absent.
  const std::vector<double>* extraChannel(const std::string& name) const;
  Vec3 commanded(std::size_t i) const { return Vec3(x[i], y[i], z[i]); }
  Vec3 feedbackOffset(std::size_t i) const { return Vec3(fbOffsetX[i], fbOffsetY[i], fbOffsetZ[i]); }
  Vec3 feedback(std::size_t i) const { return commanded(i) + feedbackOffset(i); }
  // Gives back the spare room the run channels kept as they grew.
  void shrinkRunChannels() {
    line.shrink_to_fit();
    block.shrink_to_fit();
    feed.shrink_to_fit();
  }
  // Gives samples loaded without feedback the offsets loaded later (one per sample; else
  // std::invalid_argument). Whoever calls it makes sure no other thread reads the feedback.
  void attachFeedback(FeedbackOffsets&& offsets);
  // Sets sample i's feedback from a feedback position (mm); the channels must be sized.
  void setFeedback(std::size_t i, const Vec3& position) {
    fbOffsetX[i] = static_cast<float>(position.x() - x[i]);
    fbOffsetY[i] = static_cast<float>(position.y() - y[i]);
    fbOffsetZ[i] = static_cast<float>(position.z() - z[i]);
  }
};

// True when a gap between consecutive times departs from the cycle by more than a thousandth
// of it (or a time is not finite).
bool timeIsIrregular(const double* time, std::size_t n, double cycle);

// Machining time, s: first sample to last (n - 1 cycles for a regular dump), 0 for fewer than
// two samples or a time channel that is not finite.
double machiningTime(const Trajectory& samples);

}  // namespace isurface
