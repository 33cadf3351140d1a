// The HTML report: one self-contained file (every image embedded and decodable, nothing loaded
// from elsewhere) with its sections, and every region it lists with its G-code lines; opened
// in a real headless browser when Debian's Chromium is installed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <cstdint>
#include <cstring>
#include <string>

#include "image_compare.h"
#include "test_support.h"
#include "control_machines.h"

namespace fs = std::filesystem;
using isurface::test::readPng;
using isurface::test::runCli;
using isurface::test::runShell;
using isurface::test::scratchDir;

namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string decodeBase64(const std::string& text) {
  std::string out;
  int bits = 0;
  std::uint32_t value = 0;  // the bits not yet taken out, at most 14 of them
  for (const char c : text) {
    const char* const alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* at = std::strchr(alphabet, c);
    if (c == '=' || !at || !*at) break;
    value = ((value << 6) | std::uint32_t(at - alphabet)) & 0x3fff;
    bits += 6;
    if (bits >= 8) out += char((value >> (bits -= 8)) & 0xff);
  }
  return out;
}

// Writes the report of `program` and checks it; returns the HTML path.
std::string checkReport(const std::string& name, const std::string& program) {
  const std::string html = (scratchDir() / (name + ".html")).string(), json = (scratchDir() / (name + ".json")).string();
  const auto r = runCli("report " + program + " -o " + html + " --json " + json + " --regions 3");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = readAll(html);
  for (const char* section : {"summary", "maps", "regions", "limits"})
    EXPECT_NE(text.find(std::string("<section id=\"") + section + "\""), std::string::npos) << section;
  // Self-contained: nothing fetched, nothing run.
  EXPECT_EQ(text.find("http://"), std::string::npos);
  EXPECT_EQ(text.find("https://"), std::string::npos);
  EXPECT_EQ(text.find("<script"), std::string::npos);
  // Found by hand: std::regex recurses once a character, too deep for an image's hundred kilobytes.
  const std::string prefix = "src=\"data:image/png;base64,";
  int images = 0;
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at + 1)) {
    const std::size_t begin = at + prefix.size(), end = text.find('"', begin);
    if (end == std::string::npos) break;
    const std::string png = (scratchDir() / (name + "-image.png")).string();
    std::ofstream(png, std::ios::binary) << decodeBase64(text.substr(begin, end - begin));
    const auto decoded = readPng(png);
    EXPECT_FALSE(decoded.empty()) << "image " << images << " does not decode";
    ++images;
  }
  EXPECT_GE(images, 8);
  const nlohmann::json figures = nlohmann::json::parse(readAll(json));
  for (const auto& region : figures["regions"]) {
    const std::string lines = "Lines " + std::to_string(region["first_line"].get<int>()) + "-" +
                              std::to_string(region["last_line"].get<int>());
    EXPECT_NE(text.find(lines), std::string::npos) << lines;
    const std::string worst = "<span class=\"ln\">" + std::to_string(region["worst_line"].get<int>()) + "</span>";
    EXPECT_NE(text.find(worst), std::string::npos) << "the worst line's G-code: " << worst;
  }
  EXPECT_EQ(figures["axes"].size(), 3u);
  return html;
}

}  // namespace

TEST(Report, ABundledSample) {
  const std::string html = checkReport("transition", std::string(::isurface::test::sourceDir()) + "/samples/transition-surface.nc");
  EXPECT_NE(readAll(html).find("Programmed feeds"), std::string::npos);
}

TEST(Report, AProgramWrittenByOthers) {
  const std::string program = std::string(::isurface::test::sharedDir()) + "/realdata/linuxcnc_test.ngc";
  ISURFACE_SKIP_WITHOUT_REALDATA(program);
  checkReport("linuxcnc-test", program);
}

