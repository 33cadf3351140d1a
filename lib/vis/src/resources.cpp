#include "isurface/vis/resources.h"

#include <stdexcept>

namespace isurface::vis {

const std::string& resourceText(const std::string& relativePath) {
  const auto& files = embeddedResources();
  const auto found = files.find(relativePath);
  if (found == files.end()) throw std::runtime_error("resource not built in: " + relativePath);
  return found->second;
}

}  // namespace isurface::vis
