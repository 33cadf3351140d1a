// The Export dialog's model: the path follows the kind of export, and the dialog says why it
// cannot export before the user presses Export.
#include <gtest/gtest.h>

#include "isurface/app_model/export_dialog.h"

using namespace isurface::app_model;

TEST(exportDialog, AnotherKindTakesItsOwnExtension) {
  ExportDialog d;
  d.path = "out/exp.png";
  d.choose(ExportKind::MapFigures);
  EXPECT_EQ(d.path, "out/exp.json");
  d.choose(ExportKind::LineSamples);
  EXPECT_EQ(d.path, "out/exp.csv");
  d.choose(ExportKind::Report);
  EXPECT_EQ(d.path, "out/exp.html");
  d.path = "notes.txt";  // not an export's extension: left as typed
  d.choose(ExportKind::ViewPng);
  EXPECT_EQ(d.path, "notes.txt");
  d.path = ".png";  // nothing before the extension: left as typed
  d.choose(ExportKind::MapFigures);
  EXPECT_EQ(d.path, ".png");
}

TEST(exportDialog, ShowsTheSelectedLine) {
  ExportDialog d;
  d.show(std::nullopt);
  EXPECT_TRUE(d.opening);
  EXPECT_EQ(d.first, 1);
  d.show(42u);
  EXPECT_EQ(d.first, 42);
  EXPECT_EQ(d.last, 42);
}

TEST(exportDialog, SaysWhyItCannotExport) {
  ExportDialog d;
  ExportSubject subject;
  EXPECT_EQ(d.problem(subject), "nothing to export: open a program or a dump first");
  subject = {"cameo.nc", true, false, 1, false};
  EXPECT_EQ(d.problem(subject), "no map to export: cameo.nc has no surface");
  d.kind = ExportKind::LineSamples;  // samples need no map
  EXPECT_EQ(d.problem(subject), "give the file to write");
  subject.thinning = 4;
  EXPECT_EQ(d.problem(subject), "cameo.nc is shown thinned (1 sample in 4): its figures and samples need every sample");
  subject = {"cameo.nc", true, true, 1, true};
  d.path = "a.csv";
  d.first = 5;
  d.last = 4;
  EXPECT_EQ(d.problem(subject), "the lines must be first <= last, from 1");
  d.kind = ExportKind::ViewPng;
  d.width = 63;
  EXPECT_EQ(d.problem(subject), "the size must be 64 to 8192 pixels each way");
  d.width = 800;
  EXPECT_EQ(d.problem(subject), "");
  d.kind = ExportKind::Report;
  EXPECT_EQ(d.problem(subject), "wait for the work in progress (or cancel it) first");
  d.regions = 51;
  EXPECT_EQ(d.problem(subject), "the regions shown must be 0 to 50");
}
