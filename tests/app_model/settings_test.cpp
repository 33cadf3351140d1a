// Settings kept between runs: where they live, round trips, and tolerance of damaged files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <sys/stat.h>

#include "isurface/app_model/settings.h"
#include "isurface/machine/machine.h"
#include "test_support.h"

using namespace isurface::app_model;
using namespace isurface::test;

namespace {

// Sets (or unsets) an environment variable for the scope of a test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::string freshFolder(const std::string& name) {
  const std::filesystem::path folder = scratchDir() / name;
  std::filesystem::remove_all(folder);
  return folder.string();
}

void writeText(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

void expectDefaults(const Settings& s) {
  const Settings defaults;
  EXPECT_TRUE(s.recentFiles.empty());
  EXPECT_EQ(s.quantity, defaults.quantity);
  EXPECT_EQ(s.colorMap, defaults.colorMap);
  EXPECT_EQ(s.windowWidth, defaults.windowWidth);
  EXPECT_EQ(s.windowHeight, defaults.windowHeight);
}

}  // namespace

TEST(settings, PathFollowsXdgConfigHome) {
  ScopedEnv xdg("XDG_CONFIG_HOME", "/tmp/somewhere/config");
  EXPECT_EQ(settingsPath(), "/tmp/somewhere/config/isurface/settings.json");
}

TEST(settings, PathFallsBackToHomeConfig) {
  ScopedEnv home("HOME", "/home/tester");
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
    EXPECT_EQ(settingsPath(), "/home/tester/.config/isurface/settings.json");
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "");
    EXPECT_EQ(settingsPath(), "/home/tester/.config/isurface/settings.json");
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "relative/config");  // ignored, as the XDG rules say
    EXPECT_EQ(settingsPath(), "/home/tester/.config/isurface/settings.json");
  }
}

TEST(settings, NoHomeMeansNothingIsSaved) {
  ScopedEnv home("HOME", nullptr);
  ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
  EXPECT_EQ(settingsPath(), "");
  expectDefaults(loadSettings());
  EXPECT_FALSE(saveSettings(Settings{}));
}

TEST(settings, RoundTripThroughTheDefaultPath) {
  const std::string config = freshFolder("xdg-roundtrip");
  ScopedEnv xdg("XDG_CONFIG_HOME", config.c_str());
  Settings saved;
  saved.addRecent("/data/first.biip");
  saved.addRecent("/data/second part.nc");
  saved.addRecent("/data/ünïcode.biip");
  saved.quantity = "jerk";
  saved.colorMap = "viridis";
  saved.windowWidth = 2560;
  saved.windowHeight = 1440;
  saved.theme = "light";
  saved.uiScale = 1.25f;
  saved.uiScaleChosen = true;
  saved.units = "inch";
  ASSERT_TRUE(saveSettings(saved));  // creates isurface/ under the config folder
  EXPECT_TRUE(fileExists(config + "/isurface/settings.json"));

  const Settings loaded = loadSettings();
  EXPECT_EQ(loaded.recentFiles, saved.recentFiles);
  EXPECT_EQ(loaded.quantity, "jerk");
  EXPECT_EQ(loaded.colorMap, "viridis");
  EXPECT_EQ(loaded.windowWidth, 2560);
  EXPECT_EQ(loaded.windowHeight, 1440);
  EXPECT_EQ(loaded.theme, "light");
  EXPECT_FLOAT_EQ(loaded.uiScale, 1.25f);
  EXPECT_TRUE(loaded.uiScaleChosen);
  EXPECT_EQ(loaded.units, "inch");

  // The keys the file promises.
  const std::string text = readFile(config + "/isurface/settings.json");
  for (const char* key : {"recent_files", "quantity", "color_map", "window_width", "window_height", "theme", "ui_scale",
                          "units"})
    EXPECT_NE(text.find(key), std::string::npos) << key;
}

TEST(settings, SavingReplacesTheOldFile) {
  const std::string path = freshFolder("replace") + "/settings.json";
  Settings first;
  first.quantity = "accel";
  ASSERT_TRUE(saveSettings(first, path));
  Settings second;
  second.quantity = "feed";
  ASSERT_TRUE(saveSettings(second, path));
  EXPECT_EQ(loadSettings(path).quantity, "feed");
  // No temporary left beside it.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    ++files;
  EXPECT_EQ(files, 1);
}

