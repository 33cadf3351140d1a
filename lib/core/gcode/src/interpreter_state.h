#pragma once
// The interpreter's state behind interpretGcode (RS274/NGC): modal state, one block's
// execution, moves out. Private to the gcode module; split over gcode_interpreter.cpp (blocks
// and modal codes), gcode_motion.cpp (straight moves, arcs, dwell, G28/G30) and gcode_cycles.cpp
// (canned cycles). Not the machine description (isurface/machine/machine.h).
#include <array>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gcode_lexer.h"
#include "gcode_control_flow.h"
#include "gcode_cutter_comp.h"
#include "gcode_fanuc_macro.h"
#include "gcode_parameters.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/gcode/gcode_stream.h"
#include "isurface/base/units.h"

namespace isurface::gcode {

// G codes in tenths.
enum GCode : int {
  kG0 = 0, kG1 = 10, kG2 = 20, kG3 = 30, kG4 = 40, kG8 = 80, kG10 = 100, kG52 = 520, kG65 = 650,
  kG92 = 920, kG92_1 = 921, kG92_2 = 922, kG92_3 = 923,
  kG17 = 170, kG18 = 180, kG19 = 190, kG20 = 200, kG21 = 210,
  kG28 = 280, kG28_1 = 281, kG30 = 300, kG30_1 = 301,
  kG40 = 400, kG41 = 410, kG41_1 = 411, kG42 = 420, kG42_1 = 421,
  kG43 = 430, kG43_1 = 431, kG49 = 490, kG53 = 530,
  kG61 = 610, kG61_1 = 611, kG64 = 640, kG68 = 680, kG69 = 690,
  kG73 = 730, kG74 = 740, kG80 = 800, kG81 = 810, kG82 = 820, kG83 = 830, kG84 = 840, kG85 = 850,
  kG86 = 860, kG88 = 880, kG89 = 890,
  kG90 = 900, kG90_1 = 901, kG91 = 910, kG91_1 = 911,
  kG93 = 930, kG94 = 940, kG96 = 960, kG97 = 970, kG98 = 980, kG99 = 990,
};

// Modal groups of the G codes understood here.
enum Group : int {
  kGroupNonModal = 0,  // G4 G10 G28 G28.1 G30 G30.1 G53
  kGroupMotion,        // G0 G1 G2 G3 G73 G74 G80 G81-G86 G88 G89
  kGroupPlane,         // G17 G18 G19
  kGroupDistance,      // G90 G91
  kGroupArcDistance,   // G90.1 G91.1
  kGroupFeedMode,      // G93 G94
  kGroupUnits,         // G20 G21
  kGroupCutterComp,    // G40 G41 G42 G41.1 G42.1
  kGroupToolLength,    // G43 G43.1 G49
  kGroupRetract,       // G98 G99
  kGroupCoordSystem,   // G54 .. G59.3, G54.1 P (Fanuc and Haas extended work offsets)
  kGroupPathControl,   // G61 G61.1 G64
  kGroupSpindleMode,   // G96 G97
  kGroupRotation,      // G68 G69 (Fanuc's coordinate rotation in the plane)
  kGroupCount
};

inline bool isCycle(int motion) {
  switch (motion) {
    case kG73: case kG74: case kG81: case kG82: case kG83: case kG84: case kG85: case kG86: case kG88: case kG89:
      return true;
    default: return false;
  }
}

// A LinuxCNC coordinate system (G54-G59.3): its origin in machine coordinates (mm) and its XY
// rotation (degrees, G10 L2 R).
struct WorkSystem {
  Vec3 origin = Vec3::Zero();
  double rotation = 0;
};

// 1-9 for G54-G59.3 (coordSystem codes 540-593); 0 for any other (Fanuc's G54.1 P).
int workSystemIndex(int coordSystem);

// Everything that persists from block to block. Small, so a block can be undone by copying.
struct ModalState {
  Vec3 position = Vec3::Zero();  // mm
  std::array<double, 3> rotary{};  // A, B, C, deg, as the program writes them
  int motion = kG80;
  int pathMotion = kG80;        // the last of G0-G3 given (Fanuc's group 01)
  Plane plane = Plane::XY;
  bool inch = false;
  bool incremental = false;     // G91
  bool arcAbsolute = false;     // G90.1
  bool inverseTime = false;     // G93
  bool exactStop = false;       // G61 / G61.1
  bool exactPath = false;       // G61
  double blendTolerance = 0;    // mm, G64 P
  double mergeTolerance = 0;    // mm, G64 Q
  bool retractToR = false;      // G99 (else G98: back to the initial level); at power-on per dialect
  int cutterComp = kG40;
  int toolLength = kG49;
  int coordSystem = 540;
  std::array<WorkSystem, 10> work{};  // by workSystemIndex
  double toolLengthZ = 0;             // mm, G43.1 Z (G43 H: not known, 0)
  double feed = 0;              // mm/min (G94) or 1/min (G93)
  // Canned cycle words kept from block to block, mm and seconds.
  double cycleR = 0, cycleZ = 0, cycleQ = 0, cycleP = 0;
  Plane cyclePlane = Plane::XY;  // the plane of the last cycle block (its levels are along its normal)
  Vec3 g28 = Vec3::Zero(), g30 = Vec3::Zero();
  // G92 / G52: the program's coordinates plus this are the workpiece's (mm); `offsetStored` is
  // the last one set (G92.3 brings it back).
  Vec3 offset = Vec3::Zero(), offsetStored = Vec3::Zero();
  double cycleStartZ = 0;       // mm, where the canned cycle began (its G91 R is measured from it)
  // LinuxCNC's G84 / G74 in G18 or G19 left the tool away from `position` (gcode_cycles.cpp);
  // the next move starts where the tool is.
  bool tapEndedElsewhere = false;
  // G68: the program's coordinates turn by `rotation` (radians, counter-clockwise about the
  // plane's normal) about `rotationCentre` (program coordinates, mm) in `rotationPlane`.
  double rotation = 0;
  Vec3 rotationCentre = Vec3::Zero();
  Plane rotationPlane = Plane::XY;
};

// One block's G codes sorted by modal group.
struct GroupedCodes {
  int code[kGroupCount];
  std::uint32_t column[kGroupCount];
  bool has(Group g) const { return code[g] >= 0; }
};

class InterpreterState {
 public:
  InterpreterState(const InterpreterOptions& options, InterpretResult& result, std::string source);

