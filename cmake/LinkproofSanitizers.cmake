# Sanitizer and fuzzing builds (docs/fuzzing.md). Instrumentation must cover every linkproof
# object, so these options add directory-wide compile and link options (only when switched on).
#   LINKPROOF_SANITIZE  ASan + UBSan (any error aborts: -fno-sanitize-recover), e.g. a Debug
#                       build of the unit tests in CI (scripts/run_sanitizer_tests.sh);
#   LINKPROOF_FUZZ      the same plus libFuzzer coverage (clang only) and the targets of tests/fuzz.
if(LINKPROOF_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "LINKPROOF_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(LINKPROOF_SANITIZE ON)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
if(LINKPROOF_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
  # The ASan defaults (no leak checking, cmake/sanitizer_defaults.cpp) in every executable; not
  # part of the installed package's interface.
  add_library(linkproof_sanitizer_defaults OBJECT ${CMAKE_CURRENT_LIST_DIR}/sanitizer_defaults.cpp)
  link_libraries("$<BUILD_INTERFACE:$<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:linkproof_sanitizer_defaults>>")
endif()
