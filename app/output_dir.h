#pragma once
// Writes a command's output files so that nothing is half-written: files go to a staging
// folder inside DIR and are renamed into DIR only when the whole job has succeeded. An
// unwritable DIR is reported before any work is done.
#include <string>
#include <vector>

namespace rangesim::app {

// A single output file the user names (--trace, --junit): refused before any work when it exists
// as anything but a regular file (a directory, a device, a FIFO, a symbolic-link loop), which the
// rename at the end would otherwise fail on or, as root, replace. Throws UserError naming `flag`.
void check_output_file(const std::string& path, const std::string& flag);

class OutputDir {
 public:
  // Creates DIR if needed and a staging folder in it; throws UserError naming `flag` and DIR.
  OutputDir(const std::string& dir, const std::string& flag);
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
  // Moves every staged file into DIR (rename, same file system) and returns their final paths.
  std::vector<std::string> commit();

  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::string staging_;
  std::vector<std::string> names_;
  bool created_dir_ = false;
  bool committed_ = false;
};

}  // namespace rangesim::app
