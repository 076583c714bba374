# Precompiled headers: GiNaC (with CLN), fmt, nlohmann::json and the common standard headers are
# parsed by most translation units, ~4 s each under clang with the sanitizers and ~3.5 s under
# g++ -O2, in both CI builds. Parsing them once per target took the cold clang build from 995 s
# to 852 s (docs/fuzzing.md, "CI time"). LINKPROOF_PCH=OFF compiles without them (e.g. to check
# that each file includes what it uses).
option(LINKPROOF_PCH "Precompile the heavy third-party headers once per target" ON)

# linkproof_precompile_headers(target [extra headers...]): PRIVATE, so nothing reaches consumers
# of the installed library.
function(linkproof_precompile_headers target)
  if(NOT LINKPROOF_PCH)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE
    <algorithm> <functional> <map> <memory> <optional> <sstream> <string> <vector>
    <ginac/ginac.h> <fmt/format.h> <nlohmann/json.hpp> ${ARGN})
endfunction()