  // Hands the moves to `sink` in chunks of about `chunkMoves` between blocks instead of keeping
  // them all; `released(p)` is told now and then that the text before p is no longer needed.
  void streamTo(MoveSink& sink, std::size_t chunkMoves, std::function<void(const char*)> released);

  // Interprets the whole text.
  void run(std::string_view text);

  std::uint64_t movesMade() const { return delivered_ + moves_.size(); }

 private:
  // gcode_interpreter.cpp
  void runLine(const char* begin, const char* end);
  // A block's words, lexed and executed (a line, or what follows a Fanuc IF .. THEN).
  bool runBlock(const char* begin, const char* end);
  // Streaming: hands over every move but the last, which a later block may still mark as
  // ending at rest (M0, M6, a spindle change); all of them when `all`.
  void deliverMoves(bool all);
  // The first move that a later block may still change: the last one, or the open offset move.
  std::size_t firstHeldMove() const;
  // Compensation as it was before a block, to undo a bad one.
  struct CompensationSnapshot {
    CutterCompensation comp;
    std::vector<std::pair<std::uint64_t, Vec3>> openMoves;  // index and end
  };
  CompensationSnapshot compensationSnapshot() const;
  void restoreCompensation(const CompensationSnapshot& snapshot);
  bool executeBlock(const Block& block);
  bool groupCodes(const Block& block, GroupedCodes& groups);
  void applyModalCodes(const GroupedCodes& groups);
  void applyPathBlending(const Block& block);
  // A block's A, B and C words: the rotary position its G0-G3 move ends at (false: refused).
  bool readRotaryWords(const Block& block, int motion, int nonModal, std::uint32_t column);
  // Tells the program (and a streaming sink) the rotary position the next move ends at.
  void noteRotary();
  std::uint8_t pathFlags() const {
    return static_cast<std::uint8_t>((state_.exactStop ? kExactStop : 0) | (state_.exactPath ? kExactPath : 0));
  }
  void warnOnce(bool& done, std::uint32_t column, std::string message);

