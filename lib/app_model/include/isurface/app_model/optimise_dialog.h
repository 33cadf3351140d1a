#pragma once
// The Optimise dialog's model: the lines of the region (typed, found, or dragged as a box over
// the surface), what the closed loop aims at, why it cannot run, and where its result is saved.
#include <cstdint>
#include <optional>
#include <string>

#include "isurface/app_model/box_selection.h"

namespace isurface::app_model {

struct OptimiseDialog {
  bool opening = false;  // asked for: the window opens it on its next frame
  bool open = false;     // shown this frame
  int first = 1, last = 1;
  int objective = 0;     // an Objective: balanced, time, quality
  std::string problem;   // why the document cannot be optimised, if it cannot
  std::string notice;    // why the region last asked for was not chosen
  // The box last dragged over the view and what it holds; where it was dragged (shown while the
  // dialog is open: the camera may move once it closes).
  std::optional<BoxSelection> box;
  ScreenRectangle boxOnView;
  std::string program;   // the program whose lines and box these are
  // Where the result is saved: offered, or typed over the offer.
  std::string savePath;

  // Another program's lines would be other moves: forgotten when `programPath` is not theirs.
  void forgetTheRegionOfAnotherProgram(const std::string& programPath);
  // Holds `lines` (and the box they were found in, if any); the notice is cleared.
  void hold(LineRange lines, std::optional<BoxSelection> foundIn = std::nullopt);
  // Whether the box stands for the lines: it does while they are still its own (widened, or
  // those of the passes it lies on).
  bool boxed() const;
  // The other lines of a widened region held with its box (its own passes, or the passes joined
  // to them), when it has them.
  std::optional<LineRange> otherWidth() const;
  void holdOtherWidth();
  // Why the lines cannot be optimised as typed; empty when they can.
  std::string rangeProblem() const;
  // Offers where to save the result of optimising `programPath`: "NAME-optimized.nc" in
  // `folder` (where the user saved last, else the working folder), never the program's own
  // folder unless that is where the user saves; a path typed over an earlier offer for the same
  // program stays.
  void offerSavePath(const std::string& programPath, const std::string& folder);

 private:
  std::string offered_, offeredFor_;
};

}  // namespace isurface::app_model
