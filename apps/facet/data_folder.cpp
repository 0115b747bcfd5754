#include "data_folder.h"

#include <stdexcept>
#include <system_error>

namespace facet::cli {

std::filesystem::path dataFolder() {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path binary = fs::read_symlink("/proc/self/exe", error);
  if (error) throw std::invalid_argument("cannot find the facet binary's folder (/proc/self/exe): " + error.message());
  const fs::path installed = (binary.parent_path() / FACET_DATA_FROM_BINARY).lexically_normal();
  const fs::path buildTree = binary.parent_path() / "share" / "facet";
  for (const fs::path& folder : {installed, buildTree})
    if (fs::is_directory(folder / "scenes", error)) return folder;
  throw std::invalid_argument("no scenes/ in " + installed.string() + " or " + buildTree.string() +
                              ": name the files or the folder on the command line");
}

}  // namespace facet::cli
