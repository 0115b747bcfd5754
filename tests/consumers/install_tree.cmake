# cmake -P script: installs the build into a fresh PREFIX and checks that
# every part of the package is there and that the public headers name no
# header outside <facet/...> but the standard library's.
#   -DBUILD=dir -DPREFIX=dir -DLIBDIR=lib -DPYTHONDIR=lib/python3/dist-packages
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${err}")
endif()
foreach(path bin/facet ${LIBDIR}/libfacet.so include/facet/facet.h include/facet/version.h
             ${LIBDIR}/cmake/facet/facetConfig.cmake ${LIBDIR}/cmake/facet/facetConfigVersion.cmake
             ${LIBDIR}/pkgconfig/facet.pc share/facet/scenes/examples/preview.json
             share/facet/scenes/environments/sunrise.exr share/facet/scenes/cages/cube.obj
             share/facet/tools/blender/cycles_scene.py)
  if(NOT EXISTS ${PREFIX}/${path})
    message(FATAL_ERROR "the install has no ${path}")
  endif()
endforeach()
if(PYTHONDIR)
  file(GLOB module ${PREFIX}/${PYTHONDIR}/facet*.so)
  if(NOT module)
    message(FATAL_ERROR "the install has no Python module in ${PYTHONDIR}")
  endif()
endif()
file(GLOB headers ${PREFIX}/include/facet/*.h)
foreach(header ${headers})
  file(STRINGS ${header} includes REGEX "^#include")
  foreach(line ${includes})
    if(NOT line MATCHES "^#include (<[a-z_]+>|\"facet/[a-z_]+\\.h\")$")
      message(FATAL_ERROR "${header}: '${line}' is neither the standard library's nor <facet/...>")
    endif()
  endforeach()
endforeach()
message(STATUS "installed into ${PREFIX}")
