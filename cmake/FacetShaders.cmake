# facet_add_spirv_library(<target> NAMESPACE <ns> SOURCES <file.comp>...)
#
# Compiles each GLSL compute shader to SPIR-V with glslangValidator, checks it
# with spirv-val, and embeds it in a static library as
#   const std::span<const std::uint32_t> <ns>::<stem>
# declared in the generated header <target>/spirv.h. Shaders may #include any
# header below the source root; the depfile makes an edit to one of them
# rebuild exactly the shaders that include it.
include(FacetEmbed)

function(facet_add_spirv_library target)
  cmake_parse_arguments(ARG "" "NAMESPACE" "SOURCES" ${ARGN})
  set(spirv_dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_spirv)
  file(MAKE_DIRECTORY ${spirv_dir})
  set(modules "")
  foreach(src ${ARG_SOURCES})
    get_filename_component(src_abs ${src} ABSOLUTE)
    get_filename_component(stem ${src} NAME_WE)
    set(spv ${spirv_dir}/${stem}.spv)
    add_custom_command(
      OUTPUT ${spv}
      COMMAND Vulkan::glslangValidator -V --target-env vulkan1.2 --quiet
              -I${PROJECT_SOURCE_DIR} --depfile ${spv}.d -o ${spv} ${src_abs}
      COMMAND ${FACET_SPIRV_VAL} --target-env vulkan1.2 ${spv}
      DEPENDS ${src_abs}
      DEPFILE ${spv}.d
      COMMENT "GLSL -> SPIR-V ${stem}"
      VERBATIM)
    list(APPEND modules ${spv})
  endforeach()
  facet_embed_files(${target} NAMESPACE ${ARG_NAMESPACE} HEADER spirv.h WORDS FILES ${modules})
endfunction()
