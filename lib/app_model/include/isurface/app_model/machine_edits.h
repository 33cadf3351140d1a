#pragma once
// A machine edited in the window is a machine of its own: never labelled as the one it was edited
// from, in captions, exports, reports or a description saved from it.
#include "isurface/machine/machine.h"

namespace isurface::app_model {

// `edited` as the machine it is. Where its description differs from `original`'s and its name was
// left as it was, the name says so and what differs: "NAME (edited: axes.x.max_acceleration_mm_s2,
// axes.y.max_acceleration_mm_s2)"; edits of an edited machine add to its list. A name the user
// gave is kept.
Machine namedAfterEdits(Machine edited, const Machine& original);

}  // namespace isurface::app_model
