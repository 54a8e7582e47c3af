#pragma once
// Writes a command's output files so that nothing is half-written: each file is staged in DIR
// under a hidden name (.staging-<pid>.NAME; OutputFolder::same_names: .staging-<pid>/NAME) and
// moved over NAME only when the whole job has succeeded. Scratch files (plot scripts and data,
// never moved) go to the staging folder (.staging-<pid>), made when the first is asked for. An
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

// Staged files and staging folders (.staging-<pid>.NAME, .staging-<pid>) of `dir` left by runs
// whose process is gone.
void remove_stale_staging(const std::string& dir);

// What a run's output folder is.
struct OutputFolder {
  std::string kind;    // the command ("evaluate"; merge writes a "sweep"); "" = the folder of a
                       // user-named file (--junit, --trace): no lock, no manifest
  bool force = false;  // --force: replace the results of another kind of run
  bool lock = true;    // false: an MPI rank other than 0 (rank 0 holds the lock and commits)
  // Stage each file under its own name in the staging folder, not beside it under a hidden one:
  // for files that name each other (a trace and its GTKWave save file, app/cmd_cosim.cpp).
  bool same_names = false;
};

class OutputDir {
 public:
  // Creates DIR if needed, takes its lock and checks its manifest; throws UserError naming `flag`
  // and DIR.
  OutputDir(const std::string& dir, const std::string& flag, const OutputFolder& folder = {});
  // Removes the staged files and the staging folder (and DIR, if this object created it and it is
  // still empty) unless commit() ran.
  ~OutputDir();
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  // The staged path of `name` (DIR/.staging-<pid>.NAME, or DIR/.staging-<pid>/NAME); the caller
  // writes it there.
  std::string staged(const std::string& name);
  // Path of a scratch file in the staging folder, which this makes: never moved into DIR (plot
  // scripts, data). Throws UserError when the folder cannot be made.
  std::string scratch(const std::string& name);
  // Writes `text` to the staged file `name`.
  void write(const std::string& name, const std::string& text);
  // Moves every staged file into DIR (app/file_replace.h, same file system), removes the previous run's files
  // that this run did not write, and returns the final paths.
  std::vector<std::string> commit();

  const std::string& dir() const { return dir_; }

 private:
  // Makes the staging folder (once); throws UserError naming it.
  void make_staging();
  // Every staged file and anything else named .staging-<pid>.* in DIR (a tool's companion files).
  void remove_staged() const;

  std::string dir_;
  std::string prefix_;   // staged files are prefix_ + NAME: DIR/.staging-<pid>. (or <pid>/)
  std::string staging_;  // DIR/.staging-<pid> : the scratch folder, once scratch() made it
  std::vector<std::string> names_;
  OutputFolder folder_;
  std::optional<OutputManifest> previous_;  // the manifest found in DIR
  std::unique_ptr<OutputLock> lock_;
  int dir_slot_ = -1, prefix_slot_ = -1, staging_slot_ = -1;  // app/run_control.h cleanup slots
  bool made_staging_ = false;
  bool created_dir_ = false;
  bool committed_ = false;
};

}  // namespace rangesim::app
