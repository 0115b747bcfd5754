// Material files (docs/shading.md), which reject bad input with
// std::invalid_argument naming the file and the field.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "fuzz/scratch_file.h"
#include "materials/material.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = facet::fuzz::writeScratchFile("fuzz_material.json", data, size);
  try {
    facet::materials::loadMaterial(path);
  } catch (const std::invalid_argument& error) {
    if (!std::string_view(error.what()).starts_with(path.string())) std::abort();
  }
  return 0;
}
