#pragma once
// Where a five-axis run's joints pass their machine's limits. LinuxCNC 2.9 under tool-centre-point
// kinematics limits its joints in position only: the slides driven through the rotary table can
// run faster than their axes allow, which a control that keeps them within would not.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/machine/machine.h"
#include "isurface/nc/interpolator.h"

namespace isurface::linuxcnc {

class JointLimitNotes {
 public:
  explicit JointLimitNotes(const Machine& machine);
  // The joints of the next cycle, made for program line `line`.
  void note(const JointSample& joints, std::uint32_t line);
  // One warning a joint that passed its velocity or acceleration limit, naming the lines.
  std::vector<Diagnostic> warnings(const std::string& source) const;

 private:
  struct Joint {
    std::string name, unit;       // "X", "mm"; "B", "deg"
    double maxVelocity = 0;       // per s (0: none)
    double maxAcceleration = 0;   // per s^2 (0: none)
    double worstVelocity = 0, worstAcceleration = 0;
    std::size_t cycles = 0;       // cycles past a limit
    std::vector<std::pair<std::uint32_t, std::uint32_t>> lines;  // runs of lines past a limit
  };
  std::array<Joint, 5> joints_;
  double cycle_;
  std::array<double, 5> position_{}, velocity_{};
  int seen_ = 0;  // cycles noted, up to 2
};

}  // namespace isurface::linuxcnc
