// GoogleTest entry point for binaries that link SystemC: libsystemc owns main() and calls
// sc_main, so gtest_main cannot be used. Each test that elaborates runs in
// its own process (gtest_discover_tests), since SystemC allows one elaboration per process.
#include <gtest/gtest.h>

#include <cstdlib>
#include <systemc>

int sc_main(int argc, char* argv[]) {
  // The banner is printed at the first elaboration, after sc_main starts; ctest sets this too.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
