#include "scenes/input_file.h"

#include <system_error>

#include "scenes/input_error.h"

namespace facet::scene {

namespace fs = std::filesystem;

void checkInputFile(const fs::path& path, const std::string& what) {
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
