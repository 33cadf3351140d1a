#include "isurface/app_model/machine_window.h"

#include "isurface/app_model/machine_edits.h"
#include "isurface/base/diagnostic.h"

namespace isurface::app_model {

void MachineWindow::show() {
  if (open) return;
  open = appearing = true;
  edit = inUse;
  message.clear();
}

void MachineWindow::use(const Machine& machine, const std::string& from) {
  inUse = edit = machine;
  source = from;
  appliedFor.clear();
}

void MachineWindow::revert() {
  edit = inUse;
  message.clear();
}

void MachineWindow::load() {
  if (loadPath.empty()) return;
  try {
    edit = loadMachine(loadPath);
    loaded = Loaded{loadPath, machineDescriptionJson(edit)};
    message = "loaded " + loadPath + ": simulate to use it";
  } catch (const InputError& e) {
    message = e.what();
  }
}

std::optional<Machine> MachineWindow::checkedEdit() {
  try {
    return namedAfterEdits(parseMachine(machineDescriptionJson(edit), "machine window"), inUse);
  } catch (const InputError& e) {
    message = e.what();
    return std::nullopt;
  }
}

bool MachineWindow::apply() {
  const std::optional<Machine> m = checkedEdit();
  if (!m) return false;
  // Where the machine now in use comes from: as it was, the file it was loaded from unchanged,
  // or edits.
  const std::string description = machineDescriptionJson(*m);
  if (description != machineDescriptionJson(inUse))
    source = loaded && description == loaded->description ? loaded->path : "edited";
  inUse = *m;
  edit.name = inUse.name;
  message.clear();
  return true;
}

}  // namespace isurface::app_model
