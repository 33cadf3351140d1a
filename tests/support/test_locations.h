#pragma once
// Where the tests find the clone, ../shared and the programs they run. Defined in a source that
// CMake generates in the build tree (tests/CMakeLists.txt), so that the tests' own objects do not
// depend on the clone's folder and a compiler cache shared by clones in other folders reuses them.

namespace isurface::test {

const char* sourceDir();   // the clone's root
const char* sharedDir();   // ../shared beside the clone; its realdata/ may be missing
const char* cliProgram();  // isurface-cli in this build tree
const char* guiProgram();  // isurface in this build tree; empty when the window tier is not built

}  // namespace isurface::test
