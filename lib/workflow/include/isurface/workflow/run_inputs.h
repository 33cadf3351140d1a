#pragma once
// Opening what a user brings: a G-code program, a Biip dump (simulated or a machine trace), or
// both, joined. Written once for the command line and the application. Errors are InputError
// naming the file (and line); a progress callback may throw to cancel.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/base/progress.h"
#include "isurface/base/trajectory.h"
#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/io/trajectory_loading.h"
#include "isurface/machine/machine.h"

namespace isurface {

class BiipReader;

// True when the file starts with a Biip dump's magic bytes: the format is decided by content,
// not by the name's extension.
bool isBiipFile(const std::string& path);

// A program and the dump made from it, as a user names them; either may be empty.
struct RunFiles {
  std::string program, dump;
};

// Files as named on a command line or dropped together: a dump right after a program joins
// that program; any other file stands alone.
std::vector<RunFiles> pairRunFiles(const std::vector<std::string>& paths);

// Throws InputError naming `path` when its program makes no move (an empty file, only
// comments or modal words): there is no motion to simulate, measure or map, and a result made
// of the machine standing still would look like one. Every reading of a program to be
// simulated goes through here.
void requireMotion(const std::string& path, std::uint64_t moves);

// How `machine`'s control reads a program: its dialect, power-on units and reference positions.
InterpreterOptions interpreterOptions(const Machine& machine);

// Interprets a program as `machine`'s control reads it; its warnings go to `warnings`, its first
// error is thrown (with options.keepGoing every error is reported by the caller's printer
// first, see cli).
Program readProgram(const std::string& path, const ProgressCallback& progress = {},
                    std::vector<std::string>* warnings = nullptr, const Machine& machine = defaultMachine());

// The machine a dump's metadata says it was made with (a simulation's dump names it), if any.
std::optional<Machine> machineOfDump(const BiipReader& reader);

// Why a dump cannot belong to a program, or nothing when it may: its metadata names another
// program, its line numbers run past the program's last line, or its samples leave the
// program's path (more than 1 % of the samples checked lie farther than kJoinDistance from
// every move near their line).
std::optional<std::string> dumpMismatch(const BiipReader& dump, const Trajectory& samples, const Program& program);
// Why samples with G-code lines are not a run of `program` (they name lines it does not have, or
// lie away from its moves of their lines); nullopt when they may be.
std::optional<std::string> samplesMismatch(const Trajectory& samples, const Program& program);
constexpr double kJoinDistance = 1.0;  // mm

// A dump refused as another program's: the message names both files and why. A caller may
// offer an override (the CLI's --force) or open the program alone (the application).
class DumpMismatchError : public InputError {
 public:
  using InputError::InputError;
};

struct OpenRunRequest {
  RunFiles files;
  // The machine to simulate with when there is no dump; when empty, the default machine.
  std::optional<Machine> machine;
  TrajectoryChannels channels;  // kept of a dump, or of a simulation (its feedback)
  bool force = false;  // join a dump to a program that does not look like its own
  // A dump whose samples need more than the free memory is thinned to fit in half of it (one
  // record in k, with a warning saying so) instead of being refused.
  bool thinToFit = false;
};

// Where the servo's positions of samples opened without them come from, when a view asks for
// them: the dump's fb_x fb_y fb_z, or the servo of the machine that simulated the run.
struct FeedbackSupply {
  std::shared_ptr<const BiipReader> dump;  // a dump with feedback channels, kept open to read again
  std::optional<Machine> servo;            // a simulated run: its machine's servo replayed
  Vec3 servoStart = Vec3::Zero();          // from where the simulation started it (the program's start), mm
  bool available() const { return dump || servo; }
};

// The feedback of `samples` (opened without it) from `supply`; InputError when the supply
// has none or the memory is short. The progress callback may throw to cancel.
FeedbackOffsets loadFeedback(const Trajectory& samples, const FeedbackSupply& supply,
                             const ProgressCallback& progress = {});

// A program and its samples: read from the dump, or simulated with the machine.
struct OpenedRun {
  RunFiles files;
  std::shared_ptr<const Program> program;     // null for a dump alone
  std::shared_ptr<const Trajectory> samples;  // null when a program has no motion
  Machine machine;        // what made the samples: the dump's own, else the simulation's
  bool machineKnown = true;  // false: a dump that names no machine (a trace); `machine` is the default
  std::vector<std::string> warnings;
  // Samples opened without the feedback they could have (request.channels.feedback false).
  FeedbackSupply feedbackSupply;
  // The dump thinned samples came from (Trajectory::thinning > 1), kept open: a close-up reads
  // its records where the camera looks without checking the whole file again.
  std::shared_ptr<const BiipReader> thinnedDump;
};

// Throws InputError for a bad file, and DumpMismatchError for a dump that does not belong to
// its program unless request.force.
OpenedRun openRun(const OpenRunRequest& request, const ProgressCallback& progress = {});

// Simulates a program in memory with a machine (progress 0..1).
// Without `feedback` the servo's positions are not kept (see TrajectoryChannels). What the
// machine does otherwise than the program says (feeds above its axes' limits) is added to
// `warnings` where given.
Trajectory simulateRun(const Program& program, const Machine& machine, const ProgressCallback& progress = {},
                       bool feedback = true, std::vector<std::string>* warnings = nullptr);

}  // namespace isurface
