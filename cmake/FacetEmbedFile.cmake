# cmake -P helper: writes a file as a C++ array, of 32-bit words when WORDS
# is set (a SPIR-V module, little-endian on disk) and of bytes otherwise.
file(READ ${INPUT} hex HEX)
string(LENGTH "${hex}" n)
if(WORDS)
  math(EXPR rem "${n} % 8")
  if(n EQUAL 0 OR NOT rem EQUAL 0)
    message(FATAL_ERROR "${INPUT}: not a SPIR-V module (size is not a whole number of words)")
  endif()
  string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u,\n" values "${hex}")
  set(type "std::uint32_t")
else()
  if(n EQUAL 0)
    message(FATAL_ERROR "${INPUT}: an empty file has nothing to embed")
  endif()
  string(REGEX REPLACE "(................................)" "\\1\n" lines "${hex}")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," values "${lines}")
  set(type "unsigned char")
endif()
file(WRITE ${OUTPUT}.tmp
"#include <cstdint>
#include <span>
namespace ${NAMESPACE} {
static const ${type} ${SYMBOL}_values[] = {
${values}};
extern const std::span<const ${type}> ${SYMBOL}(${SYMBOL}_values);
}
")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
