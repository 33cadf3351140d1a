#pragma once
// The degenerate geometry sweep: programs whose moves are zero-length, repeated, collinear
// reversals, nanometre arcs, full circles, zero-pitch helices, tiny and huge coordinates, each
// followed by an ordinary raster; what the in-process and the command-line checks share.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace isurface::test {

// A raster of `passes` passes along X, `spacing` mm apart, each of `points` points `step` mm
// apart, from (x0, y0, z0), in plain G1 lines (what optimize re-optimises). `repeat` writes the
// middle point of each pass that many times (zero-length moves); `backtrack` steps back half a
// step there and forward again (a collinear reversal).
inline std::string raster(int passes, int points, double step, double x0 = 0, double y0 = 0, double z0 = 0,
                          int repeat = 1, bool backtrack = false, double spacing = 1) {
  std::ostringstream g;
  g << std::fixed << std::setprecision(12);
  g << "G0 X" << x0 << " Y" << y0 << " Z" << z0 + 1 << "\nG1 Z" << z0 << " F3000\n";
  for (int p = 0; p < passes; ++p) {
    const double y = y0 + p * spacing;
    const double direction = p % 2 == 0 ? 1 : -1;
    for (int i = 0; i < points; ++i) {
      const int k = direction > 0 ? i : points - 1 - i;
      const double x = x0 + k * step;
      const bool middle = i == points / 2;
      for (int r = 0; r < (middle ? repeat : 1); ++r) g << "G1 X" << x << " Y" << y << "\n";
      if (middle && backtrack) g << "G1 X" << x - direction * step / 2 << "\nG1 X" << x << "\n";
    }
  }
  return g.str();
}

struct DegenerateCase {
  std::string name;
  std::string gcode;
};

inline void PrintTo(const DegenerateCase& c, std::ostream* os) { *os << c.name; }

// Every case ends with an ordinary raster, so that passes, a surface and runs of G1 moves to
// re-optimise exist beside the degenerate moves.
inline DegenerateCase degenerate(std::string name, const std::string& moves) {
  return {std::move(name), "G21 G90 G17 G94\nG0 X0 Y0 Z1\nG1 Z0 F3000\n" + moves + raster(5, 16, 1.0, 0, 10) + "G0 Z5\nM2\n"};
}

inline std::vector<DegenerateCase> cases() {
  return {
      degenerate("ZeroLengthMoves", "G1 X0 Y0 Z0\nG0 X0 Y0 Z0\n" + raster(4, 12, 1.0, 0, 0, 0, 3)),
      degenerate("RepeatedPointsAndCollinearReversals", raster(4, 12, 1.0, 0, 0, 0, 2, true)),
      // Arcs whose chord is a nanometre on a 1 mm radius (centre and radius format); the
      // centre-format arc that ends a nanometre from its start (a full circle in LinuxCNC's
      // reading); an R-format arc whose radius is a nanometre (LinuxCNC has no lower limit).
      degenerate("NanometreArcs",
                 "G1 X10 Y0\nG2 X10.000000001 Y0 I0 J-1\nG3 X10.000000002 Y0 R1\nG2 X10.000000001 Y0 R1\n"
                 "G3 X10 Y0.000000001 I-1 J0\nG2 X10 Y0.000000003 R0.0000000015\nG1 X0 Y0\n"),
      degenerate("FullCirclesInEveryPlane",
                 "G1 X5 Y0\nG17 G2 X5 Y0 I-2 J0\nG3 X5 Y0 I-2 J0 P2\nG18 G2 X5 Z0 I-2 K0\n"
                 "G19 G3 Y0 Z0 J1 K0\nG17 G1 X0 Y0\n"),
      degenerate("ZeroPitchHelices",
                 "G1 X5 Y0\nG2 X5 Y0 Z0 I-2.5 J0 P3\nG3 X5 Y0 Z0.000000001 I-2.5 J0 P2\n"
                 "G2 X5 Y0 Z-1 I-2.5 J0 P2\nG1 X0 Y0 Z0\n"),
      degenerate("TinyCoordinates", raster(4, 12, 1e-6, 1e-9, 1e-9, 1e-9, 1, false, 1e-6)),
      degenerate("HugeCoordinates", raster(3, 10, 1.0, 2e4, -2e4, 1e3) + "G0 Z1\nG0 X0 Y10\n"),
  };
}

template <typename Values>
std::size_t countNonFinite(const Values& values) {
  std::size_t n = 0;
  for (const auto v : values) n += !std::isfinite(double(v));
  return n;
}

class DegenerateGeometry : public ::testing::TestWithParam<DegenerateCase> {};

}  // namespace isurface::test
