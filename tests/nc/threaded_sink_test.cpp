// The sink that stores samples on a thread of its own: what reaches the inner sink, in what
// order, and what happens when the inner sink fails or the run is abandoned.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <thread>
#include <vector>

#include "isurface/gcode/gcode_interpreter.h"
#include "isurface/nc/sample_trajectory.h"
#include "isurface/nc/simulator.h"
#include "isurface/nc/threaded_sink.h"
#include "isurface/machine/machine.h"

using namespace isurface;

namespace {

struct Recording : SampleSink {
  std::vector<SimSample> samples;
  std::size_t expected = 0, failAfter = ~std::size_t{0};
  bool feedback = true;
  std::shared_future<void> gate;       // when valid, each batch waits for it (a stalled disk)
  std::atomic<bool> entered{false};    // a batch reached consume()
  bool failed = false;
  std::size_t callsAfterFailure = 0;
  void expect(std::size_t n) override { expected = n; }
  bool wantsFeedback() const override { return feedback; }
  void consume(const SimSample* s, std::size_t count) override {
    entered = true;
    if (gate.valid()) gate.wait();
    if (failed) ++callsAfterFailure;
    if (samples.size() + count > failAfter) {
      failed = true;
      throw std::runtime_error("disk full");
    }
    samples.insert(samples.end(), s, s + count);
  }
};

std::vector<SimSample> numbered(std::size_t count) {
  std::vector<SimSample> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = SimSample{static_cast<std::uint32_t>(i), 0, double(i), 0, 0, 0, 0, 0, 0};
  }
  return out;
}

}  // namespace

TEST(threadedSink, EveryBatchReachesTheInnerSinkInOrder) {
  Recording inner;
  const std::vector<SimSample> all = numbered(100'000);
  {
    ThreadedSink sink(inner);
    sink.expect(all.size());
    // Batches of every size, from one sample to many, copied from the caller's buffer (reused
    // at once) or handed over with it, one and the other in turn.
    std::vector<SimSample> batch;
    bool handOver = false;
    for (std::size_t at = 0, size = 1; at < all.size(); at += size, size = size * 3 % 5001 + 1) {
      batch.assign(all.begin() + at, all.begin() + std::min(all.size(), at + size));
      if (handOver) {
        sink.consumeBatch(batch);
        ASSERT_TRUE(batch.empty());
      } else {
        sink.consume(batch.data(), batch.size());
        for (SimSample& s : batch) s.x = -1;
      }
      handOver = !handOver;
    }
    sink.drain();
    EXPECT_EQ(inner.samples.size(), all.size());
  }
  EXPECT_EQ(inner.expected, all.size());
  ASSERT_EQ(inner.samples.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) ASSERT_EQ(inner.samples[i].x, double(i)) << i;
}

TEST(threadedSink, AFailureOfTheInnerSinkReachesTheCallerAndNothingMoreIsStored) {
  Recording inner;
  inner.failAfter = 50'000;
  const std::vector<SimSample> all = numbered(4096);
  ThreadedSink sink(inner);
  EXPECT_THROW(
      {
        for (int k = 0; k < 100; ++k) sink.consume(all.data(), all.size());
        sink.drain();
      },
      std::runtime_error);
  EXPECT_THROW(sink.drain(), std::runtime_error);  // and at every later call
  EXPECT_THROW(sink.consume(all.data(), all.size()), std::runtime_error);
  EXPECT_LE(inner.samples.size(), inner.failAfter);
  EXPECT_TRUE(inner.failed);
  // Nothing queued behind the failed batch reached it. (A failure while the producer is copying
  // its next batch in is not forced here: that would need a pause inside the copy.)
  EXPECT_EQ(inner.callsAfterFailure, 0u);
}

TEST(threadedSink, AFailureReachesTheCallerOfBatchesHandedOverWithTheirBuffers) {
  Recording inner;
  inner.failAfter = 50'000;
  const std::vector<SimSample> all = numbered(4096);
  ThreadedSink sink(inner);
  std::vector<SimSample> batch;
  bool thrown = false;
  for (int k = 0; k < 100 && !thrown; ++k) {
    batch = all;
    try {
      sink.consumeBatch(batch);
    } catch (const std::runtime_error&) {
      thrown = true;
      EXPECT_EQ(batch.size(), all.size());  // a batch refused stays with its caller
    }
  }
  if (!thrown) {
    EXPECT_THROW(sink.drain(), std::runtime_error);
  }
  batch = all;
  EXPECT_THROW(sink.consumeBatch(batch), std::runtime_error);
  EXPECT_LE(inner.samples.size(), inner.failAfter);
  EXPECT_EQ(inner.callsAfterFailure, 0u);
}

TEST(threadedSink, AnAbandonedRunDropsWhatIsStillQueued) {
  Recording inner;
  std::promise<void> open;
  inner.gate = open.get_future().share();
  const std::vector<SimSample> all = numbered(4096);
  std::atomic<bool> destroying{false};
  std::thread opener;
  {
    ThreadedSink sink(inner);
    sink.consume(all.data(), all.size());
    while (!inner.entered) std::this_thread::yield();  // the first batch is being stored
    for (int k = 0; k < 4; ++k) sink.consume(all.data(), all.size());  // queued behind it
    // The disk comes back once the sink is being destroyed, as when the simulation throws (the
    // destructor drops the queue at once; the pause only leaves it the time to get there).
    opener = std::thread([&] {
      while (!destroying) std::this_thread::yield();
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      open.set_value();
    });
    destroying = true;
  }
  opener.join();
  EXPECT_EQ(inner.samples.size(), all.size());  // the batch being stored; the queued ones dropped
}

TEST(threadedSink, ASimulationThroughItIsTheDirectSimulationSampleForSample) {
  const Program program = interpretGcode(
      "G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z0 F600\nG1 X20 F300\nG2 X30 Y10 I0 J10\nG1 Y30\nG3 X10 Y30 R10\nG1 X0 Y0\n",
      "threaded.nc").program;
  const Machine machine = defaultMachine();
  for (const bool feedback : {true, false}) {
    TrajectorySink direct(machine.cycle, program.source, feedback);
    simulate(program, machine, direct);
    TrajectorySink stored(machine.cycle, program.source, feedback);
    {
      ThreadedSink sink(stored);
      simulate(program, machine, sink);
      sink.drain();
    }
    const Trajectory a = direct.take(), b = stored.take();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_GT(a.size(), 5u * 4096u);  // batches enough to be queued
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a.x[i], b.x[i]);
      ASSERT_EQ(a.y[i], b.y[i]);
      ASSERT_EQ(a.z[i], b.z[i]);
      ASSERT_EQ(a.line.runValue(a.line.runAt(i)), b.line.runValue(b.line.runAt(i)));
    }
    EXPECT_EQ(a.hasFeedback(), b.hasFeedback());
    if (feedback) {
      EXPECT_EQ(a.fbOffsetX, b.fbOffsetX);
    }
  }
}
