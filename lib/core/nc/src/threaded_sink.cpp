#include "isurface/nc/threaded_sink.h"


namespace isurface {

namespace {
// Batches waiting at most: the interpolator runs at most this far ahead of the inner sink.
constexpr std::size_t kMostQueued = 4;
}  // namespace

ThreadedSink::ThreadedSink(SampleSink& inner) : inner_(inner) {
  // Room for every buffer there can be, so the worker's push never allocates (nor fails).
  spare_.reserve(kMostQueued + 2);
  worker_ = std::thread([this] { work(); });
}

ThreadedSink::~ThreadedSink() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queue_.clear();  // not drained: the run was abandoned
  }
  changed_.notify_all();
  worker_.join();
}

void ThreadedSink::expect(std::size_t samples) {
  std::unique_lock<std::mutex> lock(mutex_);
  waitIdle(lock);
  inner_.expect(samples);
}

void ThreadedSink::consume(const SimSample* samples, std::size_t count) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < kMostQueued || error_; });
  rethrow(lock);
  std::vector<SimSample> batch;
  if (!spare_.empty()) {
    batch = std::move(spare_.back());
    spare_.pop_back();
  }
  lock.unlock();
  batch.assign(samples, samples + count);
  lock.lock();
  if (error_) {  // the inner sink failed while this batch was copied: it is not handed over
    spare_.push_back(std::move(batch));
    rethrow(lock);
  }
  queue_.push_back(std::move(batch));
  lock.unlock();
  changed_.notify_all();
}

void ThreadedSink::consumeBatch(std::vector<SimSample>& batch) {
  std::vector<SimSample> replacement;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return queue_.size() < kMostQueued || error_; });
    rethrow(lock);
    if (!spare_.empty()) {
      replacement = std::move(spare_.back());
      spare_.pop_back();
    }
    queue_.push_back(std::move(batch));
  }
  changed_.notify_all();
  replacement.clear();
  batch = std::move(replacement);
}

void ThreadedSink::drain() {
  std::unique_lock<std::mutex> lock(mutex_);
  waitIdle(lock);
  rethrow(lock);
}

void ThreadedSink::waitIdle(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [&] { return (queue_.empty() && !busy_) || error_; });
}

// The inner sink's failure stays: every later call throws it, and nothing more reaches it.
void ThreadedSink::rethrow(std::unique_lock<std::mutex>&) {
  if (error_) std::rethrow_exception(error_);
}

void ThreadedSink::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;  // stopping, with nothing left
    std::vector<SimSample> batch = std::move(queue_.front());
    queue_.erase(queue_.begin());
    busy_ = true;
    lock.unlock();
    std::exception_ptr failure;
    try {
      inner_.consume(batch.data(), batch.size());
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    busy_ = false;
    if (failure && !error_) error_ = failure;  // the first failure is the one the caller hears of
    if (error_) queue_.clear();
    spare_.push_back(std::move(batch));
    changed_.notify_all();
  }
}

}  // namespace isurface
