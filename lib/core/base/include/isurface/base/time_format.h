#pragma once
// Machining times as people read them.
#include <string>

namespace isurface {

// "m:ss.mmm", from an hour on "h:mm:ss.mmm"; 0:00.000 for a time that is not a finite positive
// number.
std::string formatDuration(double seconds);

}  // namespace isurface
