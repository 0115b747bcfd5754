# Warnings for facet's own code; third-party headers come in as SYSTEM includes.
# -ffp-contract=off: lavapipe does not fuse a*b+c, so neither does the CPU side
# (see platform notes); parity then compares like with like.
#
# -Wno-missing-field-initializers: descriptors (ours, WebGPU-style, and
# Vulkan's `VkFoo foo{VK_STRUCTURE_TYPE_FOO}`) are meant to be brace-initialised
# in part, every other member taking its default.
add_library(facet_options INTERFACE)
target_compile_options(facet_options INTERFACE
  -Wall -Wextra -Wpedantic -Wno-missing-field-initializers -ffp-contract=off)
