#pragma once
// Signal curves of millions of samples drawn fast: per-pixel min/max decimation answered from a
// pyramid of min/max pairs over blocks of 2^k samples, so a redraw costs about pixels x log(n)
// whatever the zoom.
#include <cstddef>
#include <utility>
#include <vector>

namespace isurface::app_model {

struct Envelope {
  std::vector<float> low, high;  // one pair per pixel column; NaN where the column has no sample
};

class SignalPyramid {
 public:
  SignalPyramid() = default;
  explicit SignalPyramid(std::vector<float> values);  // non-finite values are skipped

  std::size_t size() const;
  float value(std::size_t i) const;
  // Min and max of samples [first, last) split evenly into `columns` pixel columns.
  Envelope envelope(std::size_t first, std::size_t last, int columns) const;
  // Min and max over [first, last); NaN, NaN when it holds no finite sample.
  std::pair<float, float> range(std::size_t first, std::size_t last) const;

 private:
  // Widens [low, high] by the finite samples of [first, last) (bounds already clamped).
  void accumulate(std::size_t first, std::size_t last, float& low, float& high) const;

  // Level k > 0 holds min/max over blocks of 2^k samples (NaN for a block without a finite one);
  // level 0 is the values themselves, kept once in low_[0] (high_[0] stays empty).
  std::vector<std::vector<float>> low_, high_;
};

// The sample shown at a pixel column of a curve spanning samples [first, last) over `columns`.
// `column` may be fractional (a mouse position): the sample then lies in the range envelope()
// draws in column floor(column), its fraction placing it proportionally (an integral column gives
// that range's first sample). Clamped to [first, last - 1]; `first` when nothing is shown.
std::size_t sampleAtColumn(std::size_t first, std::size_t last, int columns, double column);

}  // namespace isurface::app_model
