// An edited machine is named as a machine of its own.
#include <gtest/gtest.h>

#include "isurface/app_model/machine_edits.h"

namespace isurface::app_model {
namespace {

TEST(machineEdits, aMachineWithOtherLimitsIsNotNamedAsTheOneItWasEditedFrom) {
  const Machine original = defaultMachine();
  Machine edited = original;
  edited.axes[0].maxAcceleration *= 0.5;
  edited.axes[1].maxAcceleration *= 0.5;
  const Machine named = namedAfterEdits(edited, original);
  EXPECT_EQ(named.name, original.name + " (edited: X acceleration, Y acceleration)");
  EXPECT_EQ(named.axes[0].maxAcceleration, edited.axes[0].maxAcceleration);
}

TEST(machineEdits, editsOfAnEditedMachineAddToItsList) {
  const Machine original = defaultMachine();
  Machine once = original;
  once.axes[0].maxAcceleration = 1000;
  once = namedAfterEdits(once, original);
  Machine twice = once;
  twice.axes[0].maxAcceleration = 800;  // listed already
  twice.chordTolerance = 0.005;
  EXPECT_EQ(namedAfterEdits(twice, once).name,
            original.name + " (edited: X acceleration, chord tolerance)");
  Machine many = once;
  for (AxisLimits& axis : many.axes) axis.maxJerk *= 2;
  many.cycle = 0.002;
  const std::string name = namedAfterEdits(many, once).name;
  EXPECT_EQ(name.substr(name.size() - 10), " and more)") << name;
  Machine again = namedAfterEdits(many, once);
  again.rapidVelocity *= 0.5;
  EXPECT_EQ(namedAfterEdits(again, namedAfterEdits(many, once)).name, name);
}

TEST(machineEdits, aNameTheUserGaveOrAnUnchangedMachineIsKept) {
  const Machine original = defaultMachine();
  Machine renamed = original;
  renamed.name = "Shop VMC 3";
  renamed.axes[2].maxVelocity = 100;
  EXPECT_EQ(namedAfterEdits(renamed, original).name, "Shop VMC 3");
  EXPECT_EQ(namedAfterEdits(original, original).name, original.name);
}

}  // namespace
}  // namespace isurface::app_model
