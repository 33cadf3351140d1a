// Opening programs and dumps, and joining a dump to its program.
#include "isurface/workflow/run_inputs.h"
#include "isurface/base/file_read_stream.h"

#include "isurface/workflow/file_kinds.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "isurface/base/available_memory.h"
#include "isurface/gcode/path_segment.h"
#include "isurface/io/biip.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/threaded_sink.h"
#include "isurface/nc/servo_feedback.h"
#include "isurface/nc/simulator.h"
#include "isurface/base/json_text.h"

namespace isurface {

namespace {

constexpr std::size_t kJoinChecks = 2000;      // samples checked against the program's path
constexpr double kJoinOffShare = 0.01;         // share of them that may lie off it
constexpr double kJoinStepMm = 0.5;            // arcs are walked in steps of this length, mm

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

double distanceToMove(const Vec3& p, const PathSegment& segment) {
  if (!segment.arc) return distanceToSegment(p, segment.start, segment.end);
  const int steps = static_cast<int>(std::clamp(segment.length / kJoinStepMm, 2.0, 256.0));
  double best = (p - segment.start).norm();
  for (int i = 1; i <= steps; ++i) best = std::min(best, (p - segment.at(segment.length * i / steps)).norm());
  return best;
}

// First and last move of each line with motion.
std::unordered_map<std::uint32_t, std::pair<std::size_t, std::size_t>> movesByLine(const Program& program) {
  std::unordered_map<std::uint32_t, std::pair<std::size_t, std::size_t>> byLine;
  for (std::size_t k = 0; k < program.moves.size(); ++k) {
    if (!program.moves[k].isMotion()) continue;
    auto [it, added] = byLine.try_emplace(program.moves[k].line, k, k);
    if (!added) it->second.second = k;
  }
  return byLine;
}

// Whether a sample lies near a move of its line, or the moves just before and after (a
// blended corner belongs to either).
bool nearItsLine(const Program& program, const Vec3& p, std::pair<std::size_t, std::size_t> moves) {
  const std::size_t from = moves.first > 0 ? moves.first - 1 : 0;
  const std::size_t to = std::min(program.moves.size() - 1, moves.second + 1);
  for (std::size_t k = from; k <= to; ++k)
    if (program.moves[k].isMotion() && distanceToMove(p, PathSegment::from(program, k)) <= kJoinDistance) return true;
  return false;
}

std::optional<std::string> sourceMismatch(const BiipReader& dump, const Program& program) {
  const nlohmann::json meta = nlohmann::json::parse(dump.header().metadataJson, nullptr, false);
  if (!meta.is_object() || !meta.contains("source") || !meta["source"].is_string()) return std::nullopt;
  const std::string named = meta["source"].get<std::string>();
  if (named.empty() || fileName(named) == fileName(program.source)) return std::nullopt;
  return "its metadata names the program " + named;
}

std::optional<std::string> pathMismatch(const Trajectory& samples, const Program& program) {
  if (!samples.hasLine || samples.size() == 0) return std::nullopt;
  std::uint32_t lastLine = 0;
  samples.line.forEachRun([&](std::uint32_t line, std::size_t, std::size_t) { lastLine = std::max(lastLine, line); });
  if (program.lineCount > 0 && lastLine > program.lineCount)
    return "its samples name line " + std::to_string(lastLine) + ", past the program's last line " +
           std::to_string(program.lineCount);
  const auto byLine = movesByLine(program);
  const std::size_t step = std::max<std::size_t>(1, samples.size() / kJoinChecks);
  std::size_t checked = 0, off = 0;
  for (std::size_t i = 0; i < samples.size(); i += step) {
    const auto moves = byLine.find(samples.line[i]);
    const Vec3 p = samples.commanded(i);
    if (moves == byLine.end() || !p.allFinite()) continue;
    ++checked;
    if (!nearItsLine(program, p, moves->second)) ++off;
  }
  if (checked == 0 || double(off) <= kJoinOffShare * double(checked)) return std::nullopt;
  return std::to_string(off) + " of " + std::to_string(checked) + " samples checked lie farther than " +
         std::to_string(static_cast<int>(kJoinDistance)) + " mm from the program's moves of their lines";
}

}  // namespace

bool isBiipFile(const std::string& path) {
  FileReadStream in(path);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && std::memcmp(magic, "BIIP", 4) == 0;
}

std::vector<RunFiles> pairRunFiles(const std::vector<std::string>& paths) {
  std::vector<RunFiles> runs;
  for (const std::string& path : paths) {
    bool samples = false;  // a dump or a trace
    try {
      samples = fileKind(path) != FileKind::Program;
    } catch (const InputError&) {
      // Opened by itself, it says what is wrong with it.
    }
    if (samples && !runs.empty() && !runs.back().program.empty() && runs.back().dump.empty()) runs.back().dump = path;
    else if (samples) runs.push_back({"", path});
    else runs.push_back({path, ""});
  }
  return runs;
}

InterpreterOptions interpreterOptions(const Machine& machine) {
  InterpreterOptions options;
  options.inchAtPowerOn = machine.control.inch;
  options.fanuc = machine.control.fanuc;
  options.planeAtPowerOn = machine.control.plane;
  options.incrementalAtPowerOn = machine.control.incremental;
  options.powerOnModesNamed = machine.control.modesNamed;
  options.g28Position = machine.g28Position;
  options.g30Position = machine.g30Position;
  options.toolDiameters = machine.toolDiameters;
  options.subroutinePath = machine.control.subroutinePath;
  return options;
}

void requireMotion(const std::string& path, std::uint64_t moves) {
  if (moves == 0)
    throw InputError(Diagnostic{path, 0, 0, "no motion in the program: it makes no move, so there is nothing to "
                                            "simulate or measure"});
}

Program readProgram(const std::string& path, const ProgressCallback& progress, std::vector<std::string>* warnings,
                    const Machine& machine) {
  InterpreterOptions options = interpreterOptions(machine);
  options.progress = progress;
  InterpretResult r = interpretGcodeFile(path, options);
  if (!r.ok()) throw InputError(r.errors.front());
  requireMotion(path, r.program.moves.size());
  if (warnings)
    for (const Diagnostic& w : r.program.warnings) warnings->push_back(w.str());
  return std::move(r.program);
}

std::optional<Machine> machineOfDump(const BiipReader& reader) {
  const nlohmann::json meta = nlohmann::json::parse(reader.header().metadataJson, nullptr, false);
  if (!meta.is_object() || !meta.contains("machine") || !meta["machine"].is_object()) return std::nullopt;
  try {
    return parseMachine(jsonText(meta["machine"]), reader.path() + " (its machine)");
  } catch (const InputError&) {
    return std::nullopt;  // a trace's own notes on its machine, not a machine description
  }
}

std::optional<std::string> samplesMismatch(const Trajectory& samples, const Program& program) {
  return pathMismatch(samples, program);
}

std::optional<std::string> dumpMismatch(const BiipReader& dump, const Trajectory& samples, const Program& program) {
  if (auto why = sourceMismatch(dump, program)) return why;
  return pathMismatch(samples, program);
}

Trajectory simulateRun(const Program& program, const Machine& machine, const ProgressCallback& progress,
                       bool feedback, std::vector<std::string>* warnings) {
  TrajectorySink trajectory(machine.cycle, program.source, feedback);
  SimulationReport report;
  if (simulatesFiveAxis(machine)) {
    // The joints do not pass ThreadedSink's thread.
    trajectory.keepJointsOf(*machine.kinematics);
    report = simulate(program, machine, trajectory, progress);
  } else {
    ThreadedSink sink(trajectory);
    report = simulate(program, machine, sink, progress);
    sink.drain();
  }
  if (warnings)
    for (const Diagnostic& w : report.warnings) warnings->push_back(w.str());
  return trajectory.take();
}

namespace {

std::size_t nonFiniteSamples(const Trajectory& s) {
  std::size_t bad = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double v = (s.x[i] - s.x[i]) + (s.y[i] - s.y[i]) + (s.z[i] - s.z[i]);  // NaN unless all finite
    bad += static_cast<std::size_t>(v != v);
  }
  return bad;
}

// 1 when the dump's samples fit in half the free memory (the map, the curves and the close-up
// need the rest); else the thinning that fits them there, and a warning saying what it costs.
std::size_t thinningForMemory(const BiipReader& reader, const TrajectoryChannels& channels,
                              std::vector<std::string>& warnings) {
  const std::uint64_t records = reader.recordCount(), perSample = bytesPerSample(reader, channels);
  const std::optional<std::uint64_t> known = availableMemory();
  if (!known || records * perSample <= *known / 2) return 1;  // not known: loaded whole, as before
  const std::uint64_t free = *known;
  const std::size_t k = thinningToFit(records, perSample, free / 2);
  const double ms = 1000.0 * reader.header().cycleSeconds * double(k);
  warnings.push_back(fmt::format(
      "{}: its {} samples need {:.1f} GB of memory, more than half the {:.1f} GB this machine has free: shown thinned, 1 sample in "
      "{} ({} samples, one every {:g} ms); speeds are means over {:g} ms, accelerations and jerks are smoother than "
      "the machine's, and a move shorter than {:g} ms may have no sample",
      reader.path(), records, double(records * perSample) / 1e9, double(free) / 1e9, k, (records + k - 1) / k, ms, ms,
      ms));
  return k;
}

// The samples of a dump or a trace, with what they say of their machine and of the program.
void readSamples(const OpenRunRequest& request, const ProgressCallback& progress, OpenedRun& run) {
  const std::string& path = request.files.dump;
  const FileKind kind = fileKind(path);
  if (kind == FileKind::Program)
    throw InputError(Diagnostic{path, 0, 0, "is a G-code program, not a Biip dump or a trace"});
  std::optional<std::string> mismatch;
  if (isTrace(kind)) {
    auto samples = std::make_shared<Trajectory>(readTrace(path, kind));
    if (run.program && !request.force) mismatch = pathMismatch(*samples, *run.program);
    run.machineKnown = false;
    run.samples = std::move(samples);
  } else {
    const auto opened = std::make_shared<const BiipReader>(path);
    const BiipReader& reader = *opened;
    for (const std::string& w : reader.headerWarnings()) run.warnings.push_back(path + ": " + w);
    const std::size_t nonFiniteWarningAt = run.warnings.size();
    TrajectoryChannels channels = request.channels;
    channels.block = run.program != nullptr;  // a move index means nothing without the program's moves
    if (request.thinToFit) channels.thinning = thinningForMemory(reader, channels, run.warnings);
    // Not const: feedback loaded later joins it (Trajectory::attachFeedback).
    auto samples = std::make_shared<Trajectory>(loadTrajectory(reader, progressStage(progress, 0.3, 1.0), channels));
    // Every record loaded: they are counted in memory, not by another walk over the file.
    const bool whole = samples->thinning == 1 && samples->size() == reader.recordCount();
    const std::string nonFinite = nonFiniteWarning(whole ? nonFiniteSamples(*samples) : reader.nonFiniteSampleCount());
    if (!nonFinite.empty()) run.warnings.insert(run.warnings.begin() + nonFiniteWarningAt, path + ": " + nonFinite);
    if (run.program && !request.force) mismatch = dumpMismatch(reader, *samples, *run.program);
    if (!samples->hasFeedback() && reader.hasChannel("fb_x") && reader.hasChannel("fb_y") && reader.hasChannel("fb_z"))
      run.feedbackSupply.dump = opened;
    if (samples->thinning > 1) run.thinnedDump = opened;
    const std::optional<Machine> own = machineOfDump(reader);
    run.machineKnown = own.has_value();
    if (own) run.machine = *own;
    run.samples = std::move(samples);
  }
  if (mismatch)
    throw DumpMismatchError(Diagnostic{path, 0, 0, "is not a dump of " + request.files.program + ": " + *mismatch});
}

}  // namespace

