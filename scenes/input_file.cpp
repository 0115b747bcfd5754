#include "scenes/input_file.h"

#include <algorithm>
#include <system_error>

#include "scenes/input_error.h"

namespace facet::scene {

namespace fs = std::filesystem;

namespace {
thread_local InputFileLog* openLog = nullptr;
}  // namespace

InputFileLog::InputFileLog() : outer_(openLog) { openLog = this; }

InputFileLog::~InputFileLog() { openLog = outer_; }

void noteInputFile(const fs::path& path) {
  for (InputFileLog* log = openLog; log; log = log->outer_)
    if (std::find(log->files_.begin(), log->files_.end(), path) == log->files_.end()) log->files_.push_back(path);
}

std::optional<std::string> inputFileProblem(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) return "no such file";
  if (fs::is_directory(status)) return "it is a folder, not a file";
  if (!fs::is_regular_file(status)) return "it is a FIFO, socket or device, not a regular file";
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) return error.message();
  if (size > kLargestInputFile)
    return "it is " + std::to_string(size) + " bytes, more than the " + std::to_string(kLargestInputFile) +
           " facet reads";
  return std::nullopt;
}

void checkInputFile(const fs::path& path, const std::string& what) {
  noteInputFile(path);
  if (const std::optional<std::string> problem = inputFileProblem(path))
    throw InputError(path.string(), 0, "cannot open " + what, *problem);
}

}  // namespace facet::scene
