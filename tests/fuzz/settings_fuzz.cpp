// Fuzz target: the window's settings file, read as the application reads it at start
// (loadSettings on a file, through its bounded reader). The reader promises never to fail: a
// damaged file gives the defaults value by value, so any exception is a finding. What it returns
// must be within the ranges the window relies on, and must survive being written and read back
// unchanged (the next start sees what this one kept): that is checked on the text saveSettings
// writes and loadSettings reads, without the file, whose synced writes would slow the run down a
// hundredfold. The corpus's named seeds are files saveSettings wrote (the defaults, a light
// inch setup, ten recent files with the window at its bounds, the largest scale); the others are
// what libFuzzer found reaching new edges from them.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

#include "fuzz_support.h"
#include "isurface/app_model/settings.h"

namespace {

using isurface::app_model::Settings;

// The recent files are at most 10, absolute (the application may start elsewhere next time),
// none twice; the other values within the reader's ranges.
bool withinRanges(const Settings& s) {
  if (s.recentFiles.size() > 10) return false;
  const std::set<std::string> distinct(s.recentFiles.begin(), s.recentFiles.end());
  if (distinct.size() != s.recentFiles.size()) return false;
  for (const std::string& path : s.recentFiles)
    if (path.empty() || path.front() != '/') return false;
  if (s.windowWidth < 200 || s.windowWidth > 32768 || s.windowHeight < 200 || s.windowHeight > 32768)
    return false;
  if (!std::isfinite(s.uiScale) || s.uiScale < 1.0f || s.uiScale > 2.0f) return false;
  if (s.theme != "dark" && s.theme != "light") return false;
  return s.units == "auto" || s.units == "mm" || s.units == "inch";
}

bool same(const Settings& a, const Settings& b) {
  return a.recentFiles == b.recentFiles && a.quantity == b.quantity && a.colorMap == b.colorMap &&
         a.windowWidth == b.windowWidth && a.windowHeight == b.windowHeight && a.theme == b.theme &&
         a.uiScale == b.uiScale && a.uiScaleChosen == b.uiScaleChosen && a.units == b.units &&
         a.programMachines == b.programMachines;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Settings read = isurface::app_model::loadSettings(isurface::fuzz::writeScratch(data, size, ".json"));
  if (!withinRanges(read)) std::abort();  // a finding: a value the window does not expect
  const Settings again = isurface::app_model::settingsFromText(isurface::app_model::settingsText(read));
  if (!same(again, read)) std::abort();  // a finding: not kept as read
  return 0;
}
