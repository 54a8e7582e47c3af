// Verilator flags shared by every verilate() call in rtl/CMakeLists.txt (read with -f).
// verilate() itself adds --sc (SystemC model), --trace (VCD; TRACE_VCD is ignored on 5.006),
// --prefix and --Mdir. Paths here are relative to rtl/, the WORKING_DIRECTORY of verilate().

// All lint warnings on, and fatal: a lint error fails `cmake` (verilate runs at configure time).
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
