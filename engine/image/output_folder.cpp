#include "engine/image/output_folder.h"

#include <unistd.h>

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
