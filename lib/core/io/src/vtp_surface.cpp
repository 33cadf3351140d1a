#include "isurface/io/vtp_surface.h"

#include <zlib.h>

#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace isurface {

namespace {

// VTK's zlib blocks: uncompressed pieces of this size, each compressed on its own.
constexpr std::size_t kBlockBytes = 1 << 15;

void appendU64(std::string& out, std::uint64_t v) {
  unsigned char bytes[8];
  for (int k = 0; k < 8; ++k) bytes[k] = static_cast<unsigned char>(v >> (8 * k));  // little-endian
  out.append(reinterpret_cast<const char*>(bytes), 8);
}

// One appended array as vtkZLibDataCompressor frames it: the number of blocks, the block size,
// the size of a last partial block (0 when it is whole), each block's compressed size, then the
// compressed blocks.
std::string compressedArray(const void* data, std::size_t bytes) {
  const auto* in = static_cast<const unsigned char*>(data);
  const std::size_t blocks = (bytes + kBlockBytes - 1) / kBlockBytes;
  std::vector<std::string> compressed(blocks);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t size = std::min(kBlockBytes, bytes - b * kBlockBytes);
    uLongf length = compressBound(static_cast<uLong>(size));
    compressed[b].resize(length);
    if (compress2(reinterpret_cast<Bytef*>(compressed[b].data()), &length, in + b * kBlockBytes,
                  static_cast<uLong>(size), Z_DEFAULT_COMPRESSION) != Z_OK)
      throw std::runtime_error("zlib could not compress the surface");
    compressed[b].resize(length);
  }
  std::string out;
  appendU64(out, blocks);
  appendU64(out, kBlockBytes);
  appendU64(out, bytes % kBlockBytes);
  for (const std::string& c : compressed) appendU64(out, c.size());
  for (const std::string& c : compressed) out += c;
  return out;
}

// Escapes what XML does not allow in an attribute's value.
std::string attribute(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string surfaceVtp(const std::vector<Vec3>& positions, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                       const std::vector<VtpPointArray>& arrays) {
  const std::size_t n = positions.size();
  for (const VtpPointArray& a : arrays)
    if (a.values.size() != n)
      throw std::invalid_argument(fmt::format("array {} has {} values for {} vertices", a.name, a.values.size(), n));
  std::vector<float> points(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) points[3 * i + k] = static_cast<float>(positions[i][k]);
  // VTK XML cells: the vertices of every cell one after the other, and where each cell ends.
  std::vector<std::int64_t> connectivity(3 * triangles.size()), offsets(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (triangles[t][k] >= n)
        throw std::invalid_argument(fmt::format("triangle {} names vertex {} of {}", t, triangles[t][k], n));
      connectivity[3 * t + k] = triangles[t][k];
    }
    offsets[t] = static_cast<std::int64_t>(3 * (t + 1));
  }

  std::string appended, header;
  const auto dataArray = [&](const char* type, const std::string& name, int components, const void* data,
                             std::size_t bytes) {
    header += fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
                          "offset=\"{}\"/>\n",
                          type, attribute(name), components, appended.size());
    appended += compressedArray(data, bytes);
  };
  header += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                        "NumberOfPolys=\"{}\">\n      <PointData>\n",
                        n, triangles.size());
  for (const VtpPointArray& a : arrays) dataArray("Float32", a.name, 1, a.values.data(), n * sizeof(float));
  header += "      </PointData>\n      <Points>\n";
  dataArray("Float32", "Points", 3, points.data(), points.size() * sizeof(float));
  header += "      </Points>\n      <Polys>\n";
  dataArray("Int64", "connectivity", 1, connectivity.data(), connectivity.size() * sizeof(std::int64_t));
  dataArray("Int64", "offsets", 1, offsets.data(), offsets.size() * sizeof(std::int64_t));
  header += "      </Polys>\n    </Piece>\n";

  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\" "
      "compressor=\"vtkZLibDataCompressor\">\n  <PolyData>\n";
  out += header;
  out += "  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
  out += appended;
  out += "\n  </AppendedData>\n</VTKFile>\n";
  return out;
}

}  // namespace isurface
