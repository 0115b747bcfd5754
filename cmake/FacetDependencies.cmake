# Every dependency is a Debian 12 package (tools/packages.txt).
find_package(Threads REQUIRED)
find_package(Vulkan REQUIRED COMPONENTS glslangValidator)
find_program(FACET_SPIRV_VAL spirv-val REQUIRED)
# The optimizer folds a pipeline's constants into its kernel (engine/gpu/spirv_specialize.h).
find_package(SPIRV-Tools-opt REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(CLI11 QUIET CONFIG)
find_package(TinyGLTF REQUIRED)
find_package(OpenEXR REQUIRED)
if(BUILD_TESTING)
  find_package(GTest REQUIRED)
endif()
if(FACET_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
if(FACET_BUILD_PYTHON)
  # Debian's interpreter: the one python3-numpy is installed for.
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the facet module is built and tested for")
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 CONFIG REQUIRED)
endif()

if(NOT TARGET CLI11::CLI11)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${CLI11_INCLUDE_DIR})
endif()

find_path(STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)
add_library(facet::stb INTERFACE IMPORTED)
target_include_directories(facet::stb SYSTEM INTERFACE ${STB_INCLUDE_DIR})

# OpenSubdiv's own CMake config on Debian 12 names a static libosdCPU.a that
# the package does not ship, so we wrap the shared library ourselves.
find_library(OSD_CPU_LIBRARY osdCPU REQUIRED)
find_path(OSD_INCLUDE_DIR opensubdiv/far/topologyRefiner.h REQUIRED)
add_library(OpenSubdiv::osdCPU SHARED IMPORTED)
set_target_properties(OpenSubdiv::osdCPU PROPERTIES
  IMPORTED_LOCATION ${OSD_CPU_LIBRARY}
  INTERFACE_INCLUDE_DIRECTORIES ${OSD_INCLUDE_DIR})
