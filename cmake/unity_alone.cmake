# Unity builds: the sources of oasis_core and of the test programs compiled in batches of 16, as
# the web build compiles the page. Most of a source's compile time is the shared headers (GLM,
# epoxy, gtest), so a batch costs little more than one file: CI builds two trees from scratch
# (docs/tests.md gives the times). -DOASIS_UNITY=OFF compiles each source alone (an edit then
# recompiles one file, not its batch).
option(OASIS_UNITY "Compile oasis_core and the test programs in unity batches" ON)
set(OASIS_UNITY_BATCH 16 CACHE STRING "sources per unity batch")

# The sources compiled on their own where the rest goes in unity batches: their file-local names
# (anonymous namespaces, statics) are also another source's, which one translation unit cannot hold
# twice.
set(OASIS_UNITY_ALONE pixel_probe file_output gbuffer_layout png_text svg_plot)

# Puts TARGET's sources in unity batches (when OASIS_UNITY is on), leaving out those named by
# OASIS_UNITY_ALONE and any further base names given after it.
function(oasis_unity_build target)
  if(NOT OASIS_UNITY)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${OASIS_UNITY_BATCH})
  get_target_property(sources ${target} SOURCES)
  foreach(source IN LISTS sources)
    get_filename_component(name ${source} NAME_WE)
    if(name IN_LIST OASIS_UNITY_ALONE OR name IN_LIST ARGN)
      set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
  endforeach()
endfunction()
