#pragma once
// A progress line on stderr for long operations ("\rLABEL NN%"); silent when stderr is not a
// terminal, unless the environment has ISURFACE_PROGRESS=1.
#include <string>

namespace isurface::cli {

class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  ~ProgressLine();
  void update(double fraction);  // 0..1; redraws at most every 100 ms
  // What is being done now, after the label ("optimising, candidate 5: corners rounded NN%").
  void stage(std::string text);
  void finish();

 private:
  void draw(int percent);
  std::string label_, stage_;
  bool enabled_ = false, terminal_ = false;
  double lastDraw_ = -1;
  int lastPercent_ = -1;
};

}  // namespace isurface::cli
