#pragma once
// Feeds a program asks for that the machine's axes cannot give: every control runs such a move at
// the axes' limit, and a user must be told, not find a map of a slower program than was written.
#include <cstdint>
#include <optional>
#include <string>

#include "isurface/base/diagnostic.h"
#include "isurface/gcode/program.h"
#include "isurface/machine/machine.h"

namespace isurface {

class FeedCapNotes {
 public:
  explicit FeedCapNotes(const Machine& machine) : machine_(machine) {}
  // Move `move` (a feed move; rapids run at the rapid rate anyway) from `start`.
  void note(const Move& move, const Vec3& start);
  // One warning naming the first such line, its feed and what the axes allow there, and how many
  // moves more; none when every feed was within the axes' limits.
  std::optional<Diagnostic> warning(const std::string& source) const;

 private:
  const Machine& machine_;
  std::uint64_t capped_ = 0;
  Move first_{};
  double firstLimitMmMin_ = 0;
};

}  // namespace isurface
