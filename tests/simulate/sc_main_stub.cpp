// libsystemc.so defines main() and refers to sc_main. This binary never elaborates (it runs the
// bare kernels) and takes gtest_main's main(); the stub satisfies the linker.
extern "C" int sc_main(int, char*[]) { return 1; }
