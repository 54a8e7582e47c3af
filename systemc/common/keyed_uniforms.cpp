#include "systemc/common/keyed_uniforms.h"

#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

// GCC's function clones are an x86 ELF feature (an ifunc resolver); other targets get the loop.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
__attribute__((target_clones("arch=x86-64-v4", "default")))
#endif
void keyed_uniforms(std::uint64_t frame_key, const std::uint64_t* rc, double* u, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) u[i] = keyed_uniform(splitmix64(frame_key ^ rc[i]));
}

}  // namespace rangesim::systemc
