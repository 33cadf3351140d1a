// The Open dialog's model: it opens at the folder of its path, a folder typed is entered and a
// file typed is opened, the filter lists the folder again.
#include <gtest/gtest.h>

#include <filesystem>

#include "isurface/app_model/open_dialog.h"
#include "scratch_files.h"

using namespace isurface;
using namespace isurface::app_model;

TEST(openDialog, EntersFoldersAndOpensFiles) {
  const std::filesystem::path folder = test::freshScratchFolder("open-dialog");
  std::filesystem::create_directories(folder / "sub");
  test::writeFileBytes(folder / "sub" / "part.nc", "G21\nG1 X1 F100\n");
  test::writeFileBytes(folder / "run.biip", "BIIP" + std::string(60, '\0'));
  OpenDialog d;
  d.path = (folder / "run.biip").string();
  d.open();
  EXPECT_TRUE(d.opening);
  EXPECT_EQ(std::filesystem::path(d.listing.folder), folder);
  ASSERT_EQ(d.listing.entries.size(), 2u);  // sub/, run.biip

  d.path = (folder / "sub").string();
  EXPECT_EQ(d.submit(), std::nullopt);  // a folder: entered
  EXPECT_EQ(std::filesystem::path(d.listing.folder), folder / "sub");
  EXPECT_EQ(d.path, d.listing.folder + "/");
  d.path += "part.nc";
  EXPECT_EQ(d.submit(), (folder / "sub" / "part.nc").string());
  d.up();
  EXPECT_EQ(std::filesystem::path(d.listing.folder), folder);

  d.filter = FileFilter::Programs;  // a dump is not a program: listed again without it
  d.relist(d.listing.folder);
  ASSERT_EQ(d.listing.entries.size(), 1u);
  EXPECT_TRUE(d.listing.entries[0].folder);
  d.path.clear();
  EXPECT_EQ(d.submit(), std::nullopt);
}
