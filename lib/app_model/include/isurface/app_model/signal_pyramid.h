#pragma once
// Signal curves of millions of samples drawn fast: per-pixel min/max decimation answered from a
// pyramid of min/max pairs over blocks of 64 * 2^k samples, so a redraw costs about
// pixels x log(n) whatever the zoom. The samples' own values are not kept: they are read from a
// source when a view needs them (a column's ends, a zoomed-in view, one sample), so a curve
// costs about 0.25 bytes a sample.
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace isurface::app_model {

struct Envelope {
  std::vector<float> low, high;  // one pair per pixel column; NaN where the column has no sample
};

class SignalPyramid {
 public:
  // Writes the values of samples [first, last) to out[0 .. last - first). Called from the thread
  // that uses the pyramid (and, while it is built, from the building one).
  using Source = std::function<void(std::size_t first, std::size_t last, float* out)>;

  SignalPyramid() = default;
  SignalPyramid(std::size_t size, Source source);     // reads the whole source once, in pieces
  explicit SignalPyramid(std::vector<float> values);  // a source of these values

  std::size_t size() const { return size_; }
  float value(std::size_t i) const;                 // NaN beyond the end
  std::vector<float> values(std::size_t first, std::size_t last) const;  // clamped to the end
  // Min and max of samples [first, last) split evenly into `columns` pixel columns; non-finite
  // values are skipped. The last answer is remembered (a curve redrawn as it was costs nothing).
  Envelope envelope(std::size_t first, std::size_t last, int columns) const;
  // Min and max over [first, last); NaN, NaN when it holds no finite sample.
  std::pair<float, float> range(std::size_t first, std::size_t last) const;

 private:
  explicit SignalPyramid(std::shared_ptr<const std::vector<float>> values);
  // Widens [low, high] by the finite samples of [first, last) (bounds already clamped).
  void accumulate(std::size_t first, std::size_t last, float& low, float& high) const;
  void accumulateRaw(std::size_t first, std::size_t last, float& low, float& high) const;

  std::size_t size_ = 0;
  Source source_;
  // Level k holds min/max over blocks of 64 * 2^k samples (NaN for a block without a finite
  // one); a trailing partial block has no entry (its samples are read from the source).
  std::vector<std::vector<float>> low_, high_;
  struct Remembered {
    std::size_t first = 0, last = 0;
    int columns = -1;
    Envelope envelope;
  };
  std::shared_ptr<Remembered> remembered_ = std::make_shared<Remembered>();
};

// The sample shown at a pixel column of a curve spanning samples [first, last) over `columns`.
// `column` may be fractional (a mouse position): the sample then lies in the range envelope()
// draws in column floor(column), its fraction placing it proportionally (an integral column gives
// that range's first sample). Clamped to [first, last - 1]; `first` when nothing is shown.
std::size_t sampleAtColumn(std::size_t first, std::size_t last, int columns, double column);

}  // namespace isurface::app_model
