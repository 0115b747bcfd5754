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

void checkInputFile(const fs::path& path, const std::string& what) {
  noteInputFile(path);
  const auto refuse = [&](const std::string& rule) { throw InputError(path.string(), 0, "cannot open " + what, rule); };
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) refuse("no such file");
  if (fs::is_directory(status)) refuse("it is a folder, not a file");
  if (!fs::is_regular_file(status)) refuse("it is a FIFO, socket or device, not a regular file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) refuse(error.message());
  if (size > kLargestInputFile)
    refuse("it is " + std::to_string(size) + " bytes, more than the " + std::to_string(kLargestInputFile) +
           " facet reads");
}

}  // namespace facet::scene
