#pragma once
// What the application remembers between runs: recent files, the last colour settings and the
// window size, as JSON in $XDG_CONFIG_HOME/isurface/settings.json (~/.config/... by default).
#include <string>
#include <utility>
#include <vector>

namespace isurface::app_model {

struct Settings {
  std::vector<std::string> recentFiles;  // newest first, at most 10
  std::string quantity = "speed";
  std::string colorMap = "auto";  // rainbow, or diverging for signed quantities
  int windowWidth = 1600, windowHeight = 1000;
  std::string theme = "dark";    // or "light"
  float uiScale = 1.0f;          // 1 to 2: text and controls larger on large screens
  bool uiScaleChosen = false;    // by the user (View > Text size): else the screen's density sets it
  std::string units = "auto";    // lengths shown in "mm", "inch", or as the program is written
  // The machine each program was last simulated with when it was not the default, newest first
  // (at most 20): the program's absolute path, and the machine's description (JSON).
  std::vector<std::pair<std::string, std::string>> programMachines;

  void addRecent(const std::string& path);
  // Remembers `machineJson` for the program at `path`; the default machine is forgotten there.
  void rememberMachine(const std::string& path, const std::string& machineJson);
  // The description remembered for the program at `path`, or "".
  std::string machineOf(const std::string& path) const;
};

// The text size for a screen `pixelsWide` pixels and `millimetresWide` mm wide (0: not known),
// whose desktop asks for `contentScale` (1 when it says nothing): its density against 96 pixels
// an inch, in quarters, from 1 to 2.
float uiScaleForScreen(int pixelsWide, int millimetresWide, float contentScale);

// "" when neither XDG_CONFIG_HOME nor HOME is set: then nothing is loaded or saved.
std::string settingsPath();
// Missing or unreadable settings give the defaults (a broken file is not an error to stop for).
Settings loadSettings(const std::string& path = settingsPath());
// Written atomically; returns false (and leaves the old file) when it cannot be written.
bool saveSettings(const Settings& settings, const std::string& path = settingsPath());

// What loadSettings makes of a file's text and what saveSettings writes: apart from the file,
// so that the text's reading can be checked on its own.
Settings settingsFromText(const std::string& text);
std::string settingsText(const Settings& settings);

}  // namespace isurface::app_model