  // gcode_motion.cpp
  double length(double programValue) const {
    return state_.inch ? programValue * kMmPerInch : programValue;
  }
  Vec3 targetOf(const Block& block) const;  // axis words applied to the current position
  Vec3 programOffset() const { return machineCoordinates_ ? Vec3::Zero() : state_.offset; }
  bool setOffset(const Block& block, int code);  // G92, G92.1-G92.3, G52
  // gcode_work_offsets.cpp: G54-G59.3 origins and rotations, G10 L2 / L20, G53.
  Vec3 machineOf(const Vec3& position) const;
  Vec3 workOf(const Vec3& machine) const;
  void selectCoordSystem(int code);
  bool setWorkOffset(const Block& block, std::uint32_t column);
  bool machineTarget(const Block& block, std::uint32_t column, Vec3& target);
  // #5021-#5029 (machine position), #5161-#5169 / #5181-#5189 (G28 / G30), #5220 (the active
  // system), #5221-#5410 (the systems' origins and rotations), in program units.
  bool readMachineParameter(int number, double& value) const;
  // G68 / G69 (gcode_rotation.cpp); a program point (offsets included) turned as G68 says, and
  // back; a vector (I, J, K) turned alike.
  bool setRotation(const Block& block, int code, std::uint32_t column);
  Vec3 rotated(const Vec3& p) const;
  Vec3 unrotated(const Vec3& p) const;
  Vec3 rotatedVector(const Vec3& v) const;
  // Program::frames told of a change of G92 / G52 offset or G68 rotation (not when streaming).
  void noteFrame();
  bool hasAxisWords(const Block& block) const;
  bool straight(const Block& block, int motion, std::uint32_t column);
  bool arc(const Block& block, int motion, std::uint32_t column);
  bool dwell(const Block& block, std::uint32_t column);
  bool homeMove(const Block& block, int code);
  // Through cutter radius compensation when it is on (gcode_cutter_comp_use.cpp), else as is.
  bool emitPath(MoveKind kind, const Vec3& end, const Vec3& centre, unsigned turns, float feed, std::uint32_t column);
  void emit(MoveKind kind, const Vec3& end, float feed, std::uint8_t extraFlags = 0);
  void emitArc(MoveKind kind, const Vec3& end, const Vec3& centre, unsigned turns, float feed);

  // gcode_cutter_comp_use.cpp: G40 / G41 / G42 / G41.1 / G42.1, and what compensation forbids.
  bool setCutterComp(const Block& block, int code, std::uint32_t column);
  bool compensationAllows(const GroupedCodes& groups, int motion);
  bool compensating() const { return comp_.on(); }

  // gcode_cycles.cpp
  bool cycle(const Block& block, int motion, std::uint32_t column);

  // gcode_subprograms.cpp: Fanuc's M98 / M99 (code 980 or 990) and G65 macro calls
  bool subprogram(const Block& block, int code);
  bool macroCall(const Block& block, std::uint32_t column);

  bool fail(std::uint32_t column, std::string message);

  // gcode_subroutine_files.cpp
  std::optional<LinePosition> findSubroutineFile(const std::string& label, bool program);
  // Reading goes on at `at`: in the main text or in a subroutine file.
  void enterTextOf(const char* at);
  // At the end of a subroutine file's text: false (with an error) when nothing goes on.
  bool leaveFile(const char*& p);
  // The line a move carries: the main text's, or the line that called into the file read.
  std::uint32_t moveLine() const { return reading_ ? callLine_ : line_; }
  // Its column: unknown for moves made in another file's text (their line is the call's).
  std::uint16_t moveColumn() const {
    return reading_ || moveColumn_ > 0xffff ? 0 : static_cast<std::uint16_t>(moveColumn_);
  }
  // M99 P: the block numbered `number` in the text `from` is in.
  std::optional<LinePosition> blockInTextOf(long number, LinePosition from);
  // Tells options_.callStack the calls the next move is made in.
  void reportCallStack() const;

