#pragma once
// The cutter-location surface: triangles between each cutting pass and its neighbour, made by
// a strip that walks both passes together. Vertices are samples (every `stride`-th one).
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "isurface/surface/passes.h"

namespace isurface {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

struct SurfaceMesh {
  std::vector<std::uint32_t> vertexSample;              // sample index of each vertex
  std::vector<std::uint32_t> vertexPass;                // pass index of each vertex
  std::vector<std::array<std::uint32_t, 3>> triangles;  // vertex indices, counter-clockwise seen from +Z where possible
  // Nearest vertex on the previous / next pass (the one the strip matched), kNoVertex if none.
  std::vector<std::uint32_t> previousPassNeighbour, nextPassNeighbour;
  std::vector<std::size_t> passFirstVertex;             // first vertex of each pass, plus the end
  // Neighbouring passes that cross and double back over each other are not joined. Where the
  // pass after such a pair lies beside the pair's first, that pass is joined to it instead and
  // the crossing pass is left out (passesLeftOut); the other pairs stay apart (foldedPairs, the
  // index of each pair's first pass).
  std::vector<std::size_t> passesLeftOut, foldedPairs;
  std::size_t foldedStrips() const { return passesLeftOut.size() + foldedPairs.size(); }
  // Of the vertices, the share joined to a neighbouring pass (in a triangle): 0 when none.
  double joinedShare() const;
};

struct MeshOptions {
  double gapLimit = 2.0;    // mm; a triangle with an edge between passes longer than this is not made
  std::size_t stride = 1;   // use every stride-th sample of a pass (the last one always)
  bool feedback = false;    // build on the feedback positions instead of the commanded ones
  // A mesh of at least this many vertices makes half of its strips on a second thread (the same
  // mesh, sooner).
  std::size_t sideBySideVertices = 200'000;
};

SurfaceMesh buildSurfaceMesh(const Trajectory& samples, const PassSet& passes, const MeshOptions& options = {});

// Why there is no surface where no cutting pass was found.
inline constexpr const char* kNoCuttingPasses = "no cutting passes found to build a surface on";
// Why passes made no triangle: none, a single pass (which no gap joins to another), passes
// that fold over each other (SurfaceMesh::foldedStrips), or passes too far apart.
std::string whyNoTriangles(const PassSet& passes, double gapLimit, std::size_t foldedStrips = 0);
// What a mesh's folded strips mean, for a note beside a map; every such note holds
// kFoldedPassesNote.
std::string foldedPasses(std::size_t foldedStrips);
// The same, naming the G-code lines of the passes left out and of the pairs not joined; empty
// when every pair of neighbouring passes was joined.
std::string passesNotJoined(const Trajectory& samples, const PassSet& passes, const SurfaceMesh& mesh);
inline constexpr const char* kFoldedPassesNote = "cross and double back over each other";

// The smallest stride that keeps a mesh of these passes within maxVertices (at least 1).
std::size_t strideWithin(const PassSet& passes, std::size_t maxVertices);

// Vertex positions of a mesh, commanded or feedback, mm.
std::vector<Vec3> meshPositions(const Trajectory& samples, const SurfaceMesh& mesh, bool feedback = false);

// The typical distance between neighbouring passes, across them (the median over up to 4,096
// vertices spread over the mesh, of the distance to the next pass's nearest vertex less its part
// along the pass), mm; 0 when no two passes meet.
double medianPassSpacing(const std::vector<Vec3>& positions, const SurfaceMesh& mesh);

// Unit normals per vertex, area-weighted from the adjacent triangles (zero where none).
std::vector<Vec3> vertexNormals(const std::vector<Vec3>& positions, const SurfaceMesh& mesh);

}  // namespace isurface
