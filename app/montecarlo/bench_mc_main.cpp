// rangesim-bench-mc [--quick]: prints measure_mc_bench() as JSON (the Monte Carlo figures that
// `rangesim bench` reports), until that command exists on this branch.
#include <cstdio>
#include <cstring>
#include <exception>

#include <nlohmann/json.hpp>

#include "app/bench_mc.h"

extern "C" int sc_main(int, char*[]) { return 1; }  // libsystemc.so refers to it; never called

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  try {
    const rangesim::app::McBenchFigures f = rangesim::app::measure_mc_bench(quick);
    nlohmann::json j = {
        {"mc_vs_bare_rng", f.mc_vs_bare_rng},           {"threads2_vs_1", f.threads2_vs_1},
        {"mc_variates_per_s", f.mc_variates_per_s},     {"bare_variates_per_s", f.bare_variates_per_s},
        {"sweep_1thread_s", f.sweep_1thread_s},         {"sweep_2threads_s", f.sweep_2threads_s},
        {"sweep_1thread_cpu_s", f.sweep_1thread_cpu_s}, {"sweep_2threads_cpu_s", f.sweep_2threads_cpu_s},
        {"cpu_share_2threads", f.cpu_share_2threads},   {"cpu_2threads_vs_1", f.cpu_2threads_vs_1},
        {"load_average_1min", f.load_average_1min},     {"targets", {{"mc_vs_bare_rng", 0.5}, {"threads2_vs_1", 1.8}}}};
    std::printf("%s\n", j.dump(2).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rangesim-bench-mc: %s\n", e.what());
    return 1;
  }
  return 0;
}
