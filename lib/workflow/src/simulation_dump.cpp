// Simulating into a Biip dump whose metadata names the program and the machine.
#include "isurface/workflow/simulation_dump.h"

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "isurface/io/biip.h"
#include "isurface/nc/threaded_sink.h"
#include "isurface/base/units.h"
#include "isurface/base/json_text.h"
#include "isurface/workflow/run_inputs.h"

namespace isurface {

namespace {

// A record of a five-axis run: the sample, then its rotary axes and joints.
struct FiveAxisRecord {
  SimSample sample;
  JointSample joints;
};

class BiipSink : public SampleSink {
 public:
  BiipSink(BiipWriter& writer, bool fiveAxis) : writer_(writer), fiveAxis_(fiveAxis) {}
  bool keepsJoints() const override { return fiveAxis_; }
  void consumeJoints(const JointSample* joints, std::size_t count) override { joints_.assign(joints, joints + count); }
  void consume(const SimSample* samples, std::size_t count) override {
    if (!fiveAxis_) {
      writer_.appendRecords(samples, count);
      return;
    }
    if (joints_.size() != count) throw std::logic_error("a five-axis batch came without its joints");
    for (std::size_t i = 0; i < count; ++i) {
      const FiveAxisRecord record{samples[i], joints_[i]};
      writer_.append(&record);
    }
    joints_.clear();
  }

 private:
  BiipWriter& writer_;
  bool fiveAxis_;
  std::vector<JointSample> joints_;
};

// Samples go through a thread that writes them while the next are made; a five-axis run's
// joints do not pass that thread, and are written as they come.
struct DumpSinks {
  DumpSinks(BiipWriter& writer, const Machine& machine)
      : records(writer, simulatesFiveAxis(machine)), threaded(records) {}
  SampleSink& sink() { return records.keepsJoints() ? static_cast<SampleSink&>(records) : threaded; }
  void drain() { threaded.drain(); }
  BiipSink records;
  ThreadedSink threaded;
};

}  // namespace

std::vector<BiipChannel> simulationChannels(const Machine& machine) {
  std::vector<BiipChannel> channels = {
      {"line", BiipType::U32, offsetof(SimSample, line)}, {"block", BiipType::U32, offsetof(SimSample, block)},
      {"x", BiipType::F64, offsetof(SimSample, x)},       {"y", BiipType::F64, offsetof(SimSample, y)},
      {"z", BiipType::F64, offsetof(SimSample, z)},       {"fb_x", BiipType::F64, offsetof(SimSample, fbX)},
      {"fb_y", BiipType::F64, offsetof(SimSample, fbY)},  {"fb_z", BiipType::F64, offsetof(SimSample, fbZ)},
      {"feed", BiipType::F64, offsetof(SimSample, feed)}};
  if (simulatesFiveAxis(machine))
    for (const JointChannel& c : jointChannels(*machine.kinematics))
      channels.push_back({c.name, BiipType::F64, static_cast<std::uint32_t>(offsetof(FiveAxisRecord, joints) + c.offset)});
  return channels;
}

namespace {

std::string simulationMetadata(const std::string& source, const Machine& machine) {
  const nlohmann::json meta = {{"source", source},
                               {"units", "mm"},
                               {"writer", "isurface-cli 0.1.0 simulate"},
                               {"coordinates", "workpiece"},
                               {"machine", nlohmann::json::parse(machineLimitsJson(machine))}};
  return jsonText(meta);
}

}  // namespace

SimulationReport simulateToBiip(const Program& program, const Machine& machine, const std::string& path,
                                const ProgressCallback& progress) {
  BiipWriter writer(path, simulationChannels(machine), machine.cycle, simulationMetadata(program.source, machine));
  DumpSinks sinks(writer, machine);
  const SimulationReport report = simulate(program, machine, sinks.sink(), progress);
  sinks.drain();
  writer.commit();
  return report;
}

namespace {

// Takes the moves and keeps none: a reading of the whole program before its simulation.
class DiscardingSink : public MoveSink {
 public:
  void consume(const Move*, std::size_t, std::uint64_t) override {}
};

}  // namespace

StreamedSimulation simulateGcodeFileToBiip(const std::string& gcodePath, const Machine& machine,
                                           const std::string& biipPath, const InterpreterOptions& options) {
  StreamedSimulation result;
  // The program is read once before it is simulated, without the simulation: a program that
  // never ends passes the interpreter's bound on its loops in seconds, where its simulation
  // would write hours of samples first; and the program's errors are told before any sample is
  // made. Reading costs little beside simulating. (A pipe can be read only once: its program is
  // bounded as it is simulated, by the interpreter's bound or the machine's longest run.)
  std::error_code notAFile;
  if (std::filesystem::is_regular_file(gcodePath, notAFile)) {
    DiscardingSink discard;
    InterpreterOptions reading = options;
    reading.progress = nullptr;
    reading.callStack = nullptr;
    result.interpretation = interpretGcodeFileStream(gcodePath, discard, reading);
    if (!result.interpretation.ok()) return result;
  }
  BiipWriter writer(biipPath, simulationChannels(machine), machine.cycle, simulationMetadata(gcodePath, machine));
  DumpSinks sinks(writer, machine);
  StreamingSimulation simulation(machine, options.startPosition, gcodePath, sinks.sink());
  result.interpretation = interpretGcodeFileStream(gcodePath, simulation, options);
  if (!result.interpretation.ok()) return result;  // the writer removes its temporary file
  requireMotion(gcodePath, result.interpretation.moveCount);
  result.report = simulation.finish();
  sinks.drain();
  result.largestWindow = simulation.planner().largestHeld();
  result.forcedCommits = simulation.planner().forcedCommits();
  writer.commit();
  return result;
}

}  // namespace isurface
