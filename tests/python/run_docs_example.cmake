# cmake -P script: runs the ```python block of docs/api.md.
#   -DPYTHON=/usr/bin/python3 -DDOC=docs/api.md -DWORK=dir
include(${CMAKE_CURRENT_LIST_DIR}/../support/doc_block.cmake)
facet_doc_block(python ${DOC} example)
file(WRITE ${WORK}/docs_example.py "${example}")
# The example's own temporary folder goes under WORK, emptied each run.
file(REMOVE_RECURSE ${WORK}/tmp)
file(MAKE_DIRECTORY ${WORK}/tmp)
execute_process(COMMAND ${CMAKE_COMMAND} -E env TMPDIR=${WORK}/tmp ${PYTHON} ${WORK}/docs_example.py
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "docs/api.md's Python example failed (${rc}):\n${out}${err}")
endif()
message("${out}")
