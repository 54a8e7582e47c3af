#pragma once
// One writer per output folder: a run holds DIR/.rangesim.lock (an flock, released by the kernel
// however the process ends, so a killed run leaves no stale lock) with its pid, start time and
// command in it. A second run into the same folder, a --resume of a sweep still running
// included, is refused naming the holder.
#include <string>

namespace rangesim::app {

class OutputLock {
 public:
  // Takes the lock of `dir` (an existing folder); throws UserError naming `flag`, the folder and
  // the holder when another process holds it.
  OutputLock(const std::string& dir, const std::string& flag);
  ~OutputLock();  // removes the lock file, then releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  int cleanup_slot_ = -1;  // app/run_control.h: the file goes when the run is ended by a signal
};

}  // namespace rangesim::app
