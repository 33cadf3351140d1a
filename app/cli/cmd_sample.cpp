// isurface-cli sample: writes the bundled sample programs from their generators.
#include <cstdio>

#include "command.h"
#include "output_options.h"
#include "isurface/io/atomic_file.h"
#include "isurface/base/diagnostic.h"
#include "isurface/gcode/sample_parts.h"

namespace isurface::cli {
namespace {

struct SampleOptions {
  std::string name, output;
  bool list = false;
};

int runSample(const SampleOptions& o) {
  if (o.list || o.name.empty()) {
    for (const SamplePart& part : sampleParts()) std::printf("%-20s %s\n", part.name.c_str(), part.description.c_str());
    return kExitOk;
  }
  bool known = false;
  for (const SamplePart& part : sampleParts()) known = known || part.name == o.name;
  if (!known) throw InputError(Diagnostic{"", 0, 0, "unknown sample '" + o.name + "' (see isurface-cli sample --list)"});
  const std::string text = generateSamplePart(o.name);
  const std::string path = o.output.empty() ? o.name + ".nc" : o.output;
  writeFileAtomically(path, text);
  std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace

Command sampleCommand() {
  return Command{"sample", "Write one of the paper's sample parts as G-code (D6R3 ball-end mill, F3000)", [](CLI::App& sub) {
      auto o = std::make_shared<SampleOptions>();
      sub.add_option("name", o->name, "sample part name");
      outputOption(sub.add_option("-o,--output", o->output, "G-code file to write (default NAME.nc)"));
      sub.add_flag("--list", o->list, "list the sample parts");
      return [o] { return runSample(*o); };
    }};
}

}  // namespace isurface::cli
