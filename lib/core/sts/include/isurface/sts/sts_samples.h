#pragma once
// A slow tool servo tool path as interpolation samples: one sample per interpolation node, in
// Cartesian workpiece coordinates, with its PVT time and the discrete and interpolation errors
// around it as channels, so that every tool of iSurface (maps, the app, export) shows it.
#include "isurface/sts/sts_report.h"
#include "isurface/base/trajectory.h"

namespace isurface {

// `ncText` is the program formatStsNcProgram() wrote: each sample carries the line of its node's
// block. Channels beyond x y z t line: discrete_error_um, interpolation_error_um.
Trajectory stsTrajectory(const StsJobResult& job, const StsJobOptions& options, const std::string& ncText,
                         const std::string& source);

}  // namespace isurface
