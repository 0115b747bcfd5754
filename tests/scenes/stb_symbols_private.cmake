# Fails when any of FILES exports a dynamic symbol of stb_image (the
# decoder): shared libraries that link Debian's full stb_image, tinygltf
# among them, would bind to it. stb_image_write's symbols (stbi_write_*,
# stbi_zlib_compress, stbi_flip_vertically_on_write) are compiled in full
# and may bind either way.
foreach(file ${FILES})
  execute_process(COMMAND nm -D --defined-only ${file} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "nm -D failed on ${file}")
  endif()
  string(REGEX MATCHALL "[^\n]* stbi_[^\n]*" exported "${symbols}")
  list(FILTER exported EXCLUDE REGEX " stbi_(write_|zlib_compress$|flip_vertically_on_write$)")
  if(exported)
    message(FATAL_ERROR "${file} exports stb_image symbols: ${exported}")
  endif()
endforeach()
