#pragma once
// The machine programs are simulated with, and the machine window's copy of it being edited:
// loaded from and saved to a description, checked as a file is, applied as a machine of its own.
#include <optional>
#include <string>

#include "isurface/machine/machine.h"

namespace isurface::app_model {

struct MachineWindow {
  Machine inUse = defaultMachine();     // what programs are simulated with
  std::string source = "built-in default";  // where it came from
  Machine edit = defaultMachine();      // the window's copy, applied by apply()
  bool open = false;
  bool appearing = false;  // opened this frame: it takes the machine in use and comes to the front
  std::string loadPath, savePath;
  std::string message;  // what the last request did, or why it failed
  // The program the machine in use was applied to (simulated with from the window); empty when
  // it was chosen with no program open, for the programs opened next.
  std::string appliedFor;
  // The description last loaded, as it was read.
  struct Loaded {
    std::string path, description;
  };
  std::optional<Loaded> loaded;

  // Opens it with the machine in use; an open one keeps its edits.
  void show();
  // The machine in use from now on, and in the window.
  void use(const Machine& machine, const std::string& from);
  void revert();
  // Reads loadPath into the copy being edited.
  void load();
  // The copy, checked as a description file is and named after its edits from the machine in
  // use; nothing (and the message says why) when a value is refused.
  std::optional<Machine> checkedEdit();
  // The copy becomes the machine in use: its source stays where nothing changed, is the file it
  // was loaded from where it is that file's machine, else "edited"; false when it was refused.
  bool apply();
};

}  // namespace isurface::app_model
