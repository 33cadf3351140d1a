#pragma once
// The paper's test parts, machined with a D6R3 ball-end mill at F3000 S12000, as G-code written
// the way CAM output is: ball-end cutter locations dropped onto the surface, simplified to G1
// moves within a chord tolerance. They are the bundled samples (samples/*.nc).
#include <string>
#include <vector>

namespace isurface {

struct SamplePart {
  std::string name;         // file stem, e.g. "transition-surface"
  std::string description;  // one line, written as the program's first comment
};

const std::vector<SamplePart>& sampleParts();

// G-code text of a sample part; throws std::invalid_argument for an unknown name.
std::string generateSamplePart(const std::string& name);

}  // namespace isurface