// The page as a reader sees it: Debian's Chromium (apt-get install chromium) draws it headless.
TEST(Report, OpensInABrowserAndIsNotBlank) {
  if (!fs::exists("/usr/bin/chromium")) GTEST_SKIP() << "Debian's chromium is not installed";
  const std::string html = checkReport("browser", std::string(::isurface::test::sourceDir()) + "/samples/cola-bottle-bottom.nc");
  const std::string shot = (scratchDir() / "report-shot.png").string();
  const auto r = runShell("timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
                          "--window-size=1200,1600 --enable-logging=stderr --v=0 --screenshot=" + shot + " file://" + html);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("CONSOLE"), std::string::npos) << r.err;
  const auto image = readPng(shot);
  ASSERT_FALSE(image.empty());
  std::size_t coloured = 0;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    if (image.rgb[i] < 200 || image.rgb[i + 1] < 200 || image.rgb[i + 2] < 200) ++coloured;
  EXPECT_GT(coloured, image.rgb.size() / 3 / 20) << "the page is nearly blank";
}

// A CI job gates on the report: a threshold crossed is exit code 1, the report written anyway.
TEST(Report, AThresholdCrossedFailsTheJob) {
  const std::string program = std::string(::isurface::test::sourceDir()) + "/samples/transition-surface.nc";
  const std::string html = (scratchDir() / "gate.html").string();
  const auto crossed = runCli("report " + program + " -o " + html + " --regions 1 --fail-on 'jerk>1'");
  EXPECT_EQ(crossed.exitCode, 1) << crossed.err;
  EXPECT_NE(crossed.err.find("threshold crossed: jerk"), std::string::npos) << crossed.err;
  EXPECT_TRUE(fs::exists(html));
  const auto kept = runCli("report " + program + " -o " + html + " --regions 1 --fail-on 'jerk>1e12'");
  EXPECT_EQ(kept.exitCode, 0) << kept.err;
  const auto bad = runCli("report " + program + " -o " + html + " --fail-on 'jerk=1'");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("bad --fail-on"), std::string::npos);
}

TEST(Report, ABatchRanksEveryProgramOfAFolder) {
  const fs::path in = scratchDir() / "batch-in", out = scratchDir() / "batch-out";
  fs::remove_all(in), fs::remove_all(out);
  fs::create_directories(in);
  fs::copy_file(std::string(::isurface::test::sourceDir()) + "/samples/transition-surface.nc", in / "transition.nc");
  std::ofstream(in / "stops.nc") << "G21 G90\nG1 X10 F600\nG4 P-\n";  // an error: listed, not reported
  std::ofstream(in / "notes.txt") << "\x01\x02 binary";              // not a program: left out
  const auto r = runCli("report --batch " + in.string() + " -o " + out.string() + " --regions 1");
  EXPECT_EQ(r.exitCode, 1) << r.err;  // one program could not be reported
  const std::string index = readAll((out / "index.html").string());
  EXPECT_NE(index.find("<a href=\"./transition.nc.html\">transition.nc</a>"), std::string::npos) << index;
  EXPECT_NE(index.find("stops.nc"), std::string::npos);
  EXPECT_NE(index.find("not reported"), std::string::npos);
  EXPECT_EQ(index.find("notes.txt"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "transition.nc.html"));
  EXPECT_TRUE(fs::exists(out / "transition.nc.json"));
}

namespace {

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// The section of the page with this id, up to the next section.
std::string sectionOf(const std::string& html, const std::string& id) {
  const std::size_t begin = html.find("<section id=\"" + id + "\"");
  if (begin == std::string::npos) return "";
  return html.substr(begin, html.find("</section>", begin) - begin);
}

}  // namespace

