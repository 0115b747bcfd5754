# cmake -P helper: writes a SPIR-V binary as a C++ array of 32-bit words.
file(READ ${INPUT} hex HEX)
string(LENGTH "${hex}" n)
math(EXPR rem "${n} % 8")
if(n EQUAL 0 OR NOT rem EQUAL 0)
  message(FATAL_ERROR "${INPUT}: not a SPIR-V module (size is not a whole number of words)")
endif()
# SPIR-V words are little-endian on disk.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u,\n" words "${hex}")
file(WRITE ${OUTPUT}.tmp
"#include <cstdint>
#include <span>
namespace ${NAMESPACE} {
static const std::uint32_t ${SYMBOL}_words[] = {
${words}};
extern const std::span<const std::uint32_t> ${SYMBOL}(${SYMBOL}_words);
}
")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
