# What `cmake --install` puts under the prefix:
#   bin/facet
#   <libdir>/libfacet.so*                    the public API (include/facet/)
#   include/facet/*.h                        with the generated version.h
#   <libdir>/cmake/facet/facetConfig*.cmake  imported target facet::facet
#   <libdir>/pkgconfig/facet.pc
#   share/facet/scenes/                      examples, cages, environments
#   share/facet/tools/blender/               the Cycles comparison's script (facet bench)
#   <FACET_PYTHON_INSTALL_DIR>/facet*.so     the Python module
# Kernels are compiled into the code; nothing installed reads the source tree.
include(CMakePackageConfigHelpers)

set(FACET_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/facet)
set(FACET_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/facet)

install(TARGETS facet RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS facet_library facet_version EXPORT facetTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/facet ${PROJECT_BINARY_DIR}/include/facet
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT facetTargets NAMESPACE facet:: DESTINATION ${FACET_CMAKE_INSTALL_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/facetConfig.cmake.in
  ${PROJECT_BINARY_DIR}/facetConfig.cmake INSTALL_DESTINATION ${FACET_CMAKE_INSTALL_DIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/facetConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/facetConfig.cmake ${PROJECT_BINARY_DIR}/facetConfigVersion.cmake
  DESTINATION ${FACET_CMAKE_INSTALL_DIR})

# facet.pc finds its prefix from its own folder, so an install moved or made
# with `cmake --install --prefix` stays right.
file(RELATIVE_PATH FACET_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" FACET_PC_TO_PREFIX ${FACET_PC_TO_PREFIX})
configure_file(${CMAKE_CURRENT_LIST_DIR}/facet.pc.in ${PROJECT_BINARY_DIR}/facet.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/facet.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

foreach(folder examples cages environments)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/${folder} DESTINATION ${FACET_DATA_INSTALL_DIR}/scenes)
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/tools/blender/cycles_scene.py DESTINATION ${FACET_DATA_INSTALL_DIR}/tools/blender)

# The build tree's binary finds its data as an installed one does
# (apps/facet/data_folder.h): share/facet/scenes and tools/blender beside it.
file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/share/facet/tools)
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/scenes ${PROJECT_BINARY_DIR}/share/facet/scenes SYMBOLIC)
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/tools/blender ${PROJECT_BINARY_DIR}/share/facet/tools/blender SYMBOLIC)
