cmake_minimum_required(VERSION 3.25)
# cmake -P script: `facet bench --sections cycles` where no Blender can be
# found (PATH without it, FACET_BLENDER unset) prints the skip note, says so
# in report.md and still succeeds.
#   -DCOMMAND="facet;bench;--quick;--sections;cycles;-o;DIR;--root;SRC" -DDIR=path
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}/empty_path")
set(ENV{PATH} "${DIR}/empty_path")
unset(ENV{FACET_BLENDER})
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench failed (exit ${rc}):\n${out}${err}")
endif()
if(NOT out MATCHES "cycles: skipped: blender is not on PATH and FACET_BLENDER is unset")
  message(FATAL_ERROR "no skip note in the output:\n${out}")
endif()
file(READ "${DIR}/report.md" report)
if(NOT report MATCHES "## Cycles: the material preview\n+Skipped: blender is not on PATH")
  message(FATAL_ERROR "report.md does not say the Cycles section was skipped:\n${report}")
endif()
