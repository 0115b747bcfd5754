# <facet/version.h>: the project version for the library, its consumers and
# the binary, generated from project(VERSION) into the build tree.
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.h.in ${PROJECT_BINARY_DIR}/include/facet/version.h @ONLY)
add_library(facet_version INTERFACE)
target_include_directories(facet_version INTERFACE
  $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
