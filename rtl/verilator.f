// Verilator flags shared by every verilation, the built-in instances of rtl/CMakeLists.txt and
// the run-time ones of tb/common/rtl_build.cpp (read with -f). Those add --sc (SystemC model),
// --trace (VCD), --prefix, --Mdir and the -G parameters. Paths here are relative to rtl/, the
// working folder of both.

// All lint warnings on, and fatal: a lint error fails the build.
-Wall
// Evaluate the immediate assertions (a_start_while_busy, ...); a failing one calls $error.
--assert
// Lint waivers: rtl/<sensor>/<block>.vlt, one per file, each scoped and explained, listed here.
ls_conventional/ls_conventional_readout.vlt
// Uninitialised state is random, not zero, so a missing reset shows up in co-simulation.
--x-assign unique
--x-initial unique
// One model = one evaluation thread; the co-simulation is small and runs one test per process.
--threads 1
