# Fails when any of FILES exports a dynamic symbol of stb_image or
# stb_image_write: shared libraries that link Debian's stb, tinygltf among
# them, would bind to facet's copies.
foreach(file ${FILES})
  execute_process(COMMAND nm -D --defined-only ${file} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "nm -D failed on ${file}")
  endif()
  string(REGEX MATCHALL "[^\n]* stbi_[^\n]*" exported "${symbols}")
  if(exported)
    message(FATAL_ERROR "${file} exports stb_image symbols: ${exported}")
  endif()
endforeach()
