// glTF 2.0 scenes: an input that starts with the binary container's magic
// is loaded as .glb, any other as .gltf.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz/clean_rejection.h"
#include "fuzz/scratch_file.h"
#include "scenes/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  try {
    facet::scene::loadScene(facet::fuzz::writeScratchFile(binary ? "fuzz.glb" : "fuzz.gltf", data, size));
  } catch (const facet::scene::InputError& error) {
    facet::fuzz::checkCleanRejection(error);
  }
  return 0;
}