// Each region gets a close-up of the map around it, besides where it lies on the whole part.
TEST(Report, EachRegionHasACloseUp) {
  const std::string html = (scratchDir() / "closeups.html").string(), json = (scratchDir() / "closeups.json").string();
  const auto r = runCli("report " + std::string(::isurface::test::sourceDir()) + "/samples/wuzhishan.nc -o " + html + " --json " +
                        json + " --regions 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string text = readAll(html);
  const nlohmann::json figures = nlohmann::json::parse(readAll(json));
  ASSERT_EQ(figures["regions"].size(), 2u);
  for (int k = 1; k <= 2; ++k) {
    const std::string region = sectionOf(text, "region-" + std::to_string(k));
    EXPECT_EQ(occurrences(region, "alt=\"Close-up of the region"), 1u) << "region " << k;
    EXPECT_EQ(occurrences(region, "alt=\"Where it lies on the whole part"), 1u) << "region " << k;
    // The close-up (the region's first image) is another picture than the whole part (its
    // second): the same map framed closer.
    const std::string prefix = "src=\"data:image/png;base64,";
    std::vector<isurface::test::Image> images;
    for (std::size_t at = region.find(prefix); at != std::string::npos && images.size() < 2; at = region.find(prefix, at + 1)) {
      const std::size_t begin = at + prefix.size();
      const std::string png = (scratchDir() / ("closeup-" + std::to_string(images.size()) + ".png")).string();
      std::ofstream(png, std::ios::binary) << decodeBase64(region.substr(begin, region.find('"', begin) - begin));
      images.push_back(readPng(png));
    }
    ASSERT_EQ(images.size(), 2u);
    const isurface::test::ImageDifference d = isurface::test::compareImages(images[0], images[1]);
    EXPECT_TRUE(d.sameSize);
    EXPECT_GT(d.meanDifference, 10.0) << "region " << k << ": the close-up looks like the whole part";
  }
}

// A second run of the program (another machine's dump) beside this one: both speed maps, the
// difference and the figures of both, from the independent figures module.
TEST(Report, ASecondRunStandsBesideIt) {
  const std::string program = std::string(::isurface::test::sourceDir()) + "/samples/transition-surface.nc";
  const std::string other = (scratchDir() / "transition-linuxcnc.biip").string();
  ASSERT_EQ(runCli("simulate " + program + " -o " + other + " --machine " + std::string(::isurface::test::sourceDir()) +
                   "/resources/machines/linuxcnc-sim.json").exitCode, 0);
  const std::string html = (scratchDir() / "beside.html").string(), json = (scratchDir() / "beside.json").string();
  const auto r = runCli("report " + program + " -o " + html + " --json " + json + " --regions 1 --compare " + other);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string section = sectionOf(readAll(html), "comparison");
  ASSERT_FALSE(section.empty());
  EXPECT_EQ(occurrences(section, "<img"), 3u);
  EXPECT_NE(section.find("adjacent-pass inconsistency, p99"), std::string::npos);
  const nlohmann::json c = nlohmann::json::parse(readAll(json))["comparison"];
  EXPECT_EQ(c["compared_with"], other);
  EXPECT_GT(c["this_run"]["surface_samples"].get<double>(), 1000);
  EXPECT_NE(c["this_run"]["machining_time_s"].get<double>(), c["compared_run"]["machining_time_s"].get<double>());
  // A compared run that is not of this program is refused, as compare refuses it.
  const auto wrong = runCli("report " + program + " -o " + html + " --compare " + std::string(::isurface::test::sourceDir()) +
                            "/samples/wuzhishan.nc");
  EXPECT_EQ(wrong.exitCode, 2) << wrong.err;
}

// The program re-optimised: before and after maps, the difference, and the figures of the
// region and of the whole program.
// On a control that brakes at the transition's chords, where its transition is a region to
// optimise (control_machines.h).
TEST(ReportLong, AnOptimisationShowsBeforeAndAfter) {
  const std::string html = (scratchDir() / "optimised.html").string(), json = (scratchDir() / "optimised.json").string();
  const auto r = runCli("report " + std::string(::isurface::test::sourceDir()) + "/samples/transition-surface.nc -o " + html +
                        " --json " + json + " --regions 1 --optimize auto --machine " +
                        ::isurface::test::sourcePath(::isurface::test::kMachineWithoutChordSmoothing));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string section = sectionOf(readAll(html), "optimisation");
  ASSERT_FALSE(section.empty());
  EXPECT_EQ(occurrences(section, "<img"), 3u);
  EXPECT_EQ(occurrences(section, "<table"), 2u);
  const nlohmann::json o = nlohmann::json::parse(readAll(json))["optimisation"];
  EXPECT_EQ(o["mode"], "auto");
  EXPECT_LT(o["max_path_distance_mm"].get<double>(), 0.01);
  EXPECT_GT(o["region"]["before"]["surface_samples"].get<double>(), 0);
  EXPECT_EQ(runCli("report x.nc -o " + html + " --optimize some").exitCode, 2);
}

// A program that cuts no surface (a drilled hole) is still reported: its summary and how close
// the axes came to their limits, and a word on why there are no maps; a batch gate passes it.
TEST(Report, AProgramWithoutASurfaceIsStillReported) {
  const std::string program = (scratchDir() / "drill.nc").string();
  std::ofstream(program) << "G21 G90 G17\nG0 X10 Y10 Z5\nG1 Z-3 F120\nG0 Z5\nM30\n";
  const std::string html = (scratchDir() / "drill.html").string(), json = (scratchDir() / "drill.json").string();
  const auto r = runCli("report " + program + " -o " + html + " --json " + json);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string text = readAll(html);
  for (const char* section : {"summary", "maps", "regions", "limits"})
    EXPECT_NE(text.find(std::string("<section id=\"") + section + "\""), std::string::npos) << section;
  EXPECT_NE(text.find("No quality map: "), std::string::npos);
  const nlohmann::json figures = nlohmann::json::parse(readAll(json));
  EXPECT_TRUE(figures["regions"].empty());
  EXPECT_EQ(figures["axes"].size(), 3u);
  EXPECT_GT(figures["summary"]["machining_time_s"].get<double>(), 1.0);
  // Asked to re-optimise it too: the report stands and says why nothing was re-optimised.
  const auto optimised = runCli("report " + program + " -o " + html + " --json " + json + " --optimize auto");
  ASSERT_EQ(optimised.exitCode, 0) << optimised.err;
  EXPECT_NE(sectionOf(readAll(html), "optimisation").find("Not re-optimised: "), std::string::npos);
  EXPECT_TRUE(nlohmann::json::parse(readAll(json))["optimisation"].contains("not_done"));
}

// A comment of kilobytes on a program line is cut where the report shows the line, with its
// length said: the page does not grow with what the lines carry.
TEST(Report, LongProgramLinesAreCutWhereTheReportShowsThem) {
  std::ifstream in(std::string(::isurface::test::sourceDir()) + "/samples/transition-surface.nc");
  const std::string comment = " (" + std::string(5000, 'x') + ")";
  std::string program, line;
  while (std::getline(in, line)) program += line + (line.rfind("G1", 0) == 0 ? comment : "") + "\n";
  const std::string path = (scratchDir() / "long-lines.nc").string(), html = (scratchDir() / "long-lines.html").string();
  std::ofstream(path) << program;
  const auto r = runCli("report " + path + " -o " + html);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string text = readAll(html);
  EXPECT_NE(text.find("characters)"), std::string::npos);
  EXPECT_EQ(text.find(std::string(1000, 'x')), std::string::npos);
}

namespace {

// Whether every byte sequence of `text` is well-formed UTF-8 (as a page that says so must be).
bool wellFormedUtf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto b = [&](std::size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
    const unsigned lead = b(0);
    std::size_t length = lead < 0x80 ? 1 : lead >= 0xC2 && lead <= 0xDF ? 2 : lead >= 0xE0 && lead <= 0xEF ? 3
                                     : lead >= 0xF0 && lead <= 0xF4 ? 4 : 0;
    if (length == 0) return false;
    for (std::size_t k = 1; k < length; ++k)
      if (b(k) < 0x80 || b(k) > 0xBF) return false;
    i += length;
  }
  return true;
}

}  // namespace

// A program whose file name is not UTF-8 (Latin-1 from an old share) is reported under its name
// with replacement characters: the page says it is UTF-8 and holds only UTF-8.
TEST(Report, AFileNameThatIsNotUtf8MakesAWellFormedPage) {
  const fs::path folder = scratchDir() / "latin1-name";
  fs::create_directories(folder);
  const fs::path program = folder / "r\xe9sum\xe9.nc";
  fs::copy_file(isurface::test::sourcePath("samples/transition-surface.nc"), program, fs::copy_options::overwrite_existing);
  const std::string html = (scratchDir() / "latin1-name.html").string();
  const auto r = runCli("report '" + program.string() + "' -o " + html);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string page = readAll(html);
  EXPECT_TRUE(wellFormedUtf8(page));
  EXPECT_NE(page.find("r\xEF\xBF\xBDsum\xEF\xBF\xBD.nc"), std::string::npos);
}
