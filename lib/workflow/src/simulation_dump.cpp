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

class BiipSink : public SampleSink {
 public:
  explicit BiipSink(BiipWriter& writer) : writer_(writer) {}
  void consume(const SimSample* samples, std::size_t count) override {
    for (std::size_t i = 0; i < count; ++i) writer_.append(&samples[i]);
  }

 private:
  BiipWriter& writer_;
};

}  // namespace

std::vector<BiipChannel> simulationChannels() {
  std::vector<BiipChannel> channels = {
      {"line", BiipType::U32, offsetof(SimSample, line)}, {"block", BiipType::U32, offsetof(SimSample, block)},
      {"x", BiipType::F64, offsetof(SimSample, x)},       {"y", BiipType::F64, offsetof(SimSample, y)},
      {"z", BiipType::F64, offsetof(SimSample, z)},       {"fb_x", BiipType::F64, offsetof(SimSample, fbX)},
      {"fb_y", BiipType::F64, offsetof(SimSample, fbY)},  {"fb_z", BiipType::F64, offsetof(SimSample, fbZ)},
      {"feed", BiipType::F64, offsetof(SimSample, feed)}};
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
  BiipWriter writer(path, simulationChannels(), machine.cycle, simulationMetadata(program.source, machine));
  BiipSink records(writer);
  ThreadedSink sink(records);
  const SimulationReport report = simulate(program, machine, sink, progress);
  sink.drain();
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
  BiipWriter writer(biipPath, simulationChannels(), machine.cycle, simulationMetadata(gcodePath, machine));
  BiipSink records(writer);
  ThreadedSink sink(records);
  StreamingSimulation simulation(machine, options.startPosition, gcodePath, sink);
  result.interpretation = interpretGcodeFileStream(gcodePath, simulation, options);
  if (!result.interpretation.ok()) return result;  // the writer removes its temporary file
  requireMotion(gcodePath, result.interpretation.moveCount);
  result.report = simulation.finish();
  sink.drain();
  result.largestWindow = simulation.planner().largestHeld();
  result.forcedCommits = simulation.planner().forcedCommits();
  writer.commit();
  return result;
}

}  // namespace isurface
