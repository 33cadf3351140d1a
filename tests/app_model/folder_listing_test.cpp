// The Open dialog's listing: folders first, names sorted, files told apart by content.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "isurface/app_model/folder_listing.h"
#include "test_support.h"

using namespace isurface;
using namespace isurface::app_model;

namespace {

std::vector<std::string> names(const FolderListing& listing) {
  std::vector<std::string> out;
  for (const FolderEntry& e : listing.entries) out.push_back(e.name + (e.folder ? "/" : ""));
  return out;
}

std::filesystem::path filledFolder() {
  const std::filesystem::path folder = test::scratchDir() / "browse";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder / "zeta");
  std::filesystem::create_directories(folder / "Alpha");
  std::filesystem::create_directories(folder / ".hidden");
  std::ofstream(folder / "b-part.NC") << "G21\nG1 X1 F100\n";
  std::ofstream(folder / "a-part.ngc") << "G21\nG1 X2 F100\n";
  std::ofstream(folder / "run.biip", std::ios::binary) << "BIIP" << std::string(60, '\0');
  std::ofstream(folder / "log.csv") << "t,x,y,z\n0,1,2,3\n0.001,1,2,3\n";
  std::ofstream(folder / "notes.bin", std::ios::binary) << std::string(200, '\0');
  return folder;
}

}  // namespace

TEST(folderListing, FoldersFirstThenFilesSortedByName) {
  const FolderListing listing = listFolder(filledFolder().string(), FileFilter::Openable);
  EXPECT_TRUE(listing.error.empty()) << listing.error;
  EXPECT_EQ(names(listing), (std::vector<std::string>{"Alpha/", "zeta/", "a-part.ngc", "b-part.NC", "log.csv", "run.biip"}));
  EXPECT_EQ(listing.entries[2].kind, FileKind::Program);
  EXPECT_EQ(listing.entries[4].kind, FileKind::CsvTrace);
  EXPECT_EQ(listing.entries[5].kind, FileKind::Dump);
}

TEST(folderListing, FilteredByKind) {
  const std::string folder = filledFolder().string();
  EXPECT_EQ(names(listFolder(folder, FileFilter::Programs)),
            (std::vector<std::string>{"Alpha/", "zeta/", "a-part.ngc", "b-part.NC"}));
  EXPECT_EQ(names(listFolder(folder, FileFilter::Dumps)), (std::vector<std::string>{"Alpha/", "zeta/", "run.biip"}));
  EXPECT_EQ(names(listFolder(folder, FileFilter::Traces)), (std::vector<std::string>{"Alpha/", "zeta/", "log.csv"}));
  const FolderListing all = listFolder(folder, FileFilter::All);
  ASSERT_EQ(all.entries.size(), 7u);
  EXPECT_EQ(all.entries[5].name, "notes.bin");
  EXPECT_FALSE(all.entries[5].kind.has_value());
}

TEST(folderListing, AFolderThatCannotBeReadSaysWhy) {
  const FolderListing listing = listFolder((test::scratchDir() / "no-such-folder").string(), FileFilter::All);
  EXPECT_TRUE(listing.entries.empty());
  EXPECT_NE(listing.error.find("no-such-folder"), std::string::npos);
}
