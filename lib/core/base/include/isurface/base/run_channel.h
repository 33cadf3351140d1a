#pragma once
// A per-sample channel whose value changes seldom (the G-code line, the move index, the
// programmed feed): kept as runs of equal values, so it costs a few bytes a move instead of
// four a sample (1.2 GB of a 100 M-sample run's 4.8 GB were these three channels).
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <utility>
#include <vector>

namespace isurface {

template <typename T>
class RunChannel {
 public:
  RunChannel() = default;
  RunChannel(std::initializer_list<T> values) {
    for (const T& v : values) push_back(v);
  }
  RunChannel(const std::vector<T>& values) {  // NOLINT: a vector of per-sample values converts
    for (const T& v : values) push_back(v);
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t runCount() const { return values_.size(); }
  std::size_t runBegin(std::size_t run) const { return begins_[run]; }
  std::size_t runEnd(std::size_t run) const { return run + 1 < begins_.size() ? begins_[run + 1] : size_; }
  T runValue(std::size_t run) const { return values_[run]; }
  // The run that holds sample i (< size()): a binary search over the runs.
  std::size_t runAt(std::size_t i) const {
    return static_cast<std::size_t>(std::upper_bound(begins_.begin(), begins_.end(), i) - begins_.begin()) - 1;
  }
  // Calls f(value, first, end) for the part of each run inside samples [begin, end).
  template <typename F>
  void forEachRun(std::size_t begin, std::size_t end, F&& f) const {
    end = std::min(end, size_);
    if (begin >= end) return;
    for (std::size_t r = runAt(begin); r < values_.size() && begins_[r] < end; ++r)
      f(values_[r], std::max(begin, begins_[r]), std::min(end, runEnd(r)));
  }
  template <typename F>
  void forEachRun(F&& f) const {
    forEachRun(0, size_, std::forward<F>(f));
  }
  // Sample i's value, i < size(). A walk over many samples reads through a Cursor instead.
  T operator[](std::size_t i) const { return values_[runAt(i)]; }

  void push_back(const T& value) { append(value, 1); }
  // Appends `count` samples of one value.
  void append(const T& value, std::size_t count) {
    if (count == 0) return;
    if (values_.empty() || !sameBits(values_.back(), value)) {
      begins_.push_back(size_);
      values_.push_back(value);
    }
    size_ += count;
  }
  void assign(std::size_t count, const T& value) {
    clear();
    append(value, count);
  }
  // Shortens to `count` samples, or lengthens with `value`.
  void resize(std::size_t count, const T& value = T()) {
    if (count >= size_) return append(value, count - size_);
    if (count == 0) return clear();
    const std::size_t keep = runAt(count - 1) + 1;
    begins_.resize(keep);
    values_.resize(keep);
    size_ = count;
  }
  void clear() {
    begins_.clear();
    values_.clear();
    size_ = 0;
  }
  void shrink_to_fit() {
    begins_.shrink_to_fit();
    values_.shrink_to_fit();
  }
  std::vector<T> toVector() const {
    std::vector<T> out;
    out.reserve(size_);
    for (std::size_t r = 0; r < values_.size(); ++r) out.insert(out.end(), runEnd(r) - runBegin(r), values_[r]);
    return out;
  }
  bool operator==(const RunChannel& other) const {
    return size_ == other.size_ && begins_ == other.begins_ &&
           std::equal(values_.begin(), values_.end(), other.values_.begin(), other.values_.end(), sameBits);
  }
  bool operator!=(const RunChannel& other) const { return !(*this == other); }

  // Reads samples in any order, fastest when each is at or shortly after the one before: it
  // keeps the run it read last.
  class Cursor {
   public:
    explicit Cursor(const RunChannel& channel) : channel_(&channel) {}
    T operator[](std::size_t i) {
      if (i < begin_ || i >= end_) seek(i);
      return value_;
    }

   private:
    void seek(std::size_t i) {
      const RunChannel& c = *channel_;
      std::size_t run = run_ + 1;
      if (!(valid_ && run < c.runCount() && c.runBegin(run) <= i && i < c.runEnd(run))) run = c.runAt(i);
      run_ = run;
      valid_ = true;
      begin_ = c.runBegin(run);
      end_ = c.runEnd(run);
      value_ = c.runValue(run);
    }
    const RunChannel* channel_;
    std::size_t run_ = 0, begin_ = 0, end_ = 0;
    bool valid_ = false;
    T value_ = T();
  };
  Cursor cursor() const { return Cursor(*this); }

 private:
  // NaN feeds of a trace are one run, not one run each.
  static bool sameBits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

  std::vector<std::size_t> begins_;  // first sample of each run, rising
  std::vector<T> values_;
  std::size_t size_ = 0;
};

}  // namespace isurface
