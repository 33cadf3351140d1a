#pragma once
// Comparing rendered PNGs with reference images under a tolerance that a real regression breaks
// (a changed colour map, a missing legend, a hole in the surface) but rendering noise does not.
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace isurface::test {

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // row-major, 3 bytes a pixel
  bool empty() const { return rgb.empty(); }
  unsigned char* at(int x, int y) { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
  const unsigned char* at(int x, int y) const { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

inline Image readPng(const std::string& path) {
  Image image;
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!reader->CanReadFile(path.c_str())) return image;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  const int components = data->GetNumberOfScalarComponents();
  image.width = dims[0];
  image.height = dims[1];
  image.rgb.resize(static_cast<std::size_t>(dims[0]) * dims[1] * 3);
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const auto* pixel = static_cast<const unsigned char*>(data->GetScalarPointer(x, y, 0));
      for (int c = 0; c < 3; ++c) image.at(x, y)[c] = pixel[std::min(c, components - 1)];
    }
  return image;
}

struct ImageDifference {
  bool sameSize = false;
  double meanDifference = 0;   // mean absolute channel difference over the image, 0..255
  double worstBlock = 0;       // largest mean absolute difference of any 32x32 block, 0..255
};

inline ImageDifference compareImages(const Image& a, const Image& b) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height || a.empty()) return d;
  d.sameSize = true;
  constexpr int kBlock = 32;
  double total = 0;
  for (int by = 0; by < a.height; by += kBlock)
    for (int bx = 0; bx < a.width; bx += kBlock) {
      double block = 0;
      int count = 0;
      for (int y = by; y < std::min(by + kBlock, a.height); ++y)
        for (int x = bx; x < std::min(bx + kBlock, a.width); ++x)
          for (int c = 0; c < 3; ++c) {
            block += std::abs(static_cast<int>(a.at(x, y)[c]) - static_cast<int>(b.at(x, y)[c]));
            ++count;
          }
      total += block;
      d.worstBlock = std::max(d.worstBlock, block / count);
    }
  d.meanDifference = total / (3.0 * a.width * a.height);
  return d;
}

// The tolerance of the screenshot tests: a render matches its reference when no 32x32 block
// differs by more than this on average (0..255) and the whole image by less than a fifth of it.
constexpr double kWorstBlockTolerance = 12.0;
inline bool matches(const ImageDifference& d) {
  return d.sameSize && d.worstBlock <= kWorstBlockTolerance && d.meanDifference <= kWorstBlockTolerance / 5;
}

}  // namespace isurface::test