TEST(settings, UnwritableLocationFailsAndKeepsNothingHalfWritten) {
  const std::string folder = freshFolder("unwritable");
  writeText(folder + "/blocker", "a file where a folder should be");
  EXPECT_FALSE(saveSettings(Settings{}, folder + "/blocker/isurface/settings.json"));
  EXPECT_EQ(readFile(folder + "/blocker"), "a file where a folder should be");
}

TEST(settings, MissingFileGivesDefaults) {
  expectDefaults(loadSettings(freshFolder("missing") + "/settings.json"));
  expectDefaults(loadSettings(""));
}

TEST(settings, BrokenFileGivesDefaults) {
  const std::string folder = freshFolder("broken");
  for (const char* text : {"{\"quantity\": \"jerk\",", "not json at all", "", "[1, 2, 3]", "null", "\"text\""}) {
    writeText(folder + "/settings.json", text);
    expectDefaults(loadSettings(folder + "/settings.json"));
  }
  expectDefaults(loadSettings(folder));  // a folder, not a file
}

// The text on its own reads as the file does, and what is written reads back the same.
TEST(settings, TextReadsAsTheFileAndComesBackUnchanged) {
  expectDefaults(settingsFromText("{\"quantity\": \"jerk\","));
  Settings s = settingsFromText(R"({"recent_files": ["/a.nc"], "theme": "light", "ui_scale": 1.5, "units": "mm"})");
  EXPECT_EQ(s.recentFiles, (std::vector<std::string>{"/a.nc"}));
  EXPECT_EQ(s.theme, "light");
  EXPECT_FLOAT_EQ(s.uiScale, 1.5f);
  EXPECT_EQ(s.units, "mm");
  s.windowWidth = 333;
  const Settings again = settingsFromText(settingsText(s));
  EXPECT_EQ(again.recentFiles, s.recentFiles);
  EXPECT_EQ(again.windowWidth, 333);
  EXPECT_EQ(again.uiScale, s.uiScale);
  EXPECT_EQ(again.units, "mm");
}

TEST(settings, WrongTypesFallBackOneByOne) {
  const std::string path = freshFolder("types") + "/settings.json";
  writeText(path, R"({"recent_files": ["/a.nc", 7, null, "/b.nc"], "quantity": 3, "color_map": "gray",
                      "window_width": "wide", "window_height": -5, "unknown_key": true})");
  const Settings s = loadSettings(path);
  EXPECT_EQ(s.recentFiles, (std::vector<std::string>{"/a.nc", "/b.nc"}));
  EXPECT_EQ(s.quantity, Settings{}.quantity);
  EXPECT_EQ(s.colorMap, "gray");
  EXPECT_EQ(s.windowWidth, Settings{}.windowWidth);
  EXPECT_EQ(s.windowHeight, Settings{}.windowHeight);
}

TEST(settings, LoadedRecentFilesAreDeduplicatedAndCapped) {
  const std::string path = freshFolder("recent-load") + "/settings.json";
  std::string list;
  for (int i = 0; i < 15; ++i) list += (i ? ", " : "") + std::string("\"/f") + std::to_string(i % 12) + "\"";
  writeText(path, "{\"recent_files\": [" + list + "]}");
  const Settings s = loadSettings(path);
  ASSERT_EQ(s.recentFiles.size(), 10u);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(s.recentFiles[i], "/f" + std::to_string(i));
}

TEST(settings, AddRecentMovesToFrontAndKeepsTen) {
  Settings s;
  s.addRecent("/a");
  s.addRecent("/b");
  s.addRecent("/c");
  EXPECT_EQ(s.recentFiles, (std::vector<std::string>{"/c", "/b", "/a"}));
  s.addRecent("/a");
  EXPECT_EQ(s.recentFiles, (std::vector<std::string>{"/a", "/c", "/b"}));
  s.addRecent("/a");
  EXPECT_EQ(s.recentFiles, (std::vector<std::string>{"/a", "/c", "/b"}));
  s.addRecent("");
  EXPECT_EQ(s.recentFiles.size(), 3u);

  for (int i = 0; i < 20; ++i) s.addRecent("/file" + std::to_string(i));
  ASSERT_EQ(s.recentFiles.size(), 10u);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(s.recentFiles[i], "/file" + std::to_string(19 - i));
  s.addRecent("/file15");
  EXPECT_EQ(s.recentFiles.front(), "/file15");
  EXPECT_EQ(s.recentFiles.size(), 10u);
  EXPECT_EQ(s.recentFiles[1], "/file19");
}

