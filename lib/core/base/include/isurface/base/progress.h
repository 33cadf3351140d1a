#pragma once
// Progress of long operations: a callback given the fraction done (0..1). A caller cancels by
// throwing from it (the application's jobs throw JobCancelled); work in progress unwinds and
// leaves no partial output.
#include <functional>

namespace isurface {

using ProgressCallback = std::function<void(double)>;

// The part [from, to] of a whole operation's progress, handed to one of its stages.
inline ProgressCallback progressStage(const ProgressCallback& whole, double from, double to) {
  if (!whole) return {};
  return [whole, from, to](double f) { whole(from + (to - from) * f); };
}

}  // namespace isurface
