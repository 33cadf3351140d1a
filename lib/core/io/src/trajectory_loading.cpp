// Loading a dump's samples into one array per channel.
#include "isurface/io/trajectory_loading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "isurface/base/available_memory.h"
#include "isurface/base/diagnostic.h"
#include "isurface/io/biip.h"

namespace isurface {

namespace {

// Channels with a member of their own; every other channel goes to `extra`.
bool isKnownChannel(const std::string& name, bool feedbackComplete) {
  static const char* const own[] = {"t", "line", "block", "x", "y", "z", "feed"};
  for (const char* n : own)
    if (name == n) return true;
  return feedbackComplete && (name == "fb_x" || name == "fb_y" || name == "fb_z");
}

// Records copied per step: small enough that a step's records stay in the cache while each
// channel is picked out of them.
constexpr std::size_t kChunkRecords = std::size_t(1) << 16;
constexpr std::size_t kProgressRecords = std::size_t(1) << 20;

// Records [begin, begin + count) of the feedback channels as offsets from the commanded
// positions already loaded (float: see Trajectory).
void copyFeedbackOffsets(const BiipChannelView (&feedback)[3], const Trajectory& commanded, std::size_t begin,
                         std::size_t count, std::vector<double>& chunk, FeedbackOffsets& out) {
  const std::vector<double>* axes[3] = {&commanded.x, &commanded.y, &commanded.z};
  std::vector<float>* offsets[3] = {&out.x, &out.y, &out.z};
  for (int axis = 0; axis < 3; ++axis) {
    feedback[axis].copyTo(chunk.data(), begin, count);
    const double* position = axes[axis]->data() + begin;
    float* offset = offsets[axis]->data() + begin;
    for (std::size_t k = 0; k < count; ++k) offset[k] = static_cast<float>(chunk[k] - position[k]);
  }
}

}  // namespace

double rapidFeedFromMetadata(const std::string& metadataJson) {
  if (metadataJson.empty()) return 0;
  const nlohmann::json meta = nlohmann::json::parse(metadataJson, nullptr, false);
  if (!meta.is_object()) return 0;
  const auto machine = meta.find("machine");
  if (machine == meta.end() || !machine->is_object()) return 0;
  const auto rapid = machine->find("rapid_mm_min");
  if (rapid == machine->end() || !rapid->is_number()) return 0;
  const double value = rapid->get<double>();
  return std::isfinite(value) && value > 0 ? value : 0;
}

std::uint64_t bytesPerSample(const BiipReader& reader, const TrajectoryChannels& channels) {
  const bool feedbackComplete = reader.hasChannel("fb_x") && reader.hasChannel("fb_y") && reader.hasChannel("fb_z");
  std::size_t extras = 0;
  for (const BiipChannel& c : reader.header().channels) extras += channels.extra && !isKnownChannel(c.name, feedbackComplete);
  // Positions 24, feedback offsets 12, times and extra channels 8 each: the line, move index
  // and feed, kept as runs, cost about nothing beside them.
  return 24 + (feedbackComplete && channels.feedback ? 12 : 0) + (reader.hasChannel("t") ? 8 : 0) + 8 * extras;
}

std::size_t thinningToFit(std::uint64_t records, std::uint64_t bytesPerSample, std::uint64_t budget) {
  const std::uint64_t fitting = std::max<std::uint64_t>(1, budget / std::max<std::uint64_t>(1, bytesPerSample));
  if (records <= fitting) return 1;
  return static_cast<std::size_t>((records + fitting - 1) / fitting);
}

Trajectory loadTrajectory(const BiipReader& reader, const TrajectoryProgress& progress,
                          const TrajectoryChannels& channels) {
  const BiipHeader& header = reader.header();
  const std::size_t first = std::min(channels.firstRecord, reader.recordCount());
  const std::size_t records = std::min(channels.records, reader.recordCount() - first);
  const std::size_t thinning = std::max<std::size_t>(1, channels.thinning);
  const std::size_t n = (records + thinning - 1) / thinning;
  const auto view = [&reader, first, records, thinning](const char* name) {
    return reader.channel(name).part(first, records).every(thinning);
  };
  Trajectory out;
  out.source = reader.path();
  out.cycle = header.cycleSeconds * double(thinning);
  out.thinning = thinning;
  out.rapidFeed = rapidFeedFromMetadata(header.metadataJson);

  const BiipChannelView t = view("t");
  const BiipChannelView line = view("line");
  const BiipChannelView block = view("block");
  const bool useBlock = block.valid() && channels.block;
  const bool feedbackComplete = reader.hasChannel("fb_x") && reader.hasChannel("fb_y") && reader.hasChannel("fb_z");
  out.hasLine = line.valid();
  requireMemory(reader.path(), fmt::format("its {} samples", n), std::uint64_t(n) * bytesPerSample(reader, channels),
                availableMemory());
  // Destination of each floating channel copied in chunks.
  struct Copy {
    BiipChannelView view;
    std::vector<double>* to;
  };
  std::vector<Copy> copies;
  const auto add = [&](const std::string& name, std::vector<double>& to) {
    to.resize(n);
    copies.push_back({view(name.c_str()), &to});
  };
  add("x", out.x);
  add("y", out.y);
  add("z", out.z);
  if (t.valid()) add("t", out.time);
  const bool useFeedback = feedbackComplete && channels.feedback;
  const BiipChannelView feedback[3] = {view("fb_x"), view("fb_y"), view("fb_z")};
  std::vector<double> feedbackChunk;
  FeedbackOffsets offsets;
  if (useFeedback) {
    for (std::vector<float>* offset : {&offsets.x, &offsets.y, &offsets.z}) offset->resize(n);
    feedbackChunk.resize(kChunkRecords);
  }
  const BiipChannelView feed = view("feed");
  std::vector<float> feedChunk(feed.valid() ? kChunkRecords : 0);
  for (const BiipChannel& c : header.channels) {
    if (!channels.extra || isKnownChannel(c.name, feedbackComplete)) continue;
    out.extra.emplace_back(c.name, std::vector<double>());
  }
  // Resized only now: `extra` must not grow after pointers into it are taken.
  for (auto& [name, values] : out.extra) add(name, values);

  if (!line.valid()) out.line.assign(n, 0);
  if (!t.valid()) out.startTime = header.t0Seconds + double(first) * header.cycleSeconds;

  std::size_t nextReport = kProgressRecords;
  for (std::size_t begin = 0; begin < n; begin += kChunkRecords) {
    const std::size_t count = std::min(kChunkRecords, n - begin);
    for (const Copy& c : copies) c.view.copyTo(c.to->data() + begin, begin, count);
    if (feed.valid()) {
      feed.copyTo(feedChunk.data(), begin, count);
      for (std::size_t k = 0; k < count; ++k) out.feed.push_back(feedChunk[k]);
    }
    if (useFeedback) copyFeedbackOffsets(feedback, out, begin, count, feedbackChunk, offsets);
    if (line.valid())
      for (std::size_t i = begin; i < begin + count; ++i) out.line.push_back(countAt(line, i, reader.path(), "line"));
    if (useBlock)
      for (std::size_t i = begin; i < begin + count; ++i) out.block.push_back(countAt(block, i, reader.path(), "block"));
    reader.releaseRecords(first + begin * thinning, first + (begin + count) * thinning);
    if (progress && begin + count >= nextReport) {
      progress(double(begin + count) / double(n));
      nextReport += kProgressRecords;
    }
  }
  reader.checkIntact();
  if (useFeedback) out.attachFeedback(std::move(offsets));
  out.shrinkRunChannels();
  if (t.valid()) {
    for (std::size_t i = 0; i < out.time.size(); ++i)
      requireTimeAdvances(out.time, i, reader.path(), thinning);
    out.irregularTime = timeIsIrregular(out.time.data(), n, out.cycle);
  }
  if (progress) progress(1.0);
  return out;
}

FeedbackOffsets loadFeedbackOffsets(const BiipReader& reader, const Trajectory& samples,
                                    const TrajectoryProgress& progress) {
  const std::size_t thinning = std::max<std::size_t>(1, samples.thinning);
  const std::size_t n = (reader.recordCount() + thinning - 1) / thinning;
  if (!(reader.hasChannel("fb_x") && reader.hasChannel("fb_y") && reader.hasChannel("fb_z")))
    throw InputError(Diagnostic{reader.path(), 0, 0, "has no feedback channels (fb_x fb_y fb_z)"});
  if (n != samples.size())
    throw InputError(Diagnostic{reader.path(), 0, 0,
                                fmt::format("holds {} records, not the {} samples loaded from it", reader.recordCount(),
                                            samples.size())});
  requireMemory(reader.path(), fmt::format("the feedback of its {} samples", n), std::uint64_t(n) * 12,
                availableMemory());
  const BiipChannelView feedback[3] = {reader.channel("fb_x").every(thinning), reader.channel("fb_y").every(thinning),
                                       reader.channel("fb_z").every(thinning)};
  FeedbackOffsets offsets;
  for (std::vector<float>* offset : {&offsets.x, &offsets.y, &offsets.z}) offset->resize(n);
  std::vector<double> chunk(kChunkRecords);
  std::size_t nextReport = kProgressRecords;
  for (std::size_t begin = 0; begin < n; begin += kChunkRecords) {
    const std::size_t count = std::min(kChunkRecords, n - begin);
    copyFeedbackOffsets(feedback, samples, begin, count, chunk, offsets);
    reader.releaseRecords(begin * thinning, (begin + count) * thinning);
    if (progress && begin + count >= nextReport) {
      progress(double(begin + count) / double(n));
      nextReport += kProgressRecords;
    }
  }
  reader.checkIntact();
  if (progress) progress(1.0);
  return offsets;
}

}  // namespace isurface
