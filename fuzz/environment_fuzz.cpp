// Environment maps: an input that starts with OpenEXR's magic number is
// loaded as .exr, any other as Radiance .hdr.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz/clean_rejection.h"
#include "fuzz/scratch_file.h"
#include "scenes/environment_map.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const unsigned char exrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  const bool exr = size >= 4 && std::memcmp(data, exrMagic, 4) == 0;
  try {
    facet::scene::loadEnvironmentMap(facet::fuzz::writeScratchFile(exr ? "fuzz.exr" : "fuzz.hdr", data, size));
  } catch (const facet::scene::InputError& error) {
    facet::fuzz::checkCleanRejection(error);
  }
  return 0;
}