FeedbackOffsets loadFeedback(const Trajectory& samples, const FeedbackSupply& supply, const ProgressCallback& progress) {
  if (supply.dump) return loadFeedbackOffsets(*supply.dump, samples, progress);
  if (supply.servo) return servoFeedback(samples, *supply.servo, supply.servoStart, progress);
  throw InputError(Diagnostic{samples.source, 0, 0, "has no feedback positions (fb_x fb_y fb_z) to load"});
}

OpenedRun openRun(const OpenRunRequest& request, const ProgressCallback& progress) {
  OpenedRun run;
  run.files = request.files;
  run.machine = request.machine ? *request.machine : defaultMachine();
  const bool hasDump = !request.files.dump.empty();
  if (!request.files.program.empty()) {
    const FileKind kind = fileKind(request.files.program);
    if (kind != FileKind::Program)
      throw InputError(Diagnostic{request.files.program, 0, 0, std::string("is a ") + fileKindName(kind) + ", not a G-code program"});
    run.program = std::make_shared<const Program>(
        readProgram(request.files.program, progressStage(progress, 0.0, hasDump ? 0.3 : 0.2), &run.warnings, run.machine));
  }
  if (hasDump) {
    readSamples(request, progress, run);
  } else if (run.program) {
    run.samples = std::make_shared<Trajectory>(
        simulateRun(*run.program, run.machine, progressStage(progress, 0.2, 1.0), request.channels.feedback, &run.warnings));
    if (!request.channels.feedback) {
      run.feedbackSupply.servo = run.machine;
      run.feedbackSupply.servoStart = run.program->start;
    }
  }
  if (progress) progress(1.0);
  return run;
}

}  // namespace isurface
