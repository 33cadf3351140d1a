#pragma once
// A per-sample channel whose value changes seldom (the G-code line, the move index, the
// programmed feed): kept as runs of equal values, so it costs a few bytes a move instead of
// four a sample (1.2 GB of a 100 M-sample run's 4.8 GB were these three channels). A channel
// whose value changes nearly every sample (a trace's measured feed) would cost three times a
// plain array as runs: past a third of a run a sample it becomes a plain array ("dense"), each
// sample a run of its own.
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
  bool dense() const { return dense_; }
  // Bytes held, spare room included.
  std::size_t bytes() const { return begins_.capacity() * sizeof(std::size_t) + values_.capacity() * sizeof(T); }
  // Runs side by side may hold equal values once the channel is dense.
  std::size_t runCount() const { return values_.size(); }
  std::size_t runBegin(std::size_t run) const { return dense_ ? run : begins_[run]; }
  std::size_t runEnd(std::size_t run) const {
    if (dense_) return run + 1;
    return run + 1 < begins_.size() ? begins_[run + 1] : size_;
  }
  T runValue(std::size_t run) const { return values_[run]; }
  // The run that holds sample i (< size(), and the channel not empty): a binary search.
  std::size_t runAt(std::size_t i) const {
    if (dense_) return i;
    return static_cast<std::size_t>(std::upper_bound(begins_.begin(), begins_.end(), i) - begins_.begin()) - 1;
  }
  // Calls f(value, first, end) for the part of each run inside samples [begin, end).
  template <typename F>
  void forEachRun(std::size_t begin, std::size_t end, F&& f) const {
    end = std::min(end, size_);
    if (begin >= end) return;
    for (std::size_t r = runAt(begin); r < values_.size() && runBegin(r) < end; ++r)
      f(values_[r], std::max(begin, runBegin(r)), std::min(end, runEnd(r)));
  }
  template <typename F>
  void forEachRun(F&& f) const {
    forEachRun(0, size_, std::forward<F>(f));
  }
  // Sample i's value, i < size() (an empty channel reads T()). A walk over many samples reads
  // through a Cursor instead.
  T operator[](std::size_t i) const { return values_.empty() ? T() : values_[runAt(std::min(i, size_ - 1))]; }

  void push_back(const T& value) { append(value, 1); }
  // Appends `count` samples of one value.
  void append(const T& value, std::size_t count) {
    if (count == 0) return;
    if (dense_) {
      values_.insert(values_.end(), count, value);
    } else if (values_.empty() || !sameBits(values_.back(), value)) {
      begins_.push_back(size_);
      values_.push_back(value);
    }
    size_ += count;
    if (!dense_ && values_.size() >= kDenseRuns && values_.size() * 3 > size_) makeDense();
  }
  void assign(std::size_t count, const T& value) {
    clear();
    append(value, count);
  }
  // Shortens to `count` samples, or lengthens with `value`.
  void resize(std::size_t count, const T& value = T()) {
    if (count >= size_) return append(value, count - size_);
    if (count == 0) return clear();
    if (dense_) {
      values_.resize(count);
      size_ = count;
      return;
    }
    const std::size_t keep = runAt(count - 1) + 1;
    begins_.resize(keep);
    values_.resize(keep);
    size_ = count;
  }
  void clear() {
    begins_.clear();
    values_.clear();
    size_ = 0;
    dense_ = false;
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
    if (size_ != other.size_) return false;
    const std::vector<T> mine = toVector(), theirs = other.toVector();
    return std::equal(mine.begin(), mine.end(), theirs.begin(), theirs.end(), sameBits);
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
    // A cursor reads the channel as it was: one that is resized or appended to needs a new one.

   private:
    void seek(std::size_t i) {
      const RunChannel& c = *channel_;
      if (c.empty()) return;
      i = std::min(i, c.size() - 1);
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
  // Below this many runs a channel stays runs whatever their length.
  static constexpr std::size_t kDenseRuns = 4096;

  // NaN feeds of a trace are one run, not one run each.
  static bool sameBits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

  void makeDense() {
    values_ = toVector();
    begins_.clear();
    begins_.shrink_to_fit();
    dense_ = true;
  }

  std::vector<std::size_t> begins_;  // first sample of each run, rising
  std::vector<T> values_;
  std::size_t size_ = 0;
  bool dense_ = false;
};

}  // namespace isurface
