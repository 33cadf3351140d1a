#pragma once
// G-code program + machine -> interpolation samples: feed planning, interpolation and servo.
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "isurface/base/diagnostic.h"
#include "isurface/gcode/gcode_stream.h"
#include "isurface/nc/feed_cap_notes.h"
#include "isurface/nc/interpolator.h"
#include "isurface/nc/linuxcnc_motion.h"

namespace isurface {

struct SimulationReport {
  std::uint64_t samples = 0;
  double machiningTime = 0;  // s, first to last sample
  double pathLength = 0;     // mm, programmed
  std::size_t segments = 0;  // moves with motion
  double filterTime1 = 0;    // s
  double filterTime2 = 0;    // s
  std::vector<Diagnostic> warnings;  // what the machine does otherwise than the program says
};

// Five-axis motion (rotary axes, the joints through the kinematics) is simulated on a machine
// with "kinematics" under the linuxcnc-2.9 control; its samples carry the tool tip in the
// workpiece frame and go with their joints (SampleSink::consumeJoints), and its sink must keep them.
bool simulatesFiveAxis(const Machine& machine);

// Progress is reported as planning (0..0.1) then interpolation (0.1..1).
SimulationReport simulate(const Program& program, const Machine& machine, SampleSink& sink,
                          const ProgressCallback& progress = {});

// Simulates a program handed over move by move, as interpretGcodeStream delivers it: planned
// with StreamingFeedPlanner's window and interpolated as segments become final. The samples are
// simulate()'s on the whole program, bit for bit (unless the planner had to force a commit,
// see feed_plan.h). Memory: the planner's window, the moves it spans (64 bytes each) and the
// interpolator's few cycles, whatever the program's length.
class StreamingSimulation : public MoveSink {
 public:
  // `start`: the position before the first move (InterpreterOptions::startPosition); `source`
  // names the program in planning errors. The machine and the sink must outlive it.
  StreamingSimulation(const Machine& machine, const Vec3& start, const std::string& source, SampleSink& sink,
                      const StreamingFeedPlanner::Window& window = {});
  ~StreamingSimulation() override;

  // An InputError of planning (or of the sink: a full disk) is kept, not thrown, and finish()
  // throws it; stopped() then tells the interpreter to read no more, and later moves are ignored.
  void consume(const Move* moves, std::size_t count, std::uint64_t firstIndex) override;
  void blendingChanged(const PathBlending& blending) override;
  void rotaryChanged(const RotaryPosition& rotary) override;
  // Once planning has failed or the run has passed the machine's longest run: the moves after
  // are not wanted, and the interpretation stops.
  bool stopped() const override { return simulationError_.has_value(); }
  // After the last move: the rest of the samples. Throws the error kept by consume(), if any.
  SimulationReport finish();

  const StreamingFeedPlanner& planner() const { return planner_; }

 private:
  void interpolateFinalSegments();

  const Machine& machine_;
  SampleSink& sink_;
  StreamingFeedPlanner planner_;
  std::string source_;
  std::unique_ptr<StreamingInterpolator> interpolator_;
  std::unique_ptr<LinuxCncMotion> linuxcnc_;  // the machine's control is LinuxCNC 2.9  // once the dwell before the first motion is known
  Vec3 start_;
  Vec3 moveStart_;                 // where the next move handed over starts
  std::optional<RotaryPosition> firstRotary_;  // the first move that turns a rotary axis: refused
  std::deque<RotaryPosition> rotaryChanges_;   // told, not yet reached by the moves handed over
  Vec3 rotary_ = Vec3::Zero();                 // A B C at the end of the last move handed over, deg
  // The moves that may become segments, from the one being interpolated on.
  struct HeldMove {
    std::uint64_t index;  // in the whole program
    Move move;
    Vec3 start;
  };
  std::deque<HeldMove> moves_;
  // Dwells read whose place among the segments' motion is not yet counted: checked against the
  // run's bound in program order, so that the one passing it is named, before any of their
  // hold is interpolated. Past kMostPendingDwells in a row, they are summed into the last.
  struct PendingDwell {
    std::uint64_t index;
    double seconds;
    Move move;
  };
  static constexpr std::size_t kMostPendingDwells = 4096;
  std::deque<PendingDwell> pendingDwells_;
  void countDwellsBefore(std::uint64_t index);
  double plannedTime_ = 0;  // s, of the segments handed to the interpolator with their holds
  double countedTime_ = 0;  // s, of the motion handed on and the dwells counted, in program order
  std::vector<PlannedSegment> final_;
  FeedCapNotes feeds_{machine_};
  SimulationReport report_;
  std::optional<InputError> simulationError_;
};

// A sink that keeps every sample in memory (tests, small programs).
class SampleBuffer : public SampleSink {
 public:
  void consume(const SimSample* samples, std::size_t count) override {
    data.insert(data.end(), samples, samples + count);
  }
  std::vector<SimSample> data;
};

}  // namespace isurface
