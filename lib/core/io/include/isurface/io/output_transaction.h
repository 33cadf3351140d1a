// A command's output files, published all together or not at all.
#pragma once

#include <memory>
#include <string>

namespace isurface {

// While a transaction is open, AtomicOutputFile::commit() writes, syncs and closes its
// temporary file but leaves the rename to publish(): a command that writes a program, a report
// and three images either leaves all of them or (an error, an exception, a signal) none, and
// the files it would have replaced stay as they were. One transaction at a time, per process.
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();  // removes every temporary file not yet published
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Renames every output into place, in the order they were committed. Throws InputError
  // naming the output that could not be renamed; the ones not yet renamed are removed.
  void publish();

  struct Pending;  // the outputs committed and not yet published

 private:
  std::unique_ptr<Pending> pending_;
};

namespace detail {
// Hands a committed temporary file to the open transaction. False when none is open (the
// caller renames it itself). Throws InputError when another output of the transaction has the
// same destination (the same file by its resolved path, or by device and inode).
bool deferRename(const std::string& temporary, const std::string& destination, const std::string& target);
}  // namespace detail

}  // namespace isurface
