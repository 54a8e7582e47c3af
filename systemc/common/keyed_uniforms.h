#pragma once
// Many pixels' keyed uniforms of one frame access at once (random_stream.h): the same bits as
// keyed_uniform(pixel_key_in_frame(frame_key, row, column)) one by one, computed in a loop the
// compiler vectorises. Where the CPU has AVX-512 (x86-64-v4) a clone with eight 64-bit lanes runs
// (SplitMix64 needs 64-bit multiplies, which only AVX-512DQ has in vector form), picked once at
// load time; with AVX2 alone four lanes with the multiplies made of 32-bit ones, and two keys a
// step in general-purpose registers beside them (about 1.6x the plain loop); elsewhere the plain
// loop. Integer arithmetic and exact conversions: every version
// gives the same bits (tests/skipping/test_row_extents.cpp).
#include <cstddef>
#include <cstdint>

namespace rangesim::systemc {

// The row in the high and the column in the low 32 bits, as pixel_key_in_frame packs them.
inline std::uint64_t row_column(std::uint32_t row, std::uint32_t column) {
  return (static_cast<std::uint64_t>(row) << 32) | column;
}

// u[i] = keyed_uniform(pixel_key_in_frame(frame_key, row and column of rc[i])) for i < n.
void keyed_uniforms(std::uint64_t frame_key, const std::uint64_t* rc, double* u, std::size_t n);
// The same for a grid of pixels, rows row0 .. row0 + rows - 1 of each of m columns, column by
// column: u[t rows + i] is row row0 + i's in columns[t]. Its keys are made in the loop, not read.
void keyed_uniforms_grid(std::uint64_t frame_key, std::uint32_t row0, std::size_t rows, const std::uint32_t* columns,
                         std::size_t m, double* u);

}  // namespace rangesim::systemc
