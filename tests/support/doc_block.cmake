# facet_doc_block(<language> <file.md> <variable>): the first fenced block
# of <language> in a Markdown file, so that a test runs exactly what the
# docs show.
function(facet_doc_block language file variable)
  file(READ ${file} text)
  if(NOT text MATCHES "```${language}\n(.*)")
    message(FATAL_ERROR "${file}: no ```${language} block")
  endif()
  string(FIND "${CMAKE_MATCH_1}" "```" end)
  string(SUBSTRING "${CMAKE_MATCH_1}" 0 ${end} block)
  set(${variable} "${block}" PARENT_SCOPE)
endfunction()
