# Unity builds for CI: LINKPROOF_UNITY=ON compiles the project's own targets (the library, the
# CLI library, the catalogue, linkproof::testing, the test executables, the benchmarks) as
# batches of LINKPROOF_UNITY_BATCH_SIZE sources per translation unit, so the headers and the
# shared template instantiations are compiled once per batch instead of once per file. Off by
# default: an edit then rebuilds one file, not its whole batch. Not batched: the single-source
# executables (linkproof, linkproof_mpi, the fuzz targets) and linkproof_public_headers, whose
# point is to compile each installed header on its own. scripts/build.sh and
# scripts/run_sanitizer_tests.sh turn it on when CI is set (two cold builds per run; figures in
# docs/fuzzing.md, "CI time").
#
# A batch is one translation unit, so file-local names (anonymous namespaces, `static`
# functions and constants, file-scope using-declarations, macros) must not collide between the
# sources of a target: give file-local helpers specific names. Where that is awkward, a file can
# stay out of the batches with the source property SKIP_UNITY_BUILD_INCLUSION.
option(LINKPROOF_UNITY "Unity (jumbo) build of the project's targets, for cold builds such as CI's" OFF)
set(LINKPROOF_UNITY_BATCH_SIZE 8 CACHE STRING "Sources per unity translation unit (LINKPROOF_UNITY)")

# linkproof_unity_build(target): batch the target's sources when LINKPROOF_UNITY is on.
function(linkproof_unity_build target)
  if(NOT LINKPROOF_UNITY)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${LINKPROOF_UNITY_BATCH_SIZE})
endfunction()
