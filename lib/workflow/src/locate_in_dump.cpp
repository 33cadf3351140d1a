// Locating in a dump read in place: nothing is loaded, so it answers on a dump of any size.
#include "isurface/workflow/locate_in_dump.h"

#include <algorithm>

#include "isurface/io/biip.h"

namespace isurface {

std::optional<std::size_t> firstSampleOfLine(const BiipReader& reader, std::uint32_t line) {
  const BiipChannelView view = reader.channel("line");
  if (!view.valid()) return std::nullopt;
  const std::size_t n = reader.recordCount();
  for (std::size_t i = 0; i < n; ++i)
    if (countAt(view, i, reader.path(), "line") == line) return i;
  return std::nullopt;
}

std::optional<std::size_t> nearestSample(const BiipReader& reader, const Vec3& point) {
  const BiipChannelView x = reader.channel("x"), y = reader.channel("y"), z = reader.channel("z");
  return nearestOf(reader.recordCount(), point, [&](std::size_t i, double& a, double& b, double& c) {
    a = x[i];
    b = y[i];
    c = z[i];
  });
}

SampleMotion motionAtSample(const BiipReader& reader, std::size_t sample) {
  const std::size_t n = reader.recordCount();
  const std::size_t from = sample >= kMotionWindow ? sample - kMotionWindow : 0;
  const std::size_t to = std::min(n, sample + kMotionWindow + 1);
  const std::size_t count = to - from;
  double x[2 * kMotionWindow + 1], y[2 * kMotionWindow + 1], z[2 * kMotionWindow + 1], t[2 * kMotionWindow + 1];
  reader.copyChannel("x", x, from, count);
  reader.copyChannel("y", y, from, count);
  reader.copyChannel("z", z, from, count);
  // Divided differences only when the dump's time channel is irregular, as for a loaded one.
  bool irregular = false;
  const BiipChannelView time = reader.channel("t");
  if (time.valid()) {
    const double cycle = reader.header().cycleSeconds;
    for (std::size_t i = 1; i < n && !irregular; ++i) {
      const double pair[2] = {time[i - 1], time[i]};
      irregular = timeIsIrregular(pair, 2, cycle);
    }
    if (irregular) reader.copyChannel("t", t, from, count);
  }
  return motionInWindow(x, y, z, irregular ? t : nullptr, count, sample - from, reader.header().cycleSeconds);
}

}  // namespace isurface
