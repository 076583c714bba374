# The installed-package test: installs this build tree into a temporary prefix and builds and
# runs tests/consumer against it through find_package(linkproof). Included from tests/CMakeLists.txt.
add_test(NAME package.consumer_find_package
         COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/test_consumer.sh ${PROJECT_BINARY_DIR})
set_tests_properties(package.consumer_find_package PROPERTIES
  LABELS "slow;package"
  TIMEOUT 900)

# Every installed header compiles on its own with only include/ on the path (no private header
# of src/ reachable): one translation unit per header, built with the unit tests.
file(GLOB_RECURSE LINKPROOF_PUBLIC_HEADERS CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/include
     ${PROJECT_SOURCE_DIR}/include/linkproof/*.h)
set(LINKPROOF_PUBLIC_HEADER_UNITS)
foreach(header IN LISTS LINKPROOF_PUBLIC_HEADERS)
  string(MAKE_C_IDENTIFIER ${header} unit)
  set(unit_file ${CMAKE_CURRENT_BINARY_DIR}/public_headers/${unit}.cpp)
  file(CONFIGURE OUTPUT ${unit_file} CONTENT "#include \"${header}\"\n#include \"${header}\"  // and twice\n")
  list(APPEND LINKPROOF_PUBLIC_HEADER_UNITS ${unit_file})
endforeach()
add_library(linkproof_public_headers OBJECT ${LINKPROOF_PUBLIC_HEADER_UNITS})
target_compile_features(linkproof_public_headers PRIVATE cxx_std_20)
# Only include/ and the dependencies' own headers: not linkproof::linkproof, whose build
# interface also carries src/.
target_include_directories(linkproof_public_headers PRIVATE ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(linkproof_public_headers PRIVATE PkgConfig::GINAC rapidcheck GTest::gmock)
linkproof_set_warnings(linkproof_public_headers)
add_dependencies(linkproof_unit_tests linkproof_public_headers)
