#pragma once
// LinuxCNC rs274's canonical commands as the interpreter suites compare them: each motion
// command's end point and rotary axes, in order.
#include <array>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "isurface/base/geometry.h"

namespace isurface::test {

struct Rs274Motion {
  Vec3 end = Vec3::Zero();         // program coordinates, as rs274 prints them
  std::array<double, 3> abc{};     // A, B, C
  Vec3 g92Offset = Vec3::Zero();   // the SET_G92_OFFSET in effect (rs274 prints it apart)
};

// STRAIGHT_TRAVERSE and STRAIGHT_FEED take x y z a b c; ARC_FEED(first end, second end, first
// centre, second centre, rotation, axis end, a, b, c), with the plane's axes in SELECT_PLANE's
// order: XY, XZ (first Z, second X) or YZ.
inline std::vector<Rs274Motion> rs274Motions(const std::string& canon) {
  static const std::regex motion(
      R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SET_G92_OFFSET|SELECT_PLANE)\(([^)]*)\))");
  std::vector<Rs274Motion> out;
  Vec3 offset = Vec3::Zero();
  Plane plane = Plane::XY;
  std::istringstream in(canon);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, motion)) continue;
    if (m[1] == "SELECT_PLANE") {
      plane = m[2] == "CANON_PLANE_XZ" ? Plane::ZX : m[2] == "CANON_PLANE_YZ" ? Plane::YZ : Plane::XY;
      continue;
    }
    std::vector<double> v;
    std::istringstream args(m[2].str());
    for (std::string a; std::getline(args, a, ',');) v.push_back(std::stod(a));
    if (m[1] == "SET_G92_OFFSET") {
      offset = Vec3(v.at(0), v.at(1), v.at(2));
      continue;
    }
    Rs274Motion p;
    p.g92Offset = offset;
    if (m[1] == "ARC_FEED") {
      const PlaneAxes ax = planeAxes(plane);
      p.end[ax.u] = v.at(0), p.end[ax.v] = v.at(1), p.end[ax.w] = v.at(5);
    } else {
      p.end = Vec3(v.at(0), v.at(1), v.at(2));
    }
    if (v.size() >= 6) p.abc = {v[v.size() - 3], v[v.size() - 2], v[v.size() - 1]};
    out.push_back(p);
  }
  return out;
}

}  // namespace isurface::test
