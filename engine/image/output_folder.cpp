#include "engine/image/output_folder.h"

#include <unistd.h>

#include <cstdlib>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include "engine/image/image_io.h"

namespace facet {

namespace fs = std::filesystem;

namespace {

const std::string kStagingPrefix = ".facet-staging-";

}  // namespace

StagedOutputFolder::StagedOutputFolder(const fs::path& destination) : destination_(destination) {
  std::error_code error;
  fs::create_directories(destination_, error);
  if (!fs::is_directory(destination_))
    throw OutputError(destination_.string() + ": cannot make the output folder" +
                      (error ? ": " + error.message() : std::string()));
  removeLeftoversOfEndedProcesses(destination_, kStagingPrefix);  // staging of killed runs
  staging_ = destination_ / (kStagingPrefix + std::to_string(::getpid()));
  fs::remove_all(staging_, error);
  if (!fs::create_directory(staging_, error))
    throw OutputError(destination_.string() + ": cannot write in the output folder: " + error.message());
}

namespace {

// The folder std::filesystem::temp_directory_path names (libstdc++ reads
// these variables in this order), for an error that says which it was.
std::string temporaryFolderName() {
  for (const char* variable : {"TMPDIR", "TMP", "TEMP", "TEMPDIR"})
    if (const char* value = std::getenv(variable); value && *value) return value;
  return "/tmp";
}

}  // namespace

ScratchFolder::ScratchFolder(const std::string& flag, const std::string& what, const std::string& kind) {
  std::error_code error;
  const fs::path temporary = fs::temp_directory_path(error);
  if (!error) {
    const std::string prefix = "facet-" + kind + "-";
    removeLeftoversOfEndedProcesses(temporary, prefix);
    std::random_device entropy;
    path_ = temporary / (prefix + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
    fs::create_directory(path_, error);
  }
  if (!error) return;
  const std::string folder = temporaryFolderName();
  const fs::file_status status = fs::status(folder);
  const std::string reason = !fs::exists(status)         ? "no such folder"
                             : !fs::is_directory(status) ? "it is not a folder"
                                                         : error.message();
  path_.clear();
  throw OutputError(flag + ": cannot make a folder for " + what + " in the temporary folder '" + folder +
                    "' (TMPDIR): " + reason + "; set TMPDIR to a writable folder");
}

ScratchFolder::~ScratchFolder() {
  if (path_.empty()) return;
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

StagedOutputFolder::~StagedOutputFolder() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedOutputFolder::publish() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(staging_))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), staging_));
  const SignalsHeld held;
  for (const fs::path& file : files) {
    std::error_code error;
    fs::create_directories((destination_ / file).parent_path(), error);
    fs::rename(staging_ / file, destination_ / file, error);
    if (error)
      throw OutputError((destination_ / file).string() +
                        ": cannot move the written file into place: " + error.message());
  }
}

}  // namespace facet
