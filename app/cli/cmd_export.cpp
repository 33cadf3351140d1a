// isurface-cli export: the CL surface with every scalar, as VTK XML polydata for ParaView
// (written without VTK).
#include <cstdio>
#include <memory>

#include "command.h"
#include "inputs.h"
#include "output_options.h"
#include "isurface/io/atomic_file.h"
#include "isurface/analysis/quantities.h"
#include "isurface/io/vtp_surface.h"
#include "isurface/surface/surface_mesh.h"
#include "progress.h"
#include "trajectory_input.h"

namespace isurface::cli {
namespace {

struct ExportOptions {
  std::string biip, vtp, gcode, surface = "commanded";
  GapLimitOption gapLimit;
  bool force = false;
};

int runExport(const ExportOptions& o) {
  if (o.surface != "commanded" && o.surface != "feedback")
    throw InputError(Diagnostic{"", 0, 0, "unknown --surface '" + o.surface + "' (commanded, feedback)"});
  const double gapLimit = o.gapLimit.checked();
  const OpenedRun run = openRunOnTerminal({o.gcode, o.biip}, MachineOption{}, o.force);
  const Program* program = run.program.get();
  const Trajectory& samples = *run.samples;
  const bool feedback = o.surface == "feedback";
  if (feedback && !samples.hasFeedback())
    throw InputError(Diagnostic{o.biip, 0, 0, "no feedback channels (fb_x fb_y fb_z) for the feedback surface"});
  ProgressLine progress("building the surface");
  PassOptions passOptions;
  passOptions.program = program;
  const PassSet passes = splitPasses(samples, passOptions);
  MeshOptions meshOptions;
  meshOptions.feedback = feedback;
  meshOptions.gapLimit = gapLimit;
  const SurfaceMesh mesh = buildSurfaceMesh(samples, passes, meshOptions);
  if (mesh.triangles.empty()) throw InputError(Diagnostic{o.biip, 0, 0, whyNoTriangles(passes, gapLimit)});
  std::vector<VtpPointArray> arrays;
  arrays.push_back({"pass", std::vector<float>(mesh.vertexPass.begin(), mesh.vertexPass.end())});
  const auto& infos = quantityInfos();
  for (std::size_t k = 0; k < infos.size(); ++k) {
    progress.update(static_cast<double>(k) / infos.size());
    if (!quantityAvailable(infos[k].quantity, samples)) continue;
    arrays.push_back({infos[k].name, vertexQuantity(infos[k].quantity, samples, mesh)});
  }
  for (const auto& [name, values] : samples.extra) {
    std::vector<float> perVertex(mesh.vertexSample.size());
    for (std::size_t v = 0; v < perVertex.size(); ++v) perVertex[v] = static_cast<float>(values[mesh.vertexSample[v]]);
    arrays.push_back({name, std::move(perVertex)});
  }
  progress.finish();
  writeFileAtomically(o.vtp, surfaceVtp(meshPositions(samples, mesh, feedback), mesh.triangles, arrays));
  std::printf("%s: %zu vertices, %zu triangles, %zu scalars\n", o.vtp.c_str(), mesh.vertexSample.size(),
              mesh.triangles.size(), arrays.size() - 1);
  return kExitOk;
}

}  // namespace

Command exportCommand() {
  return Command{"export", "Write the CL surface of a Biip dump with every scalar as a .vtp file (ParaView)", [](CLI::App& sub) {
      auto o = std::make_shared<ExportOptions>();
      sub.add_option("biip", o->biip, "Biip dump")->required();
      outputOption(sub.add_option("--vtp", o->vtp, "VTK XML polydata file to write"))->required();
      sub.add_option("--gcode", o->gcode, "the program of the dump (tells rapids from cutting moves)");
      sub.add_option("--surface", o->surface, "commanded or feedback")->capture_default_str();
      sub.add_flag("--force", o->force, "use the dump even if it does not look like the program's own");
      o->gapLimit.addTo(sub);
      return [o] { return runExport(*o); };
    }};
}

}  // namespace isurface::cli
