// The files a process has read as inputs, so that no output replaces one of them.
#pragma once

#include <string>

namespace isurface {

// Notes the file open on `fd` (a regular file), read by the name `path`, as an input of this
// process. While inputs are protected, an input that is also this process's standard output
// (`canon p.nc >> p.nc`: what is printed would land in the program) throws InputError naming
// it, before anything is written.
void noteInputFile(int fd, const std::string& path);
// The same for a file read by name (a stream).
void noteInputFile(const std::string& path);

// The input that standard output is (a regular file noted as an input while inputs are
// protected), or an empty string: what a command prints must not be written into it.
std::string standardOutputInput();

// Whether outputs must not replace inputs (the command line: `simulate p.nc -o p.nc` is a
// slip of the hand). Off by default: the window may save a program over the one it opened.
void protectInputFiles(bool on);

// Whether inputs are protected and `path` names a file noted as an input (the same file by
// device and inode, whatever name or link it was read by). False when the path does not exist.
bool isProtectedInputFile(const std::string& path);

}  // namespace isurface
