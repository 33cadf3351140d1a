// RS274/NGC interpreter: modal groups, modal codes, M codes and the order a block runs in.
#include <sys/mman.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <utility>
#include <cstdlib>
#include <vector>
#include <optional>

#include "interpreter_state.h"
#include "program_file_text.h"

namespace isurface {
namespace gcode {

namespace {

std::string codeName(char letter, int tenths) {
  if (tenths < 0) return fmt::format("{}?", letter);
  if (tenths % 10 == 0) return fmt::format("{}{}", letter, tenths / 10);
  return fmt::format("{}{}.{}", letter, tenths / 10, tenths % 10);
}

// The modal group of a G code, -1 for a code unknown to RS274/NGC, -2 for one that is known but
// not supported here.
int groupOf(int code) {
  switch (code) {
    case kG4: case kG10: case kG28: case kG28_1: case kG30: case kG30_1: case kG53: case kG65:
    case kG52: case kG92: case kG92_1: case kG92_2: case kG92_3:
      return kGroupNonModal;
    case kG0: case kG1: case kG2: case kG3: case kG73: case kG74: case kG80: case kG81: case kG82: case kG83:
    case kG84: case kG85: case kG86: case kG88: case kG89:
      return kGroupMotion;
    case kG17: case kG18: case kG19: return kGroupPlane;
    case kG90: case kG91: return kGroupDistance;
    case kG90_1: case kG91_1: return kGroupArcDistance;
    case kG93: case kG94: return kGroupFeedMode;
    case kG20: case kG21: return kGroupUnits;
    case kG40: case kG41: case kG42: case kG41_1: case kG42_1: return kGroupCutterComp;
    case kG43: case kG43_1: case kG49: return kGroupToolLength;
    case kG98: case kG99: return kGroupRetract;
    case 540: case 541: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593:
      return kGroupCoordSystem;
    case kG61: case kG61_1: case kG64: return kGroupPathControl;
    case kG96: case kG97: return kGroupSpindleMode;
    case kG68: case kG69: return kGroupRotation;
    // Known RS274/NGC (LinuxCNC) codes that this interpreter does not model.
    case 50: case 51: case 52: case 53: case 70: case 80: case 171: case 181: case 191:
    case 330: case 331: case 382: case 383: case 384: case 385: case 432: case 760:
    case 870: case 950: case 700: case 710: case 711: case 720: case 721:
      return -2;
    default: return -1;
  }
}

enum MGroup { kMStop, kMToolChange, kMSpindle, kMCoolant, kMSubprogram, kMGroupCount };

int mGroupOf(int tenths) {
  switch (tenths) {
    case 0: case 10: case 20: case 300: case 600: return kMStop;
    case 60: return kMToolChange;
    case 30: case 40: case 50: return kMSpindle;
    case 980: case 990: return kMSubprogram;
    default: return -1;  // coolant and every other M code: accepted, no effect on motion
  }
}

}  // namespace

std::string fmtLength(double v) { return fmt::format("{:.4f}", v); }

InterpreterState::InterpreterState(const InterpreterOptions& options, InterpretResult& result, std::string source)
    : options_(options), result_(result), moves_(result.program.moves), source_(std::move(source)) {
  state_.position = options.startPosition;
  state_.g28 = options.g28Position;
  state_.g30 = options.g30Position;
  state_.inch = options.inchAtPowerOn;
  result_.program.inch = options.inchAtPowerOn;
  state_.plane = options.planeAtPowerOn;
  state_.incremental = options.incrementalAtPowerOn;
  // A canned cycle before any G98 / G99 retracts as the control powers on: LinuxCNC (rs274) to
  // the R level, Fanuc to the initial level.
  state_.retractToR = !options.fanuc;
  planeStated_ = distanceStated_ = !options.powerOnModesNamed;
  parameters_.bareSettings = options.fanuc;
  parameters_.set("_value", 0.0);  // as LinuxCNC: what the last call returned, 0 before any
  result_.program.source = source_;
  result_.program.start = options.startPosition;
  flow_.setFileFinder([this](const std::string& label, bool program) { return findSubroutineFile(label, program); });
  // LinuxCNC's #5420-#5428: where the tool is, in the program's coordinates and units (A, B, C,
  // U, V, W: 0); #5211-#5219: the G92 / G52 offset; the coordinate systems' (gcode_work_offsets.cpp).
  parameters_.setSystemReader([this](int number, double& value) {
    const double perMm = state_.inch ? 1 / kMmPerInch : 1.0;
    if (number >= 5420 && number <= 5428) {
      value = number <= 5422 ? (state_.position - state_.offset)[number - 5420] * perMm : 0.0;
      return true;
    }
    if (number >= 5211 && number <= 5219) {
      value = number <= 5213 ? state_.offset[number - 5211] * perMm : 0.0;
      return true;
    }
    return readMachineParameter(number, value);
  });
}

bool InterpreterState::fail(std::uint32_t column, std::string message) {
  errorColumn_ = column;
  errorMessage_ = std::move(message);
  return false;
}

void InterpreterState::warnOnce(bool& done, std::uint32_t column, std::string message) {
  if (done) return;
  done = true;
  result_.program.warnings.push_back(Diagnostic{source_, line_, column, std::move(message)});
}

namespace {

// Other controls' five-axis codes, named so that a program using them is told what is missing
// (the codes are in tenths: G43.4 is 434).
const char* fiveAxisCodeNotRead(int code) {
  switch (code) {
    case 434: return "Fanuc tool-centre-point control, type 1";
    case 435: return "Fanuc tool-centre-point control, type 2";
    case 682: return "a tilted working plane";
    case 683: return "a tilted working plane along the tool axis";
    case 531: return "a move of the tool axis to a tilted working plane";
    default: return nullptr;
  }
}

}  // namespace

bool InterpreterState::groupCodes(const Block& block, GroupedCodes& groups) {
  std::fill(std::begin(groups.code), std::end(groups.code), -1);
  for (int i = 0; i < block.gCount; ++i) {
    const int code = block.g[i];
    if (code == kG8 && block.has('P')) {
      // A Fanuc or Haas control's "G08 P1" / "G08 P0": high-speed look-ahead on or off. (In
      // LinuxCNC, G8 without P is a lathe's radius mode, not modelled here.)
      warnOnce(warnedLookAhead_, block.gColumn[i],
               "G08 P (high-speed look-ahead of Fanuc and Haas controls) does not change the path: ignored");
      continue;
    }
    const int group = groupOf(code);
    if (const char* fiveAxis = fiveAxisCodeNotRead(code))
      return fail(block.gColumn[i], fmt::format("G{} ({}) is not read: its motion would be the tool tip's as if the "
                                                "code were not there (docs/five-axis.md)",
                                                block.gValue[i], fiveAxis));
    if (group == -1)
      return fail(block.gColumn[i], fmt::format("Unknown g code used: G{}", block.gValue[i]));
    if (group == -2)
      return fail(block.gColumn[i], fmt::format("{} is not supported", codeName('G', code)));
    if (group == kGroupMotion && groups.code[group] >= 0 &&
        (code == kG80 || groups.code[group] == kG80)) {
      // "G0 G80" in one block (a common program header): cancel the cycle, keep the motion.
      if (code == kG80) continue;
    } else if (groups.code[group] >= 0) {
      return fail(block.gColumn[i],
                  fmt::format("Two g codes used from same modal group: {} and {}",
                              codeName('G', groups.code[group]), codeName('G', code)));
    }
    groups.code[group] = code;
    groups.column[group] = block.gColumn[i];
  }
  return true;
}

// One block in RS274/NGC's order of execution (the standard's table 8, as LinuxCNC follows it):
// kept as one function, longer than most, so that the order reads top to bottom as the table.
bool InterpreterState::executeBlock(const Block& block) {
  switch (block.kind) {
    case BlockKind::Deleted: return true;
    case BlockKind::Percent:
      if (!seenWords_) percentOpened_ = true;
      else if (percentOpened_) ended_ = true;
      seenWords_ = true;
      return true;
    case BlockKind::OWord: {
      seenWords_ = true;
      const ControlFlow::Outcome outcome = flow_.execute(lineStart_, lineEnd_, nextLine_);
      if (!outcome.ok) return fail(outcome.column, outcome.message);
      jump_ = outcome.jump;
      return true;
    }
    case BlockKind::SenderCommand:
      warnOnce(warnedSenderCommand_, 1, "a line for the sender, not G-code (grbl's '$' commands), is skipped");
      return true;
    case BlockKind::SenderComment:
      warnOnce(warnedSenderComment_, 1, "a sender's '#' comment line is skipped");
      return true;
    case BlockKind::Normal: break;
  }
  if (!block.hasWords()) return true;
  seenWords_ = true;

  GroupedCodes groups;
  if (!groupCodes(block, groups)) return false;

  // M codes: at most one per group among those that matter here.
  int mCode[kMGroupCount] = {-1, -1, -1, -1, -1};
  for (int i = 0; i < block.mCount; ++i) {
    const int group = mGroupOf(block.m[i]);
    if (block.m[i] >= 2000)
      warnOnce(warnedRemappedM_, block.mColumn[i],
               fmt::format("{} is a code of the control's own configuration (LinuxCNC's five-axis demos switch "
                           "tool-centre-point control with M428 and M429): it does not change the motion here, where "
                           "the machine description says whether X Y Z are the tool tip",
                           codeName('M', block.m[i])));
    if (group < 0) continue;
    if (mCode[group] >= 0)
      return fail(block.mColumn[i],
                  fmt::format("Two m codes used from same modal group: {} and {}",
                              codeName('M', mCode[group]), codeName('M', block.m[i])));
    mCode[group] = block.m[i];
  }

  const std::size_t movesBefore = moves_.size();

  // A call or a return changes whose parameters #1.. are: the line's settings are the caller's
  // (or the subprogram's), made before it. G65's letters are its arguments, not words.
  if (groups.code[kGroupNonModal] == kG65 || mCode[kMSubprogram] >= 0) parameters_.commit();
  if (groups.code[kGroupNonModal] == kG65) return macroCall(block, groups.column[kGroupNonModal]);

  // RS274/NGC order of execution: feed mode, F, S, T, M6, spindle, coolant, dwell, plane, units,
  // cutter compensation, tool length, coordinate system, path control, distance mode, retract
  // mode, home / non-modal codes, motion, stops.
  if (groups.has(kGroupFeedMode)) {
    const bool inverse = groups.code[kGroupFeedMode] == kG93;
    if (inverse != state_.inverseTime) {
      state_.inverseTime = inverse;
      state_.feed = 0;  // a feed rate has to be given again in the new mode
    }
  }
  if (block.has('F')) {
    const double f = block.get('F');
    if (f < 0) return fail(block.col('F'), "Negative F word used");
    state_.feed = state_.inverseTime ? f : length(f);
  }
  if (block.has('S') && block.get('S') < 0)
    return fail(block.col('S'), "Negative spindle speed used");
  // What the control's task waits for the motion before it does: a tool or spindle change, the
  // spindle's speed, the coolant, a tool length offset or another coordinate system (LinuxCNC 2.9's
  // emcTaskCheckPreconditions; a Fanuc control's M codes wait alike unless made to run ahead).
  bool coolant = false;  // M7 M8 M9 (M7 and M8 may stand together)
  for (int i = 0; i < block.mCount; ++i) coolant = coolant || block.m[i] == 70 || block.m[i] == 80 || block.m[i] == 90;
  const bool stopBefore = mCode[kMToolChange] >= 0 || mCode[kMSpindle] >= 0 || coolant ||
                          block.has('S') || groups.has(kGroupToolLength) ||
                          (groups.has(kGroupCoordSystem) && groups.code[kGroupCoordSystem] != state_.coordSystem);

  if (block.has('T')) {
    const double t = block.get('T');
    if (t < 0 || std::fabs(t - std::nearbyint(t)) > kWholeNumberTolerance)
      return fail(block.col('T'), "T word must be a tool number (a whole number, 0 or more)");
    selectedTool_ = static_cast<int>(std::nearbyint(t));
  }
  if (mCode[kMToolChange] == 60) spindleTool_ = selectedTool_;
  if (!compensationAllows(groups, groups.has(kGroupMotion) ? groups.code[kGroupMotion] : state_.motion)) return false;
  moveColumn_ = groups.column[kGroupNonModal];  // G4, G28, G30; motion words below
  if (groups.code[kGroupNonModal] == kG4 && !dwell(block, groups.column[kGroupNonModal]))
    return false;
  applyModalCodes(groups);
  if (groups.has(kGroupToolLength))
    state_.toolLengthZ = groups.code[kGroupToolLength] == kG43_1 && block.has('Z') ? length(block.get('Z')) : 0.0;
  if (groups.has(kGroupPathControl) && groups.code[kGroupPathControl] == kG64) {
    for (char letter : {'P', 'Q'})
      if (block.has(letter) && !(block.get(letter) >= 0))
        return fail(block.col(letter), fmt::format("G64 {} must be a tolerance of 0 or more", letter));
    applyPathBlending(block);
  }
  if (groups.has(kGroupUnits)) {
    unitsStated_ = true;
    if (!unitsRecorded_) result_.program.inch = state_.inch;
    unitsRecorded_ = true;
  }
  if (groups.has(kGroupPlane)) planeStated_ = true;
  if (groups.has(kGroupDistance)) distanceStated_ = true;
  if (!distanceStated_ && hasAxisWords(block))
    warnOnce(distanceStated_, 1,
             fmt::format("no G90 or G91 before the first move: the control's power-on distance mode ({}) is used",
                         options_.incrementalAtPowerOn ? "G91, incremental" : "G90, absolute"));
  if (!planeStated_ && (block.has('I') || block.has('J') || block.has('K') || block.has('R')))
    warnOnce(planeStated_, 1,
             fmt::format("no G17, G18 or G19 before the first arc: the control's power-on plane (G{}) is used",
                         static_cast<int>(options_.planeAtPowerOn)));
  if (groups.has(kGroupCutterComp) &&
      !setCutterComp(block, groups.code[kGroupCutterComp], groups.column[kGroupCutterComp]))
    return false;
  if (!unitsStated_ && (hasAxisWords(block) || block.has('F')))
    warnOnce(unitsStated_, 1,
             fmt::format("no G20 or G21 before the first length: the control's power-on units ({}) are used{}",
                         options_.inchAtPowerOn ? "inch, G20" : "mm, G21",
                         commentSaysInches_ && !options_.inchAtPowerOn
                             ? ", though its comments speak of inches: a control powered on in inches reads it so "
                               "(--machine resources/machines/fanuc-inch.json, or \"units_at_power_on\": \"inch\")"
                             : ""));

  // Non-modal codes that take the axis words.
  const int nonModal = groups.code[kGroupNonModal];
  const bool axesForNonModal = nonModal == kG10 || nonModal == kG28 || nonModal == kG30 || nonModal == kG65 ||
                               nonModal == kG92 || nonModal == kG52 || groups.code[kGroupRotation] == kG68 ||
                               groups.code[kGroupToolLength] == kG43_1;
  if (groups.has(kGroupRotation) &&
      !setRotation(block, groups.code[kGroupRotation], groups.column[kGroupRotation]))
    return false;
  machineCoordinates_ = nonModal == kG53;
  const bool axes = hasAxisWords(block);
  if (axesForNonModal && groups.has(kGroupMotion) && groups.code[kGroupMotion] != kG80 && axes)
    return fail(groups.column[kGroupMotion],
                "Cannot use two G codes that both use axis values");
  // G65's A, B and C are a macro's arguments. G28 and G30 would move the rotary axes through
  // their reference positions: refused (a zero while they stand at zero changes nothing). An
  // offset of the rotary axes (G10, G52, G92) is kept in mind: a rotary move after it is refused
  // (rotaryOffsetLine_), as its offset is not modelled.
  if (axesForNonModal && nonModal != kG65)
    for (char c : {'A', 'B', 'C'}) {
      if (!block.has(c)) continue;
      const bool still = block.get(c) == 0 && state_.rotary == std::array<double, 3>{};
      if ((nonModal == kG28 || nonModal == kG30 || groups.code[kGroupRotation] == kG68) && !still)
        return fail(block.col(c), fmt::format("{} word with G28, G30 or G68 (reference moves of the rotary axes) is not "
                                              "supported",
                                              c));
      if (block.get(c) != 0 && rotaryOffsetLine_ == 0) rotaryOffsetLine_ = moveLine();
    }
  if (nonModal == kG92 || nonModal == kG52 || nonModal == kG92_1 || nonModal == kG92_2 || nonModal == kG92_3) {
    if (!setOffset(block, nonModal)) return false;
  } else if (nonModal == kG28 || nonModal == kG30) {
    if (!homeMove(block, nonModal)) return false;
  } else if (nonModal == kG28_1) {
    state_.g28 = machineOf(state_.position);
  } else if (nonModal == kG30_1) {
    state_.g30 = machineOf(state_.position);
  } else if (nonModal == kG10) {
    if (!setWorkOffset(block, groups.column[kGroupNonModal])) return false;
  }

  // Motion.
  const bool explicitMotion = groups.has(kGroupMotion);
  int motion = explicitMotion ? groups.code[kGroupMotion] : state_.motion;
  // Fanuc: the cycles are a modal group of their own; G80 leaves G0-G3 as they were.
  if (options_.fanuc && !explicitMotion && motion == kG80) motion = state_.pathMotion;
  const std::uint32_t motionColumn =
      explicitMotion ? groups.column[kGroupMotion] : 0;
  bool arcRan = false, cycleRan = false;
  if (!axesForNonModal) {
    const bool arcWords = block.has('I') || block.has('J') || block.has('K') || block.has('R');
    const bool isArc = motion == kG2 || motion == kG3;
    // Axis words of a line without a G code continue the modal motion: blame the first of them.
    std::uint32_t column = motionColumn;
    if (column == 0) {
      for (char c : {'X', 'Y', 'Z', 'A', 'B', 'C'})
        if (block.has(c)) {
          column = block.col(c);
          break;
        }
    }
    if (motion == kG80) {
      if (axes)
        return fail(column, explicitMotion ? "Cannot use axis values with G80"
                            : options_.fanuc
                                ? "Cannot use axis values without a g code that uses them"
                                : "Cannot use axis values without a g code that uses them (after G80 LinuxCNC has no "
                                  "motion mode; a Fanuc or Haas control goes on with the G0 or G1 before the cycle: "
                                  "read it with a Fanuc machine, \"control\": {\"dialect\": \"fanuc\"}, e.g. "
                                  "--machine resources/machines/fanuc-inch.json)");
    } else if (axes || (explicitMotion && isArc && arcWords)) {
      if (nonModal == kG53) {
        if (motion != kG0 && motion != kG1)
          return fail(groups.column[kGroupNonModal], "Must use G0 or G1 with G53");
        if (state_.incremental)
          return fail(groups.column[kGroupNonModal], "Cannot use G53 incremental");
      }
      moveColumn_ = column;
      if (!readRotaryWords(block, motion, nonModal, column)) return false;
      if (motion == kG0 || motion == kG1) {
        if (!straight(block, motion, column)) return false;
      } else if (isArc) {
        if (!arc(block, motion, column)) return false;
        arcRan = true;
      } else if (isCycle(motion)) {
        if (!cycle(block, motion, column)) return false;
        cycleRan = true;
      }
    }
  }
  if (explicitMotion) state_.motion = motion;
  if (explicitMotion && (motion == kG0 || motion == kG1 || motion == kG2 || motion == kG3)) state_.pathMotion = motion;


  // Words that no code of this block used.
  for (char c : {'I', 'J', 'K'}) {
    if (c == 'K' && mCode[kMSubprogram] == 980) continue;  // M98's count of runs (M98 P2 K3)
    if (block.has(c) && !arcRan)
      return fail(block.col(c),
                  fmt::format("{} word with no G2 or G3 to use it", static_cast<char>(c | 0x20)));
  }
  if (block.has('R') && !arcRan && !cycleRan && nonModal != kG10 && groups.code[kGroupRotation] != kG68 &&
      !(explicitMotion && isCycle(motion)))
    return fail(block.col('R'), "R word with no g code that uses it");

  // Spindle and tool changes happen before this block's motion: the previous move ends at rest.
  if (stopBefore && movesBefore > 0) moves_[movesBefore - 1].flags |= kStopAfter;
  if (mCode[kMStop] >= 0) {
    if (!moves_.empty()) moves_.back().flags |= kStopAfter;
    if (mCode[kMStop] == 20 || mCode[kMStop] == 300) ended_ = true;
  }
  const bool frameCodes = nonModal == kG92 || nonModal == kG52 || nonModal == kG92_1 || nonModal == kG92_2 ||
                          nonModal == kG92_3 || groups.has(kGroupRotation);
  if (frameCodes) noteFrame();
  if (mCode[kMSubprogram] >= 0) return subprogram(block, mCode[kMSubprogram]);
  return true;
}

void InterpreterState::applyModalCodes(const GroupedCodes& groups) {
  if (groups.has(kGroupPlane)) {
    const int code = groups.code[kGroupPlane];
    state_.plane = code == kG17 ? Plane::XY : code == kG18 ? Plane::ZX : Plane::YZ;
  }
  if (groups.has(kGroupUnits)) state_.inch = groups.code[kGroupUnits] == kG20;
  if (groups.has(kGroupToolLength)) state_.toolLength = groups.code[kGroupToolLength];
  if (groups.has(kGroupCoordSystem)) selectCoordSystem(groups.code[kGroupCoordSystem]);
  if (groups.has(kGroupPathControl)) {
    state_.exactStop = groups.code[kGroupPathControl] != kG64;
    state_.exactPath = groups.code[kGroupPathControl] == kG61;
  }
  if (groups.has(kGroupDistance)) state_.incremental = groups.code[kGroupDistance] == kG91;
  if (groups.has(kGroupArcDistance)) state_.arcAbsolute = groups.code[kGroupArcDistance] == kG90_1;
  if (groups.has(kGroupRetract)) state_.retractToR = groups.code[kGroupRetract] == kG99;
}

bool InterpreterState::readRotaryWords(const Block& block, int motion, int nonModal, std::uint32_t column) {
  std::uint32_t rotaryColumn = 0;
  for (char c : {'A', 'B', 'C'})
    if (block.has(c) && rotaryColumn == 0) rotaryColumn = block.col(c);
  if (rotaryColumn == 0) return true;
  // What is not modelled of the rotary axes is refused, never read as if they stood still.
  if (isCycle(motion)) return fail(rotaryColumn, "A, B or C words in a canned cycle are not supported");
  if (state_.cutterComp != kG40)
    return fail(rotaryColumn, "A, B or C words under cutter radius compensation (G41/G42) are not supported");
  if (rotaryOffsetLine_ != 0)
    return fail(rotaryColumn, fmt::format("A, B or C words after an offset of the rotary axes (G10, G52 or G92 with A, "
                                          "B or C, line {}) are not supported",
                                          rotaryOffsetLine_));
  (void)column;
  for (int i = 0; i < 3; ++i) {
    const char c = "ABC"[i];
    if (!block.has(c)) continue;
    const double v = block.get(c);  // degrees, in inch programs too
    // With no offset of the rotary axes (refused above), their machine coordinates (G53) are
    // the program's.
    state_.rotary[i] = state_.incremental && nonModal != kG53 ? state_.rotary[i] + v : v;
  }
  return true;
}

void InterpreterState::noteRotary() {
  rotaryNoted_ = state_.rotary;
  const RotaryPosition change{movesMade(), state_.rotary};
  std::vector<RotaryPosition>& changes = result_.program.rotary;
  if (!changes.empty() && changes.back().move == change.move) changes.back() = change;
  else changes.push_back(change);
  if (sink_) sink_->rotaryChanged(change);
}

// G64 alone blends without a tolerance of its own; P without Q merges lines within P, as
// LinuxCNC reads it. Told to the program (and a streaming sink) only when they change.
void InterpreterState::applyPathBlending(const Block& block) {
  const double toMm = state_.inch ? 25.4 : 1.0;
  const double blend = block.has('P') ? block.get('P') * toMm : 0.0;
  const double merge = block.has('Q') ? block.get('Q') * toMm : blend;
  if (blend == state_.blendTolerance && merge == state_.mergeTolerance) return;
  state_.blendTolerance = blend;
  state_.mergeTolerance = merge;
  const PathBlending change{movesMade(), blend, merge};
  std::vector<PathBlending>& changes = result_.program.blending;
  if (!changes.empty() && changes.back().firstMove == change.firstMove) changes.back() = change;
  else changes.push_back(change);
  if (sink_) sink_->blendingChanged(change);
}

}  // namespace gcode

InterpretResult interpretGcode(std::string_view text, const std::string& sourceName,
                               const InterpreterOptions& options) {
  InterpretResult result;
  gcode::InterpreterState state(options, result, sourceName);
  state.run(text);
  return result;
}

namespace {

StreamedInterpretation streamText(std::string_view text, const std::string& sourceName, MoveSink& sink,
                                  const InterpreterOptions& options, std::size_t chunkMoves,
                                  std::function<void(const char*)> released) {
  InterpretResult result;
  gcode::InterpreterState state(options, result, sourceName);
  state.streamTo(sink, chunkMoves, std::move(released));
  state.run(text);
  StreamedInterpretation out;
  out.source = std::move(result.program.source);
  out.start = result.program.start;
  out.warnings = std::move(result.program.warnings);
  out.errors = std::move(result.errors);
  out.lineCount = result.program.lineCount;
  out.moveCount = state.movesMade();
  return out;
}

// The options for a file: its own folder is searched for subroutine files last.
InterpreterOptions withProgramFolder(const std::string& path, const InterpreterOptions& options) {
  InterpreterOptions withFolder = options;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  withFolder.subroutinePath.push_back(folder.empty() ? "." : folder.string());
  return withFolder;
}

}  // namespace

InterpretResult interpretGcodeFile(const std::string& path, const InterpreterOptions& options) {
  InterpretResult result;
  const std::string error = gcode::withFileText(path, true, [&](std::string_view text, bool) {
    result = interpretGcode(text, path, withProgramFolder(path, options));
  });
  if (!error.empty()) {
    result = InterpretResult{};
    result.program.source = path;
    result.errors.push_back(Diagnostic{path, 0, 0, error});
  }
  return result;
}

StreamedInterpretation interpretGcodeStream(std::string_view text, const std::string& sourceName,
                                            MoveSink& sink, const InterpreterOptions& options,
                                            std::size_t chunkMoves) {
  return streamText(text, sourceName, sink, options, chunkMoves, {});
}

StreamedInterpretation interpretGcodeFileStream(const std::string& path, MoveSink& sink,
                                                const InterpreterOptions& options, std::size_t chunkMoves) {
  StreamedInterpretation result;
  const std::string error = gcode::withFileText(path, false, [&](std::string_view text, bool mapped) {
    const char* base = text.data();
    const long page = ::sysconf(_SC_PAGESIZE);
    std::size_t releasedBytes = 0;
    auto release = [base, page, &releasedBytes](const char* upTo) {
      // The mapping is private and read-only: its dropped pages are read again if touched.
      const auto bytes = static_cast<std::size_t>(upTo - base) & ~static_cast<std::size_t>(page - 1);
      if (bytes <= releasedBytes) return;
      ::madvise(const_cast<char*>(base + releasedBytes), bytes - releasedBytes, MADV_DONTNEED);
      releasedBytes = bytes;
    };
    result = streamText(text, path, sink, withProgramFolder(path, options), chunkMoves,
                        mapped ? std::function<void(const char*)>(release) : nullptr);
  });
  if (!error.empty()) {
    result = StreamedInterpretation{};
    result.source = path;
    result.errors.push_back(Diagnostic{path, 0, 0, error});
  }
  return result;
}

}  // namespace isurface
