// The machine window's model: an edit applied is a machine of its own, a refused value leaves the
// machine in use as it was and says why, a description loads into the copy being edited only.
#include <gtest/gtest.h>

#include "isurface/app_model/machine_window.h"
#include "scratch_files.h"

using namespace isurface;
using namespace isurface::app_model;

TEST(machineWindow, AnEditAppliedIsAMachineOfItsOwn) {
  MachineWindow w;
  w.show();
  EXPECT_TRUE(w.open && w.appearing);
  w.edit.axes[0].maxAcceleration /= 2;
  w.show();  // already open: the edit stays
  EXPECT_EQ(w.edit.axes[0].maxAcceleration, defaultMachine().axes[0].maxAcceleration / 2);
  ASSERT_TRUE(w.apply());
  EXPECT_EQ(w.source, "edited");
  EXPECT_EQ(w.inUse.axes[0].maxAcceleration, defaultMachine().axes[0].maxAcceleration / 2);
  EXPECT_NE(w.inUse.name, defaultMachine().name);
  EXPECT_NE(w.inUse.name.find("edited: X acceleration"), std::string::npos) << w.inUse.name;
  EXPECT_EQ(w.edit.name, w.inUse.name);
}

TEST(machineWindow, ARefusedValueLeavesTheMachineInUse) {
  MachineWindow w;
  w.show();
  w.edit.cycle = 0;
  EXPECT_FALSE(w.apply());
  EXPECT_EQ(w.source, "built-in default");
  EXPECT_EQ(w.inUse.cycle, defaultMachine().cycle);
  EXPECT_NE(w.message.find("machine window"), std::string::npos) << w.message;
  w.revert();
  EXPECT_EQ(w.edit.cycle, defaultMachine().cycle);
  EXPECT_EQ(w.message, "");
}

TEST(machineWindow, ADescriptionLoadsIntoTheCopyOnly) {
  MachineWindow w;
  w.loadPath = test::writeScratch("window-machine.json", machineDescriptionJson(Machine{defaultMachine()}));
  w.load();
  EXPECT_NE(w.message.find("simulate to use it"), std::string::npos) << w.message;
  w.loadPath = test::writeScratch("window-machine-bad.json", "{ not json");
  w.load();
  EXPECT_NE(w.message.find("window-machine-bad.json"), std::string::npos) << w.message;
  EXPECT_EQ(w.source, "built-in default");
}

// Simulating with the machine as it is, or with a description loaded and left as it was, names
// where it came from, not "edited".
TEST(machineWindow, AMachineAppliedUnchangedKeepsWhereItCameFrom) {
  MachineWindow w;
  w.show();
  ASSERT_TRUE(w.apply());
  EXPECT_EQ(w.source, "built-in default");
  Machine other = defaultMachine();
  other.name = "the shop's mill";
  other.axes[2].maxVelocity /= 2;
  w.loadPath = test::writeScratch("window-shop-machine.json", machineDescriptionJson(other));
  w.load();
  ASSERT_TRUE(w.apply());
  EXPECT_EQ(w.source, w.loadPath);
  EXPECT_EQ(w.inUse.name, "the shop's mill");
  w.edit.axes[0].maxJerk /= 2;
  ASSERT_TRUE(w.apply());
  EXPECT_EQ(w.source, "edited");
}
