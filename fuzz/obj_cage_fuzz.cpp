// OBJ control cages, parsed from memory.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/clean_rejection.h"
#include "scenes/obj_cage.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    facet::scene::parseObjCage(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj");
  } catch (const facet::scene::InputError& error) {
    facet::fuzz::checkCleanRejection(error);
  }
  return 0;
}
