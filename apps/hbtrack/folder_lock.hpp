#pragma once
// Ownership of a result folder: the run writing DIR holds a lock on DIR/.hbtrack.lock (holding
// its pid, for messages) until it ends. The kernel drops the lock when the process dies, so a
// killed run leaves no stale lock, while a live one (an orphaned sweep task whose parent was
// killed) keeps its folder: a second run refuses it instead of writing the same files.
#include <string>

namespace hbtrack::cli {

// Locks DIR (which must exist) for the rest of this process; a second call for DIR is a no-op.
// Throws CaseError "-o: DIR is being written by another hbtrack run (pid N) ..." when held.
void lock_result_folder(const std::string& dir);

// The pid written by the live run holding DIR's lock, -1 when it is held but the pid is
// unreadable, 0 when no run holds it.
long result_folder_owner(const std::string& dir);

}  // namespace hbtrack::cli
