# Warnings are set per target, never by editing global flags. A build prints no warning;
# LINKPROOF_WERROR=ON (CI: scripts/build.sh and scripts/run_sanitizer_tests.sh with CI set) makes
# any warning an error.
option(LINKPROOF_WERROR "Treat compiler warnings as errors" OFF)
function(linkproof_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wno-unused-parameter)
  if(LINKPROOF_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
