#include "progress.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace isurface::cli {

namespace {
double nowSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}
}  // namespace

ProgressLine::ProgressLine(std::string label) : label_(std::move(label)) {
  // A program that runs this one and reads its progress (the window's report export) asks for it.
  const char* asked = std::getenv("ISURFACE_PROGRESS");
  enabled_ = isatty(STDERR_FILENO) != 0 || (asked && asked[0] == '1');
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(double fraction) {
  if (!enabled_) return;
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  const double now = nowSeconds();
  if (percent == lastPercent_ || now - lastDraw_ < 0.1) return;
  lastPercent_ = percent;
  lastDraw_ = now;
  std::fprintf(stderr, "\r%s %3d%%", label_.c_str(), percent);
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (!enabled_ || lastPercent_ < 0) return;
  std::fprintf(stderr, "\r%s 100%%\n", label_.c_str());
  lastPercent_ = -1;
}

}  // namespace isurface::cli