  // gcode_run_bound.cpp: the run's bound on lines read again (InterpreterOptions::
  // maxLinesReadAgain): the lines read, executed or read past, may outnumber the lines of the
  // texts by that much. Lines read in search of a subroutine or subprogram are not counted (a
  // label is searched for once): a Fanuc program whose subprograms follow its M30 reads its
  // main part once as blocks. Counts the line from `p` to `lineEnd` in the text being read;
  // false (with the error) once the bound is passed.
  bool countLineRead(const char* p, const char* lineEnd) {
    const char*& readUpTo = reading_ ? reading_->readUpTo : mainReadUpTo_;
    if (!readUpTo || p > readUpTo) readUpTo = lineEnd, ++linesOfTexts_;
    if (!flow_.searching()) ++linesRead_;
    return linesRead_ <= linesOfTexts_ + options_.maxLinesReadAgain || stopNeverEnding();
  }
  bool stopNeverEnding();
  // The path of the text `at` points into: the main program's or a subroutine file's.
  const std::string& pathOfText(const char* at) const;
  // Where the last jump back went from and to (a loop's end, M99, GOTO), in the text read.
  struct SubroutineFile;
  struct JumpBack {
    const SubroutineFile* file = nullptr;  // null: the main text
    std::uint32_t from = 0, to = 0;
  };
  void noteJump(LinePosition from, LinePosition to) {
    if (to.at <= from.at && to.at >= (reading_ ? reading_->text.data() : mainText_.begin))
      lastJumpBack_ = JumpBack{reading_, from.line, to.line};
  }

  const InterpreterOptions& options_;
  InterpretResult& result_;
  std::vector<Move>& moves_;
  std::string source_;
  ModalState state_;
  std::uint32_t line_ = 0;        // current physical line, 1-based
  std::uint32_t moveColumn_ = 0;  // column of the word whose moves are being made (Move::column)
  bool ended_ = false;            // M2 / M30 / closing '%'
  bool percentOpened_ = false;    // the first line with words was '%'
  bool seenWords_ = false;
  std::array<double, 3> rotaryNoted_{};  // the rotary position last told to the program
  std::uint32_t rotaryOffsetLine_ = 0;    // the first line that offset a rotary axis (0: none)
  bool warnedSpindleMode_ = false, warnedSenderCommand_ = false, warnedSenderComment_ = false;
  bool warnedLookAhead_ = false, warnedPeckTapping_ = false, warnedMainM99_ = false;
  bool warnedRemappedM_ = false;
  bool warnedLinuxcncTap_ = false;
  bool unitsStated_ = false, planeStated_ = true, distanceStated_ = true;
  bool commentSaysInches_ = false;  // a comment before the first length speaks of inches
  bool unitsRecorded_ = false;  // the first G20/G21 has set Program::inch
  bool machineCoordinates_ = false;  // this block is G53: no G92 / G52 offset      // G20 or G21 given (or the power-on units' warning made)
  // The error of the block being executed.
  std::uint32_t errorColumn_ = 0;
  std::string errorMessage_;
  Block block_;
  // The main text and the subroutine files read (a deque: their texts stay where they are).
  struct SubroutineFile {
    std::string path;
    std::string text;
    const char* readUpTo = nullptr;  // the end of the furthest line read in it
  };
  struct TextSpan {
    const char* begin = nullptr;
    const char* end = nullptr;
  };
  TextSpan mainText_;
  std::string lineFedText_;  // the main text, when its lines end in lone carriage returns
  std::deque<SubroutineFile> files_;
  SubroutineFile* reading_ = nullptr;        // null: the main text
  const char* textEnd_ = nullptr;            // the end of the text being read
  std::uint32_t callLine_ = 0;               // while in a file: the main text's calling line
  const char* mainLeftAt_ = nullptr;         // the main text's line after that call
  // Cutter radius compensation, and the moves that end where its open offset move ends (their
  // indices counted from the first move made; they are not delivered while it is open).
  CutterCompensation comp_;
  std::vector<std::uint64_t> compOpenMoves_;
  int selectedTool_ = 0, spindleTool_ = 0;  // T word; the tool M6 put in the spindle
  Parameters parameters_;
  ControlFlow flow_{parameters_};
  FanucMacro macro_{parameters_};
  // The line being executed, the one after it, and where an O-word sends execution instead.
  LinePosition lineStart_, nextLine_;
  const char* lineEnd_ = nullptr;
  std::optional<LinePosition> jump_;
  // Streaming (null sink_: every move stays in the program).
  MoveSink* sink_ = nullptr;
  std::size_t chunkMoves_ = 0;
  std::uint64_t delivered_ = 0;
  std::function<void(const char*)> released_;
  // The run's bound (gcode_run_bound.cpp).
  const char* mainReadUpTo_ = nullptr;  // the end of the furthest line read in the main text
  std::uint64_t linesRead_ = 0, linesOfTexts_ = 0;  // the second: each line once, when first reached
  std::optional<JumpBack> lastJumpBack_;
};

// Formats a length for messages: 4 decimals.
std::string fmtLength(double v);

}  // namespace isurface::gcode
