#pragma once
// The Export dialog's model: what is exported, where, and why it cannot be now.
#include <cstdint>
#include <optional>
#include <string>

namespace isurface::app_model {

enum class ExportKind { ViewPng, MapFigures, LineSamples, Report, RunDump };

// What the dialog needs to know of the document it would export.
struct ExportSubject {
  std::string name;
  bool hasSamples = false, hasMap = false;
  unsigned thinning = 1;    // 1: every sample
  bool jobRunning = false;  // a report would cancel it
};

struct ExportDialog {
  bool opening = false;  // asked for: the window opens it on its next frame
  bool open = false;     // shown this frame
  ExportKind kind = ExportKind::ViewPng;
  int width = 1920, height = 1080;  // px, of the view's PNG
  int first = 1, last = 1;          // lines of the samples' CSV
  int regions = 5;                  // worst regions of the report
  std::string path;

  // Opens it; the lines of the samples' CSV are the selected line, when one is.
  void show(std::optional<std::uint32_t> selectedLine);
  // Another kind of export: a path ending in a known export's extension takes the new kind's
  // (a JSON is not offered "view.png"); another extension, or none, is left as the user typed it.
  void choose(ExportKind next);
  // Why it cannot export now; empty when it can.
  std::string problem(const ExportSubject& subject) const;
};

}  // namespace isurface::app_model
