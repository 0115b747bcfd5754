// A folder of outputs written all or nothing (docs/reliability.md,
// "Outputs"): a command that writes many files (`bench`, `ibl-chart`) writes
// them into a staging folder inside its destination and moves them into
// place only when it has written every one, so a failure or a full disk
// leaves the destination as it was.
#pragma once

#include <filesystem>
#include <string>

namespace facet {

class StagedOutputFolder {
 public:
  // Creates `destination` if need be, and the staging folder in it; removes
  // the staging folders of runs that were killed.
  explicit StagedOutputFolder(const std::filesystem::path& destination);
  // Removes the staging folder with whatever it still holds.
  ~StagedOutputFolder();
  StagedOutputFolder(const StagedOutputFolder&) = delete;
  StagedOutputFolder& operator=(const StagedOutputFolder&) = delete;

  // Where the command writes, laid out as the destination will be.
  const std::filesystem::path& path() const { return staging_; }
  // Moves every file of the staging folder to the same place under the
  // destination, replacing what is there, with the signals that end a
  // command held back (image_io.h's SignalsHeld).
  void publish();

 private:
  std::filesystem::path destination_, staging_;
};

// A folder of its own in the temporary folder (TMPDIR, else /tmp) for a
// command's intermediate files (a turntable's frames, gnuplot's script and
// data): removed with whatever it holds when the command ends, and where a
// killed run left one of the same kind, by the next run that makes one.
class ScratchFolder {
 public:
  // Throws OutputError "<flag>: cannot make a folder for <what> in the
  // temporary folder '<folder>' (TMPDIR): <reason>; ..." where the temporary
  // folder is missing, not a folder or not writable: checked before the
  // work that fills it.
  ScratchFolder(const std::string& flag, const std::string& what, const std::string& kind);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace facet
