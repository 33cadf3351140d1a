#include "progress.h"

#include <sys/ioctl.h>
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
  terminal_ = isatty(STDERR_FILENO) != 0;
  enabled_ = terminal_ || (asked && asked[0] == '1');
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(double fraction) {
  if (!enabled_) return;
  const int percent = static_cast<int>(fraction * 100.0 + 0.5);
  const double now = nowSeconds();
  if (percent == lastPercent_ || now - lastDraw_ < 0.1) return;
  lastPercent_ = percent;
  lastDraw_ = now;
  draw(percent);
}

void ProgressLine::stage(std::string text) {
  if (!enabled_ || text == stage_) return;
  stage_ = std::move(text);
  if (lastPercent_ >= 0) draw(lastPercent_);
}

void ProgressLine::draw(int percent) {
  std::string shown = stage_.empty() ? label_ : label_ + ", " + stage_;
  // A line wider than the terminal would wrap, and "\r" go back to its last part only.
  winsize size{};
  if (terminal_ && ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 20 && shown.size() + 6 > size.ws_col) {
    std::size_t cut = size.ws_col - 9;
    while (cut > 0 && (static_cast<unsigned char>(shown[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
    shown = shown.substr(0, cut) + "...";
  }
  // On a terminal the rest of a longer line drawn before is cleared (ANSI erase to its end); a
  // program reading the pipe takes each line as it comes.
  std::fprintf(stderr, "\r%s %3d%%%s", shown.c_str(), percent, terminal_ ? "\x1b[K" : "");
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (!enabled_ || lastPercent_ < 0) return;
  std::fprintf(stderr, "\r%s 100%%%s\n", label_.c_str(), terminal_ ? "\x1b[K" : "");
  lastPercent_ = -1;
}

}  // namespace isurface::cli
