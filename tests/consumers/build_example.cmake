# cmake -P script: builds the C++ example of docs/api.md (its first ```cpp
# block) against the install in PREFIX, runs it (it fails on a wrong image)
# and checks that the library it ran is of this VERSION.
#   -DCONSUMER=cmake|pkg-config -DPREFIX=dir -DLIBDIR=lib -DDOC=docs/api.md
#   -DPROJECT=cmake_project -DWORK=dir -DCXX=compiler -DGENERATOR=Ninja -DVERSION=x.y.z
#   [-DLINK_FLAGS=flags]  what the program's link needs besides the package
include(${CMAKE_CURRENT_LIST_DIR}/../support/doc_block.cmake)
facet_doc_block(cpp ${DOC} example)
file(REMOVE_RECURSE ${WORK})
file(WRITE ${WORK}/cube.cpp "${example}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${rc}):\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

if(CONSUMER STREQUAL "cmake")
  run(${CMAKE_COMMAND} -S ${PROJECT} -B ${WORK}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
      -DCMAKE_CXX_COMPILER=${CXX} "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}" -DCMAKE_PREFIX_PATH=${PREFIX} -DEXAMPLE=${WORK}/cube.cpp)
  run(${CMAKE_COMMAND} --build ${WORK}/build)
  set(program ${WORK}/build/cube)
else()
  set(ENV{PKG_CONFIG_PATH} ${PREFIX}/${LIBDIR}/pkgconfig)
  run(pkg-config --cflags --libs facet)
  separate_arguments(flags UNIX_COMMAND "${out}")
  run(pkg-config --variable=libdir facet)
  string(STRIP "${out}" libdir)
  separate_arguments(link_flags UNIX_COMMAND "${LINK_FLAGS}")
  run(${CXX} -std=c++17 -O1 ${WORK}/cube.cpp ${flags} ${link_flags} -Wl,-rpath,${libdir} -o ${WORK}/cube)
  set(program ${WORK}/cube)
endif()
run(${program})
message("${out}")
if(NOT out MATCHES "^facet ${VERSION} on ")
  message(FATAL_ERROR "the example ran a library that is not facet ${VERSION}")
endif()
