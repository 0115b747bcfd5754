// Chains of material files that extend each other (docs/shading.md,
// "Material files"): the input is cut at NUL bytes into files chain0.json,
// chain1.json, ... in one scratch folder, more of them than the deepest
// chain allowed, and chain0.json is loaded as `--material` loads it. A file
// may extend another by name, itself, or one that is missing; every
// rejection names a file and its rule.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/clean_rejection.h"
#include "fuzz/scratch_file.h"
#include "scenes/scene_file.h"

namespace {

// Past the deepest chain scene_json_materials.cpp allows (64), so that the
// bound itself is reached.
constexpr std::size_t kMostFiles = 80;

std::string chainFile(std::size_t i) { return "chain" + std::to_string(i) + ".json"; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::uint8_t* end = data + size;
  std::size_t files = 0;
  for (const std::uint8_t* piece = data; files < kMostFiles && (piece < end || files == 0); ++files) {
    const std::uint8_t* cut = std::find(piece, end, std::uint8_t(0));
    facet::fuzz::writeScratchFile(chainFile(files), piece, std::size_t(cut - piece));
    piece = cut == end ? end : cut + 1;
  }
  // What a longer input before wrote is gone: a name past this one's files is missing.
  for (std::size_t i = files; i < kMostFiles; ++i) std::filesystem::remove(facet::fuzz::scratchFolder() / chainFile(i));
  try {
    std::vector<facet::scene::Texture> textures;
    facet::scene::loadMaterialReference((facet::fuzz::scratchFolder() / chainFile(0)).string(), textures);
  } catch (const facet::scene::InputError& error) {
    facet::fuzz::checkCleanRejection(error);
  }
  return 0;
}
