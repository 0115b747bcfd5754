# The Embree 3 peer (analysis/peers/embree_peer.h), shared by `facet bench`
# and raycast_bench. Without Embree (Debian libembree-dev) there is no
# facet_embree_peer target and both leave the peer out.
include_guard(GLOBAL)
find_package(embree 3 QUIET)
if(embree_FOUND)
  add_library(facet_embree_peer STATIC ${CMAKE_CURRENT_LIST_DIR}/embree_peer.cpp)
  target_include_directories(facet_embree_peer PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(facet_embree_peer PUBLIC facet_scenes facet_camera PRIVATE facet_options embree Threads::Threads)
else()
  message(STATUS "Embree 3 not found: raycast_bench and facet bench are built without the Embree peer")
endif()

# Links `target` to the peer when there is one; FACET_HAVE_EMBREE says which.
function(facet_use_embree_peer target)
  if(TARGET facet_embree_peer)
    target_link_libraries(${target} PRIVATE facet_embree_peer)
    target_compile_definitions(${target} PRIVATE FACET_HAVE_EMBREE=1)
  else()
    target_compile_definitions(${target} PRIVATE FACET_HAVE_EMBREE=0)
  endif()
endfunction()
