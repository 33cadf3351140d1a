// Temporary outputs that a signal ending the process must not leave behind.
#pragma once

namespace isurface::detail {

// Remembers a temporary file to remove if SIGINT, SIGTERM, SIGHUP or SIGQUIT ends the process
// (the signal's default action then follows, as without this). `path` must stay valid and
// unchanged until forgotten. Returns a slot for forgetTemporary(), or -1 when every slot is
// taken (the file is then not removed on a signal).
int rememberTemporary(const char* path);
void forgetTemporary(int slot);

}  // namespace isurface::detail
