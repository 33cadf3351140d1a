#pragma once
// A triangle surface with values at its vertices as VTK XML PolyData (.vtp, what ParaView and
// VTK open), written without VTK: one piece, its arrays appended raw and zlib-compressed as
// vtkXMLPolyDataWriter writes them.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface {

struct VtpPointArray {
  std::string name;
  std::vector<float> values;  // one per vertex
};

// The file's bytes: vertices (mm, stored as 32-bit floats), triangles (vertex indices) and the
// arrays. Throws std::invalid_argument when an array is not one value per vertex or a triangle
// names a vertex that is not there.
std::string surfaceVtp(const std::vector<Vec3>& positions, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                       const std::vector<VtpPointArray>& arrays);

}  // namespace isurface
