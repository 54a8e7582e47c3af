#pragma once
// Writes a command's output files so that nothing is half-written: files go to a staging
// folder inside DIR and are renamed into DIR only when the whole job has succeeded. An
// unwritable DIR is reported before any work is done.
//
// A run's own output folder (--out of evaluate, simulate, table, sweep, merge, bench) is also
// locked for the run (app/output_lock.h), and its rangesim files are listed in a manifest
// (app/output_manifest.h): the commit replaces the previous run's files, so no stale result of
// another run stays beside the new ones, and a folder holding another kind of run's results is
// refused without --force. Staging folders of runs whose process is gone are removed.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/output_manifest.h"

namespace rangesim::app {

class OutputLock;

// A single output file the user names (--trace, --junit): refused before any work when it exists
// as anything but a regular file (a directory, a device, a FIFO, a symbolic-link loop), which the
// rename at the end would otherwise fail on or, as root, replace. Throws UserError naming `flag`.
void check_output_file(const std::string& path, const std::string& flag);

// Staging folders (.staging-<pid>) of `dir` left by runs whose process is gone.
void remove_stale_staging(const std::string& dir);

// What a run's output folder is.
struct OutputFolder {
  std::string kind;    // the command ("evaluate"; merge writes a "sweep"); "" = the folder of a
                       // user-named file (--junit, --trace): no lock, no manifest
  bool force = false;  // --force: replace the results of another kind of run
  bool lock = true;    // false: an MPI rank other than 0 (rank 0 holds the lock and commits)
};

class OutputDir {
 public:
  // Creates DIR if needed, takes its lock, checks its manifest and makes a staging folder in it;
  // throws UserError naming `flag` and DIR.
  OutputDir(const std::string& dir, const std::string& flag, const OutputFolder& folder = {});
  // Removes the staging folder (and DIR, if this object created it and it is still empty)
  // unless commit() ran.
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  // Path of `name` inside the staging folder; the caller writes it there.
  std::string staged(const std::string& name);
  // Path of a scratch file in the staging folder: never moved into DIR (plot scripts, data).
  std::string scratch(const std::string& name) const;
  // Writes `text` to the staged file `name`.
  void write(const std::string& name, const std::string& text);
  // Moves every staged file into DIR (app/file_replace.h, same file system), removes the previous run's files
  // that this run did not write, and returns the final paths.
  std::vector<std::string> commit();

  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::string staging_;
  std::vector<std::string> names_;
  OutputFolder folder_;
  std::optional<OutputManifest> previous_;  // the manifest found in DIR
  std::unique_ptr<OutputLock> lock_;
  int dir_slot_ = -1, staging_slot_ = -1;  // app/run_control.h cleanup slots
  bool created_dir_ = false;
  bool committed_ = false;
};

}  // namespace rangesim::app
