#include "joint_limit_notes.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace isurface::linuxcnc {

namespace {

// Past a limit by more than this share: the samples' own rounding stays below it.
constexpr double kMargin = 1.01;
constexpr std::size_t kLinesNamed = 6;

std::string lineRuns(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& runs) {
  std::string text;
  for (std::size_t i = 0; i < runs.size() && i < kLinesNamed; ++i) {
    if (!text.empty()) text += ", ";
    text += runs[i].first == runs[i].second ? fmt::format("{}", runs[i].first)
                                            : fmt::format("{}-{}", runs[i].first, runs[i].second);
  }
  if (runs.size() > kLinesNamed) text += fmt::format(" and {} more", runs.size() - kLinesNamed);
  return text;
}

}  // namespace

JointLimitNotes::JointLimitNotes(const Machine& machine) : cycle_(machine.cycle) {
  for (int i = 0; i < 3; ++i) {
    Joint& j = joints_[static_cast<std::size_t>(i)];
    j.name = std::string(1, char('X' + i));
    j.unit = "mm";
    j.maxVelocity = machine.axes[i].maxVelocity;
    j.maxAcceleration = machine.axes[i].maxAcceleration;
  }
  for (std::size_t k = 0; k < 2 && machine.kinematics; ++k) {
    const RotaryAxis& axis = machine.kinematics->rotary[k];
    Joint& j = joints_[3 + k];
    j.name = std::string(1, axis.name);
    j.unit = "deg";
    j.maxVelocity = axis.maxVelocity;
    j.maxAcceleration = axis.maxAcceleration;
  }
}

void JointLimitNotes::note(const JointSample& sample, std::uint32_t line) {
  const std::array<double, 5> position = {sample.linear[0], sample.linear[1], sample.linear[2], sample.rotary[0],
                                          sample.rotary[1]};
  for (std::size_t k = 0; k < 5; ++k) {
    const double velocity = (position[k] - position_[k]) / cycle_;
    const double acceleration = (velocity - velocity_[k]) / cycle_;
    Joint& j = joints_[k];
    const bool fast = seen_ >= 1 && j.maxVelocity > 0 && std::abs(velocity) > kMargin * j.maxVelocity;
    const bool sharp = seen_ >= 2 && j.maxAcceleration > 0 && std::abs(acceleration) > kMargin * j.maxAcceleration;
    if (fast || sharp) {
      if (fast) j.worstVelocity = std::max(j.worstVelocity, std::abs(velocity));
      if (sharp) j.worstAcceleration = std::max(j.worstAcceleration, std::abs(acceleration));
      ++j.cycles;
      if (!j.lines.empty() && (j.lines.back().second == line || j.lines.back().second + 1 == line))
        j.lines.back().second = line;
      else if (j.lines.empty() || j.lines.back().second != line)
        j.lines.emplace_back(line, line);
    }
    velocity_[k] = seen_ >= 1 ? velocity : 0.0;
  }
  position_ = position;
  seen_ = std::min(seen_ + 1, 2);
}

std::vector<Diagnostic> JointLimitNotes::warnings(const std::string& source) const {
  std::vector<Diagnostic> out;
  for (const Joint& j : joints_) {
    if (j.cycles == 0) continue;
    std::string past;
    if (j.worstVelocity > 0)
      past = fmt::format("{:.4g} {}/s (its limit {:.4g})", j.worstVelocity, j.unit, j.maxVelocity);
    if (j.worstAcceleration > 0)
      past += fmt::format("{}{:.4g} {}/s^2 (its limit {:.4g})", past.empty() ? "" : " and ", j.worstAcceleration, j.unit,
                          j.maxAcceleration);
    out.push_back(Diagnostic{
        source, j.lines.front().first, 0,
        fmt::format("joint {} reaches {} on lines {} ({:.3f} s in all): LinuxCNC 2.9 does not keep it within its "
                    "limits there (under tool-centre-point control it limits joints in position only, and a blend into "
                    "a turn of a rotary axis adds two accelerations); a control that does slows the tip there (colour "
                    "by the joint's velocity or acceleration to see where)",
                    j.name, past, lineRuns(j.lines), double(j.cycles) * cycle_)});
  }
  return out;
}

}  // namespace isurface::linuxcnc