TEST(settings, RecentFilesAreRememberedWithTheirWholePath) {
  Settings s;
  s.addRecent("samples/part.nc");
  s.addRecent("./samples/../samples/part.nc");  // the same file: once, at the front
  ASSERT_EQ(s.recentFiles.size(), 1u);
  EXPECT_EQ(s.recentFiles[0], (std::filesystem::current_path() / "samples/part.nc").string());
}

// A device or a FIFO in the settings file's place must neither hang nor kill the window's start.
TEST(settings, ADeviceOrAFifoInItsPlaceGivesTheDefaultsAtOnce) {
  const std::string folder = freshFolder("not-a-file");
  std::filesystem::create_directories(folder);
  const std::string zero = folder + "/zero.json", fifo = folder + "/fifo.json";
  std::filesystem::create_symlink("/dev/zero", zero);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expectDefaults(loadSettings(zero));
  expectDefaults(loadSettings(fifo));  // no writer: read without waiting for one
}

// The text size follows the screen's density until the user chooses one: a 24-inch screen of
// 1920 pixels (531 mm) is usual, a 27-inch one of 2560 (597 mm, 109 dpi) a quarter denser, a
// 14-inch one of 2560 (302 mm) twice as dense; the desktop's own scale counts too. A size the
// screen set is not written as the user's.
TEST(settings, TheTextSizeFollowsTheScreenUntilChosen) {
  EXPECT_FLOAT_EQ(uiScaleForScreen(1920, 531, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(uiScaleForScreen(2560, 597, 1.0f), 1.25f);
  EXPECT_FLOAT_EQ(uiScaleForScreen(2560, 302, 1.0f), 2.0f);
  EXPECT_FLOAT_EQ(uiScaleForScreen(1920, 344, 1.0f), 1.5f);  // 15.6-inch laptop, 142 dpi
  EXPECT_FLOAT_EQ(uiScaleForScreen(2560, 0, 1.25f), 1.25f);  // no size reported: the desktop's scale
  EXPECT_FLOAT_EQ(uiScaleForScreen(0, 0, 3.0f), 2.0f);
  EXPECT_FLOAT_EQ(uiScaleForScreen(0, 0, 0.5f), 1.0f);
  Settings screen;
  screen.uiScale = 1.5f;  // set from the screen
  EXPECT_EQ(settingsText(screen).find("ui_scale"), std::string::npos);
  screen.uiScaleChosen = true;
  EXPECT_NE(settingsText(screen).find("ui_scale"), std::string::npos);
}

// The machine of a program is remembered by its absolute path, newest first, at most 20; the
// default machine, or a description that no longer reads as a machine, is not.
TEST(settings, AProgramsMachineIsRememberedAndReadBack) {
  using isurface::Machine, isurface::defaultMachine, isurface::machineDescriptionJson;
  Machine slow = defaultMachine();
  slow.name = "slow";
  slow.axes[0].maxAcceleration = 500;
  Settings s;
  s.rememberMachine("part.nc", machineDescriptionJson(slow));
  EXPECT_EQ(s.machineOf(std::filesystem::absolute("part.nc").string()), machineDescriptionJson(slow));
  const Settings back = settingsFromText(settingsText(s));
  EXPECT_EQ(back.machineOf("part.nc"), machineDescriptionJson(slow));
  EXPECT_EQ(settingsText(back), settingsText(s));
  s.rememberMachine("part.nc", machineDescriptionJson(defaultMachine()));
  EXPECT_EQ(s.machineOf("part.nc"), "");
  for (int k = 0; k < 25; ++k) s.rememberMachine("p" + std::to_string(k) + ".nc", machineDescriptionJson(slow));
  EXPECT_EQ(s.programMachines.size(), 20u);
  EXPECT_EQ(s.machineOf("p0.nc"), "");  // the oldest went first
  const Settings broken =
      settingsFromText(R"({"program_machines": [{"program": "/a.nc", "machine": {"cycle_s": -1}}, {"program": 3}]})");
  EXPECT_TRUE(broken.programMachines.empty());
}
