# The installed-package test: installs this build tree into a temporary prefix and builds and
# runs tests/consumer against it through find_package(linkproof). Included from tests/CMakeLists.txt.
add_test(NAME package.consumer_find_package
         COMMAND bash ${PROJECT_SOURCE_DIR}/scripts/test_consumer.sh ${PROJECT_BINARY_DIR})
set_tests_properties(package.consumer_find_package PROPERTIES
  LABELS "slow;package"
  TIMEOUT 900)
