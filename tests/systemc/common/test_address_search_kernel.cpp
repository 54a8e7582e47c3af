// AddressSearchKernel (plain C++, no elaboration): against a trivially correct reference, the
// documented cycle schedule, and the closed-form (event-skipping) path.
#include <gtest/gtest.h>

#include <ostream>
#include <random>
#include <stdexcept>
#include <string>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search_kernel.h"

namespace rs = rangesim::systemc;
using rangesim::AddressSearchConfig;
using rangesim::FrameTimingConfig;

namespace {

// Obviously correct: scan every column.
struct Reference {
  bool found = false;
  int left = 0, right = 0;
};
Reference reference(const rs::ActivationRow& row) {
  Reference r;
  for (int c = 0; c < row.columns(); ++c) {
    if (!row.test(c)) continue;
    if (!r.found) r.left = c;
    r.right = c;
    r.found = true;
  }
  return r;
}

rs::ActivationRow random_row(int columns, std::mt19937_64& rng) {
  rs::ActivationRow row(columns);
  std::uniform_real_distribution<double> u(0, 1);
  const double density = u(rng) < 0.2 ? 0.0 : u(rng) * u(rng) * 0.2;  // many sparse rows
  for (int c = 0; c < columns; ++c) row.set(c, u(rng) < density);
  return row;
}

struct Case {
  AddressSearchConfig config;
  int search_cycles;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << "columns " << c.config.columns << ", address_bits " << c.config.address_bits << ", search_cycles "
      << c.search_cycles;
}

class KernelRandomRows : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(KernelRandomRows, MatchesReferenceAndSchedule) {
  const Case c = GetParam();
  rs::AddressSearchKernel k(c.config, c.search_cycles);
  k.reset();
  std::mt19937_64 rng(42);
  const int stream = 2 * c.config.address_bits;
  for (int i = 0; i < 3000; ++i) {
    const rs::ActivationRow row = random_row(c.config.columns, rng);
    const Reference ref = reference(row);
    const long long edges_before = k.edges();
    const rs::AddressSearchResult r = k.run(row);
    ASSERT_EQ(r.found, ref.found) << row;
    ASSERT_EQ(r.left, ref.left) << row;
    ASSERT_EQ(r.right, ref.right) << row;
    ASSERT_EQ(r.done_cycle, ref.found ? c.search_cycles + stream : c.search_cycles);
    // Start-to-next-start = latch + search + stream edges.
    ASSERT_EQ(k.edges() - edges_before, 1 + r.done_cycle);
    // The closed form (no ticks) is identical.
    const rs::AddressSearchResult e = k.evaluate(row);
    ASSERT_EQ(e.found, r.found);
    ASSERT_EQ(e.left, r.left);
    ASSERT_EQ(e.right, r.right);
    ASSERT_EQ(e.done_cycle, r.done_cycle);
  }
}

INSTANTIATE_TEST_SUITE_P(Configs, KernelRandomRows,
                         ::testing::Values(Case{AddressSearchConfig{}, FrameTimingConfig{}.search_cycles},
                                           Case{AddressSearchConfig{16, 4, 2}, 2},
                                           Case{AddressSearchConfig{1, 1, 2}, 1},
                                           Case{AddressSearchConfig{64, 6, 2}, 3},
                                           Case{AddressSearchConfig{65, 7, 2}, 5}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           const Case& c = info.param;
                           return "columns" + std::to_string(c.config.columns) + "_bits" +
                                  std::to_string(c.config.address_bits) + "_search" + std::to_string(c.search_cycles);
                         });

TEST(AddressSearchKernel, CycleCountMatchesFrameTiming) {
  // One sampling in golden/common/frame_timing.h: latch + search + addresses_per_sampling * bits.
  const FrameTimingConfig t;
  rs::AddressSearchKernel k(AddressSearchConfig{}, t.search_cycles);
  rs::ActivationRow row(AddressSearchConfig{}.columns);
  row.set(120);
  row.set(122);
  const long long before = k.edges();
  const rs::AddressSearchResult r = k.run(row);
  EXPECT_EQ(r.done_cycle, t.search_cycles + t.addresses_per_sampling * t.address_bits);
  EXPECT_EQ(k.edges() - before, t.latch_cycles + t.search_cycles + t.addresses_per_sampling * t.address_bits);
  EXPECT_EQ(r.left, 120);
  EXPECT_EQ(r.right, 122);
}

TEST(AddressSearchKernel, PinsFollowTheDocumentedSchedule) {
  // S = 2, B = 4, row with left 5 = 0101, right 10 = 1010.
  rs::AddressSearchKernel k(AddressSearchConfig{16, 4, 2}, 2);
  rs::ActivationRow row(16);
  row.set(5);
  row.set(10);
  k.tick(false, true, row);  // end of k = 0
  const bool stream[] = {0, 1, 0, 1, 1, 0, 1, 0};
  for (int cyc = 1; cyc <= 10; ++cyc) {
    const rs::AddressSearchPins p = k.pins();
    EXPECT_TRUE(p.busy) << cyc;
    EXPECT_TRUE(p.found) << cyc;
    EXPECT_EQ(p.addr_valid, cyc >= 3) << cyc;
    if (cyc >= 3) {
      EXPECT_EQ(p.addr_bit, stream[cyc - 3]) << cyc;
    }
    EXPECT_EQ(p.done, cyc == 10) << cyc;
    k.tick(false, false, rs::ActivationRow(16));
  }
  EXPECT_FALSE(k.pins().busy);
  EXPECT_TRUE(k.pins().found);  // held until the next start
}

TEST(AddressSearchKernel, EmptyRowIsDoneAfterTheSearch) {
  rs::AddressSearchKernel k(AddressSearchConfig{16, 4, 2}, 2);
  k.tick(false, true, rs::ActivationRow(16));
  EXPECT_FALSE(k.pins().done);
  k.tick(false, false, rs::ActivationRow(16));
  const rs::AddressSearchPins p = k.pins();
  EXPECT_TRUE(p.done);
  EXPECT_FALSE(p.found);
  EXPECT_FALSE(p.addr_valid);
  k.tick(false, false, rs::ActivationRow(16));
  EXPECT_TRUE(k.idle());
}

TEST(AddressSearchKernel, StartWhileBusyIsIgnoredAndResetClears) {
  rs::AddressSearchKernel k(AddressSearchConfig{16, 4, 2}, 2);
  rs::ActivationRow a(16), b(16);
  a.set(3);
  b.set(9);
  k.tick(false, true, a);
  k.tick(false, true, b);  // ignored, like the RTL (which also asserts)
  k.tick(false, false, b);
  k.tick(true, false, b);  // synchronous reset mid-operation
  EXPECT_TRUE(k.idle());
  EXPECT_FALSE(k.pins().found);
  EXPECT_EQ(k.run(b).left, 9);
}

namespace {
// The message (made only when a check fails) names the parameter and the value.
std::string rejection(const AddressSearchConfig& c, int search_cycles) {
  try {
    rs::AddressSearchKernel k(c, search_cycles);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(AddressSearchKernel, RejectsUnbuildableParameters) {
  EXPECT_EQ(rejection(AddressSearchConfig{375, 8, 2}, 2),
            "AddressSearchKernel: address_bits = 8 cannot address 375 columns");
  EXPECT_EQ(rejection(AddressSearchConfig{375, 9, 3}, 2),
            "AddressSearchKernel: addresses_per_sampling must be 2 (left and right edge), got 3");
  EXPECT_EQ(rejection(AddressSearchConfig{375, 9, 2}, 0), "AddressSearchKernel: search_cycles must be >= 1, got 0");
  EXPECT_EQ(rejection(AddressSearchConfig{0, 9, 2}, 2), "AddressSearchKernel: columns must be >= 1, got 0");
  EXPECT_EQ(rejection(AddressSearchConfig{375, 32, 2}, 2),
            "AddressSearchKernel: address_bits must be in [1, 31], got 32");
  EXPECT_EQ(rejection(AddressSearchConfig{512, 9, 2}, 2), "");
}

TEST(ActivationRow, PacksBitsAcrossWords) {
  rs::ActivationRow row(130);
  EXPECT_EQ(row.first(), -1);
  row.set(64);
  row.set(129);
  row.set(63);
  EXPECT_EQ(row.first(), 63);
  EXPECT_EQ(row.last(), 129);
  EXPECT_EQ(row.words().size(), 3U);
  row.set(63, false);
  EXPECT_EQ(row.first(), 64);
  EXPECT_EQ(row.to_string().size(), 130U);
}
