// The .vtp surface written without VTK, read back by VTK's own XML reader (what ParaView uses):
// every point, triangle and value as written.
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>

#include "isurface/io/vtp_surface.h"

namespace isurface {
namespace {

vtkSmartPointer<vtkPolyData> readBack(const std::string& bytes) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->ReadFromInputStringOn();
  reader->SetInputString(bytes);
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), 0);
  return reader->GetOutput();
}

// A grid of 300 x 200 vertices (more than one 32 KiB block per array) and its triangles.
TEST(vtpSurface, VtksReaderReadsEveryPointTriangleAndValue) {
  constexpr int kAlong = 300, kAcross = 200;
  std::vector<Vec3> positions;
  std::vector<float> speed, line;
  for (int j = 0; j < kAcross; ++j)
    for (int i = 0; i < kAlong; ++i) {
      positions.emplace_back(0.1 * i, 0.5 * j, std::sin(0.01 * i) * 3.25);
      speed.push_back(static_cast<float>(1000 + i + 0.25 * j));
      line.push_back(static_cast<float>(10 + j));
    }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (int j = 0; j + 1 < kAcross; ++j)
    for (int i = 0; i + 1 < kAlong; ++i) {
      const std::uint32_t a = j * kAlong + i, b = a + 1, c = a + kAlong, d = c + 1;
      triangles.push_back({a, b, c});
      triangles.push_back({b, d, c});
    }
  const vtkSmartPointer<vtkPolyData> poly =
      readBack(surfaceVtp(positions, triangles, {{"speed", speed}, {"line & pass <1>", line}}));
  ASSERT_EQ(poly->GetNumberOfPoints(), kAlong * kAcross);
  ASSERT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(triangles.size()));
  for (vtkIdType p : {vtkIdType(0), vtkIdType(12345), vtkIdType(kAlong * kAcross - 1)}) {
    double at[3];
    poly->GetPoint(p, at);
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(static_cast<float>(at[k]), static_cast<float>(positions[p][k])) << p;
  }
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType t : {vtkIdType(0), vtkIdType(4321), static_cast<vtkIdType>(triangles.size() - 1)}) {
    poly->GetCellPoints(t, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(ids->GetId(k), static_cast<vtkIdType>(triangles[t][k])) << t;
  }
  vtkDataArray* readSpeed = poly->GetPointData()->GetArray("speed");
  vtkDataArray* readLine = poly->GetPointData()->GetArray("line & pass <1>");
  ASSERT_NE(readSpeed, nullptr);
  ASSERT_NE(readLine, nullptr);
  for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); p += 997) {
    EXPECT_EQ(readSpeed->GetTuple1(p), speed[p]);
    EXPECT_EQ(readLine->GetTuple1(p), line[p]);
  }
}

TEST(vtpSurface, AnArrayOfAnotherLengthOrATriangleOffTheVerticesIsRefused) {
  const std::vector<Vec3> positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_THROW(surfaceVtp(positions, {{0, 1, 2}}, {{"speed", {1.0f, 2.0f}}}), std::invalid_argument);
  EXPECT_THROW(surfaceVtp(positions, {{0, 1, 3}}, {}), std::invalid_argument);
  EXPECT_EQ(readBack(surfaceVtp(positions, {{0, 1, 2}}, {}))->GetNumberOfPolys(), 1);
}

}  // namespace
}  // namespace isurface
