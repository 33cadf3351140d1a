#pragma once
// A sink that hands the interpolator's batches to another sink on a thread of its own: storing
// the samples (and the page faults of their fresh arrays) runs beside the interpolation
// instead of after each batch of it. Call drain() before using what the inner sink holds: a
// sink destroyed without it drops the batches still queued and any failure not yet reported.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "isurface/nc/interpolator.h"

namespace isurface {

class ThreadedSink : public SampleSink {
 public:
  // `inner` must outlive this sink; its consume() runs on the sink's thread, in batch order.
  explicit ThreadedSink(SampleSink& inner);
  ~ThreadedSink() override;
  ThreadedSink(const ThreadedSink&) = delete;
  ThreadedSink& operator=(const ThreadedSink&) = delete;

  void expect(std::size_t samples) override;
  bool wantsFeedback() const override { return inner_.wantsFeedback(); }
  void consume(const SimSample* samples, std::size_t count) override;
  void consumeBatch(std::vector<SimSample>& batch) override;  // queues the vector itself
  // Waits until the inner sink has every sample handed over; rethrows what it threw.
  void drain();

 private:
  void work();
  void waitIdle(std::unique_lock<std::mutex>& lock);
  void rethrow(std::unique_lock<std::mutex>& lock);

  SampleSink& inner_;
  std::mutex mutex_;
  std::condition_variable changed_;
  // Batches handed over and not yet consumed, oldest first; spare buffers for the next ones.
  std::vector<std::vector<SimSample>> queue_, spare_;
  bool busy_ = false, stopping_ = false;
  std::exception_ptr error_;
  std::thread worker_;
};

}  // namespace isurface
