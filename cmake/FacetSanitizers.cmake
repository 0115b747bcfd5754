# The sanitized build that CI runs beside the normal one (docs/reliability.md,
# "The sanitized suite"): clang, AddressSanitizer (LeakSanitizer included) and
# UndefinedBehaviorSanitizer on everything built here, the first report fatal.
option(FACET_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer (clang)" OFF)
# The libFuzzer harnesses of fuzz/, beside their replay drivers. They need
# FACET_SANITIZE: its runtime also serves the coverage hooks that the
# loaders, instrumented for the fuzzer, call from every binary that links them.
option(FACET_FUZZ "Build the libFuzzer harnesses (clang, with FACET_SANITIZE)" OFF)

if((FACET_SANITIZE OR FACET_FUZZ) AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "FACET_SANITIZE and FACET_FUZZ need clang: -DCMAKE_CXX_COMPILER=clang++")
endif()
if(FACET_FUZZ AND NOT FACET_SANITIZE)
  message(FATAL_ERROR "FACET_FUZZ needs FACET_SANITIZE=ON")
endif()
if(FACET_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fsanitize=float-cast-overflow -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # At -O1 clang leaves glm's small vector functions out of line, and each
  # call then pays the sanitizers' checks on its arguments: forced inline, the
  # CPU reference (double glm throughout) runs several times faster, and so
  # does the sanitized suite. The math is unchanged (-ffp-contract=off holds).
  add_compile_definitions(GLM_FORCE_INLINE)
endif()
