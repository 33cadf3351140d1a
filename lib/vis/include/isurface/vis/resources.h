#pragma once
// Files of resources/ and shaders/ compiled into the library, by path relative to the source
// tree ("shaders/glow.frag.glsl").
#include <map>
#include <string>

namespace isurface::vis {

const std::map<std::string, std::string>& embeddedResources();
// The file's text; throws std::runtime_error when it is not embedded.
const std::string& resourceText(const std::string& relativePath);

}  // namespace isurface::vis
