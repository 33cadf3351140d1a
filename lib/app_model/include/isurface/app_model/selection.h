#pragma once
// The one selection every panel follows: a sample (its row in the data bar, the cursor on the
// signal curves, the glowing point in the 3D view) and its G-code line (highlighted in the
// G-code pane). Picking, locating by sample or by line, and clicking a curve all come here.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "isurface/base/trajectory.h"

namespace isurface::app_model {

struct Selection {
  std::optional<std::size_t> sample;  // index into the trajectory
  std::optional<std::uint32_t> line;  // 1-based G-code line
  std::uint64_t generation = 0;       // changes whenever the selection does: panels scroll to it
};

class SelectionModel {
 public:
  // The samples selections refer to (may be null: then only lines can be selected). Another
  // trajectory drops the selected sample (it indexed the old samples) and keeps the line.
  void setTrajectory(const Trajectory* samples);
  const Trajectory* trajectory() const { return samples_; }

  bool selectSample(std::size_t sample);        // and its line; false (ignored) when out of range
  // The first sample of the line, as the paper's locate does; with no sample the line alone.
  // Returns whether a sample was found.
  bool selectLine(std::uint32_t line);
  // The sample nearest to a point of the surface (mm); returns whether there was one.
  bool selectNearest(const Vec3& point);
  void clear();

  const Selection& current() const { return selection_; }

 private:
  void bump() { ++selection_.generation; }
  std::optional<std::size_t> firstSampleOfLineCached(std::uint32_t line);

  const Trajectory* samples_ = nullptr;
  Selection selection_;
  // (line, its first sample) sorted by line, built on the first selectLine for the trajectory:
  // later look-ups are a binary search instead of a scan of millions of samples.
  std::vector<std::pair<std::uint32_t, std::size_t>> firstSampleByLine_;
  bool lineIndexBuilt_ = false;
  std::size_t lineIndexSampleCount_ = 0;  // size it was built for: a grown trajectory rebuilds
};

}  // namespace isurface::app_model
