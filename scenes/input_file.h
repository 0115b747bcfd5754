// Only regular files are read as input (docs/reliability.md, "What is
// rejected"): a FIFO would block the read for ever, a device such as
// /dev/zero (or a link to one) would never end it, and a folder cannot be
// decoded. Checked before a loader opens the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace facet::scene {

// No input facet reads comes near this; a larger file is refused before it is read.
constexpr std::uintmax_t kLargestInputFile = std::uintmax_t(8) << 30;

// Why `path` cannot be read as input: "no such file", "it is a folder, not a
// file", ...; nothing when it is an existing regular file (links followed)
// of at most kLargestInputFile bytes.
std::optional<std::string> inputFileProblem(const std::filesystem::path& path);

// Throws InputError "<path>: cannot open <what>: <rule>" unless `path` is an
// existing regular file (links followed) of at most kLargestInputFile bytes.
// Notes `path` in the InputFileLog open on this thread first, so that a
// file that fails the check is among the files a load depends on too.
void checkInputFile(const std::filesystem::path& path, const std::string& what);

// The files the loaders check or open on this thread while it lives, each
// once, in the order first read: the files a scene depends on (its file,
// the material files it names or extends, cages, glTF buffers, images,
// environment maps), which `facet render --watch` watches. Logs nest: an
// inner log's files are noted in the outer one too.
class InputFileLog {
 public:
  InputFileLog();
  ~InputFileLog();
  InputFileLog(const InputFileLog&) = delete;
  InputFileLog& operator=(const InputFileLog&) = delete;

  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  friend void noteInputFile(const std::filesystem::path& path);
  InputFileLog* outer_;
  std::vector<std::filesystem::path> files_;
};

// Adds `path` to the open InputFileLog, if any: for a loader that opens a
// file without checkInputFile.
void noteInputFile(const std::filesystem::path& path);

}  // namespace facet::scene
