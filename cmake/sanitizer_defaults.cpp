// Linked into every executable of a sanitizer build (cmake/LinkproofSanitizers.cmake): the
// defaults AddressSanitizer reads at start-up, so that a test binary run by CMake's test
// discovery, by ctest, or as a child of a test behaves the same without ASAN_OPTIONS.
// Leaks are not checked: GiNaC and CLN keep global tables alive until exit by design, and a
// leak report would turn every exit into a failure (exit 1).
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
