// What a machine description says is what the simulation uses: no key ignored, no servo left
// unchecked, the reference positions honoured.
#include <gtest/gtest.h>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/machine/machine.h"
#include "isurface/workflow/run_inputs.h"
#include "test_locations.h"

using namespace isurface;

namespace {

std::string refusal(const std::string& json) {
  try {
    parseMachine(json, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MachineDescription, AMisspelledKeyIsRefusedWithTheKeyItMeant) {
  const std::string root = refusal(R"({"rapid_mm_mn": 5000})");
  EXPECT_NE(root.find("unknown key \"rapid_mm_mn\""), std::string::npos) << root;
  EXPECT_NE(root.find("did you mean \"rapid_mm_min\""), std::string::npos) << root;
  const std::string axis = refusal(R"({"axes": {"x": {"max_acceleration_mm_s": 500}}})");
  EXPECT_NE(axis.find("axes.x.max_acceleration_mm_s2"), std::string::npos) << axis;
  EXPECT_NE(refusal(R"({"control": {"dialekt": "fanuc"}})").find("control.dialect"), std::string::npos);
  EXPECT_NE(refusal(R"({"reference_positions_mm": {"g29": [0, 0, 0]}})").find("unknown key"), std::string::npos);
  EXPECT_NE(refusal(R"({"tools": {"diameter": {"1": 6}}})").find("tools.diameters"), std::string::npos);
  EXPECT_NE(refusal(R"({"spindle": 1})").find("unknown key \"spindle\""), std::string::npos);
}

TEST(MachineDescription, NotesAreAllowed) {
  EXPECT_EQ(refusal(R"({"comment": "shop machine 3", "_by": "me", "description": "x"})"), "");
}

TEST(MachineDescription, ACycleAloneIsCheckedAgainstTheDefaultServo) {
  // The default position gain (40 1/s) and a 0.1 s cycle: the servo model would diverge.
  const std::string why = refusal(R"({"cycle_s": 0.1})");
  EXPECT_NE(why.find("position_gain_1_s is too high for cycle_s"), std::string::npos) << why;
  EXPECT_EQ(refusal(R"({"cycle_s": 0.01})"), "");
}

TEST(MachineDescription, G28GoesToTheReferencePositionItGives) {
  const Machine m = parseMachine(R"({"reference_positions_mm": {"g28": [10, 20, 30], "g30": [-1, -2, -3]}})", "m.json");
  const InterpretResult r = interpretGcode("G21 G90\nG28\nG30\nM2\n", "home.nc", interpreterOptions(m));
  ASSERT_TRUE(r.ok()) << r.errors.front().str();
  ASSERT_GE(r.program.moves.size(), 2u);
  bool reached28 = false, reached30 = false;
  for (const Move& move : r.program.moves) {
    reached28 = reached28 || move.end.isApprox(Vec3(10, 20, 30));
    reached30 = reached30 || move.end.isApprox(Vec3(-1, -2, -3));
  }
  EXPECT_TRUE(reached28);
  EXPECT_TRUE(reached30);
}

TEST(MachineDescription, ThePlannerIsNamedKeptAndCheckedAndTheLinuxcncSimMachineUsesLinuxcnc29) {
  EXPECT_EQ(parseMachine("{}", "m.json").control.planner, TrajectoryPlanner::Generic);
  const Machine m = parseMachine(R"({"control": {"planner": "linuxcnc-2.9"}})", "m.json");
  EXPECT_EQ(m.control.planner, TrajectoryPlanner::LinuxCnc29);
  EXPECT_EQ(parseMachine(machineDescriptionJson(m), "again.json").control.planner, TrajectoryPlanner::LinuxCnc29);
  EXPECT_NE(machineLimitsJson(m).find("linuxcnc-2.9"), std::string::npos);
  EXPECT_NE(refusal(R"({"control": {"planner": "linuxcnc"}})").find("control.planner"), std::string::npos);
  const Machine sim = loadMachine(std::string(test::sourceDir()) + "/resources/machines/linuxcnc-sim.json");
  EXPECT_EQ(sim.control.planner, TrajectoryPlanner::LinuxCnc29);
}

// Whether the control smooths chords within its tolerance: on unless the description says not,
// kept through a saved description and a dump's metadata, a boolean or refused.
TEST(MachineDescription, ChordSmoothingIsOnUnlessSaidAndKept) {
  EXPECT_TRUE(parseMachine("{}", "m.json").control.chordSmoothing);
  EXPECT_TRUE(defaultMachine().control.chordSmoothing);
  const Machine without = loadMachine(std::string(test::sourceDir()) + "/resources/machines/without-chord-smoothing.json");
  EXPECT_FALSE(without.control.chordSmoothing);
  EXPECT_EQ(without.axes[0].maxJerk, defaultMachine().axes[0].maxJerk) << "the default machine's limits";
  EXPECT_FALSE(parseMachine(machineDescriptionJson(without), "again.json").control.chordSmoothing);
  EXPECT_NE(machineLimitsJson(without).find("\"chord_smoothing\":false"), std::string::npos) << machineLimitsJson(without);
  EXPECT_NE(refusal(R"({"control": {"chord_smoothing": "no"}})").find("control.chord_smoothing must be true or false"),
            std::string::npos);
}

TEST(MachineDescription, TheRiseTimeIsTheDescriptionsOwnOrItsLargestAOverJAndStaysWhenALimitIsLowered) {
  // The default's axes: 2000 / 100000 and 1500 / 75000 mm/s^2 over mm/s^3.
  EXPECT_DOUBLE_EQ(defaultMachine().control.accelerationRiseTime, 0.02);
  // Not inherited from the default: derived from the description's own axes.
  const Machine slow = parseMachine(R"({"axes": {"z": {"max_jerk_mm_s3": 15000}}})", "m.json");
  EXPECT_DOUBLE_EQ(slow.control.accelerationRiseTime, 0.1);
  const Machine given = parseMachine(R"({"control": {"acceleration_rise_time_s": 0.05}})", "m.json");
  EXPECT_DOUBLE_EQ(given.control.accelerationRiseTime, 0.05);
  // Written back, it is read as given even where the limits are then lowered.
  Machine lowered = parseMachine(machineDescriptionJson(given), "again.json");
  EXPECT_DOUBLE_EQ(lowered.control.accelerationRiseTime, 0.05);
  EXPECT_NE(machineLimitsJson(given).find("\"acceleration_rise_time_s\":0.05"), std::string::npos);
  // No jerk limit: no filter to rise, and 0 is read back.
  const Machine noJerk = loadMachine(std::string(test::sourceDir()) + "/resources/machines/linuxcnc-sim.json");
  EXPECT_EQ(noJerk.control.accelerationRiseTime, 0.0);
  EXPECT_EQ(parseMachine(machineDescriptionJson(noJerk), "again.json").control.accelerationRiseTime, 0.0);
  EXPECT_NE(refusal(R"({"control": {"acceleration_rise_time_s": -1}})").find("acceleration_rise_time_s"), std::string::npos);
  EXPECT_NE(refusal(R"({"control": {"acceleration_rise_time_s": 0}})").find("jerk limit"), std::string::npos);
}

TEST(MachineDescription, AKeyGivenTwiceOrAVelocityLoopThatNeverFollowsIsRefused) {
  const std::string twice = refusal(R"({"rapid_mm_min": 5000, "rapid_mm_min": 50000})");
  EXPECT_NE(twice.find("\"rapid_mm_min\" is given twice"), std::string::npos) << twice;
  EXPECT_NE(refusal(R"({"axes": {"x": {"max_jerk_mm_s3": 1, "max_jerk_mm_s3": 2}}})").find("\"max_jerk_mm_s3\" is given twice"),
            std::string::npos);
  // The same key in two objects is two keys.
  EXPECT_EQ(refusal(R"({"axes": {"x": {"max_jerk_mm_s3": 1e5}, "y": {"max_jerk_mm_s3": 1e5}}})"), "");
  const std::string frozen = refusal(R"({"axes": {"x": {"velocity_loop_time_constant_s": 1e308}}})");
  EXPECT_NE(frozen.find("velocity_loop_time_constant_s must be from 0 to 1 s"), std::string::npos) << frozen;
}

// A five-axis machine: its kinematics read, checked and written back; the LinuxCNC xyzbc-trt
// machine as its peer is configured.
TEST(fiveAxisMachine, TheLinuxCncTrtMachineIsItsPeersConfiguration) {
  const Machine m = loadMachine(std::string(test::sourceDir()) + "/resources/machines/linuxcnc-xyzbc-trt.json");
  ASSERT_TRUE(m.kinematics.has_value());
  const FiveAxisKinematics& k = *m.kinematics;
  EXPECT_EQ(k.structure, KinematicStructure::TableTable);
  EXPECT_EQ(k.rotary[0].name, 'B');
  EXPECT_EQ(k.rotary[1].name, 'C');
  EXPECT_EQ(k.rotary[0].pivot, Vec3(-20, 0, -15));
  EXPECT_EQ(k.rotary[1].pivot, Vec3::Zero());
  EXPECT_EQ(k.rotary[0].minimum, -120);
  EXPECT_EQ(k.rotary[0].maximum, 120);
  EXPECT_EQ(k.rotary[0].maxVelocity, 90);
  EXPECT_EQ(k.rotary[1].maxAcceleration, 900);
  EXPECT_FALSE(k.rotary[1].wraps);
  EXPECT_EQ(m.control.planner, TrajectoryPlanner::LinuxCnc29);
  // Written and read again, the same machine.
  const Machine again = parseMachine(machineDescriptionJson(m), "again.json");
  ASSERT_TRUE(again.kinematics.has_value());
  EXPECT_EQ(again.kinematics->rotary[0].pivot, k.rotary[0].pivot);
  EXPECT_EQ(again.kinematics->rotary[1].direction, k.rotary[1].direction);
  EXPECT_EQ(again.kinematics->rotary[0].maximum, 120);
  EXPECT_EQ(machineDescriptionJson(again), machineDescriptionJson(m));
  // A three-axis machine has none.
  EXPECT_FALSE(defaultMachine().kinematics.has_value());
}

TEST(fiveAxisMachine, AWrongKinematicsIsRefusedNamingTheKey) {
  const std::string axisB = R"({"name": "B", "max_velocity_deg_s": 90, "max_acceleration_deg_s2": 900})";
  const std::string axisC = R"({"name": "C", "max_velocity_deg_s": 90, "max_acceleration_deg_s2": 900})";
  const auto with = [](const std::string& kinematics) { return R"({"kinematics": )" + kinematics + "}"; };
  EXPECT_NE(refusal(with(R"({"structure": "table-chair", "rotary_axes": [)" + axisB + "," + axisC + "]}"))
                .find("kinematics.structure"),
            std::string::npos);
  EXPECT_NE(refusal(with(R"({"structure": "table-table", "rotary_axes": [)" + axisB + "]}")).find("two rotary axes"),
            std::string::npos);
  EXPECT_NE(refusal(with(R"({"structure": "table-table", "rotary_axes": [)" + axisB + "," + axisB + "]}"))
                .find("one axis twice"),
            std::string::npos);
  EXPECT_NE(refusal(with(R"({"structure": "head-head", "rotary_axes": [{"name": "D"}, )" + axisC + "]}"))
                .find("rotary_axes[0].name"),
            std::string::npos);
  EXPECT_NE(refusal(with(R"({"structure": "table-table", "rotary_axes": [{"name": "B", "max_velocity_deg_s": 90}, )" +
                         axisC + "]}"))
                .find("rotary_axes[0].max_acceleration_deg_s2"),
            std::string::npos);
  EXPECT_NE(refusal(with(R"({"structure": "table-table", "rotary_axes": [{"name": "B", "direction": [0, 0, 1], )"
                         R"("max_velocity_deg_s": 90, "max_acceleration_deg_s2": 900}, )" + axisC + "]}"))
                .find("parallel"),
            std::string::npos);
  EXPECT_NE(refusal(with(R"({"structure": "table-table", "rotary_axes": [)" + axisB + "," + axisC + R"(], "tool": 3})"))
                .find("kinematics.tool"),
            std::string::npos);
}
