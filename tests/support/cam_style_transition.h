#pragma once
// A finishing program as a CAM system writes one, made without any of the project's code (the
// bundled samples come from `isurface-cli sample`, which samples its surfaces at fixed
// steps): a plane, a fillet whose radius varies along Y, and a slope, cut by a zigzag raster
// along X. The fillet's points are placed by a chord tolerance (the sagitta of each chord
// equals it), the plane and the slope are one move each, coordinates are rounded to the
// post-processor's 4 decimals and blocks carry N numbers, as a Fanuc-style post writes them.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace isurface::testing {

struct CamStyleTransition {
  double chordTolerance = 0.005;  // mm
  double stepOver = 0.5;          // mm between passes
  double width = 30.0;            // mm, extent in Y
  double length = 55.0;           // mm, extent in X
  double filletStart = 20.0;      // mm, X where the plane meets the fillet
  double slopeDegrees = 25.0;
  double feed = 2500.0;           // mm/min
};

// Radius of the fillet at `y`, mm: 5 mm at the edges, 11 mm in the middle.
inline double camFilletRadius(const CamStyleTransition& part, double y) {
  return 5.0 + 6.0 * std::sin(M_PI * y / part.width);
}

// The cutter-location profile of one pass in X order, mm (x, z).
inline std::vector<std::pair<double, double>> camProfile(const CamStyleTransition& part, double y) {
  const double r = camFilletRadius(part, y);
  const double theta = part.slopeDegrees * M_PI / 180.0;
  const double step = 2.0 * std::acos(1.0 - part.chordTolerance / r);
  const int count = std::max(1, static_cast<int>(std::ceil(theta / step)));
  std::vector<std::pair<double, double>> points = {{0.0, 0.0}};
  for (int k = 0; k <= count; ++k) {
    const double phi = theta * k / count;
    points.emplace_back(part.filletStart + r * std::sin(phi), r * (1.0 - std::cos(phi)));
  }
  const auto [x1, z1] = points.back();
  points.emplace_back(part.length, z1 + (part.length - x1) * std::tan(theta));
  return points;
}

inline std::string camStyleTransitionProgram(const CamStyleTransition& part = {}) {
  std::string out = "%\nO1001 (CAM-STYLE TRANSITION)\n(TOOL 1 - D6 BALL, CL POINTS, CHORD TOLERANCE ";
  out += fmt::format("{:.3f} MM)\n", part.chordTolerance);
  int n = 10;
  auto block = [&](const std::string& words) {
    out += fmt::format("N{} {}\n", n, words);
    n += 10;
  };
  block("G21 G90 G17 G94 G40 G49 G80");
  block("T1 M6");
  block("S10000 M3");
  block("G0 Z30.");
  block("G0 X0. Y0.");
  block("G1 Z0. F800.");
  const int passes = static_cast<int>(std::floor(part.width / part.stepOver + 1e-9)) + 1;
  bool feedWritten = false;
  for (int p = 0; p < passes; ++p) {
    const double y = p * part.stepOver;
    std::vector<std::pair<double, double>> profile = camProfile(part, y);
    if (p % 2 == 1) std::reverse(profile.begin(), profile.end());
    if (p > 0)  // the step-over, at the end of the previous pass
      block(fmt::format("G1 X{:.4f} Y{:.4f} Z{:.4f}", profile.front().first, y, profile.front().second));
    for (std::size_t k = 1; k < profile.size(); ++k) {
      std::string words = fmt::format("G1 X{:.4f} Z{:.4f}", profile[k].first, profile[k].second);
      if (!feedWritten) words += fmt::format(" F{:.0f}.", part.feed), feedWritten = true;
      block(words);
    }
  }
  block("G0 Z30.");
  block("M5");
  block("M30");
  out += "%\n";
  return out;
}

}  // namespace isurface::testing
