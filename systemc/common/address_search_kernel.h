#pragma once
// Cycle kernel of the row address search (ls-conventional, thesis [31]): plain C++, no SystemC,
// bit- and cycle-exact to rtl/common/address_search.sv (whose header comment is the cycle schedule).
// One kernel = the search/stream logic of one row. Sweeps drive it directly; the sc_module in
// systemc/common/address_search.h only connects ports to it.
#include <algorithm>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/ls_conventional/config.h"

namespace rangesim::systemc {

// Activation bits of one row, packed 64 per word: column c is bit (c % 64) of word c / 64.
// A value type (==, <<) so it can travel on an sc_signal.
class ActivationRow {
 public:
  ActivationRow() = default;
  explicit ActivationRow(int columns);

  int columns() const { return columns_; }
  // Inline: the pixel array calls these per pixel and sampling.
  // (Columns are never negative: unsigned arithmetic spares the signed division's fix-ups.)
  bool test(int column) const {
    const auto c = static_cast<unsigned>(column);
    return (words_[c / 64] >> (c % 64)) & 1U;
  }
  void set(int column, bool value = true) {
    const auto c = static_cast<unsigned>(column);
    const std::uint64_t mask = std::uint64_t{1} << (c % 64);
    std::uint64_t& w = words_[c / 64];
    w = value ? (w | mask) : (w & ~mask);
  }
  // Columns first..last on (nothing if last < first); 0 <= first, last < columns.
  void set_range(int first, int last) {
    if (last < first) return;
    const auto f = static_cast<unsigned>(first), l = static_cast<unsigned>(last);
    const std::size_t wf = f / 64, wl = l / 64;
    const std::uint64_t mf = ~std::uint64_t{0} << (f % 64), ml = ~std::uint64_t{0} >> (63 - l % 64);
    if (wf == wl) {
      words_[wf] |= mf & ml;
      return;
    }
    words_[wf] |= mf;
    for (std::size_t w = wf + 1; w < wl; ++w) words_[w] = ~std::uint64_t{0};
    words_[wl] |= ml;
  }
  void clear() { std::fill(words_.begin(), words_.end(), 0); }  // every column off, width kept
  void clear_to_width(int columns) {  // every column off, at width `columns` (words made only for a new width)
    if (columns == columns_)
      clear();
    else
      *this = ActivationRow(columns);
  }
  bool any() const;
  int first() const;  // lowest activated column, -1 if none
  int last() const;   // highest activated column, -1 if none
  const std::vector<std::uint64_t>& words() const { return words_; }
  std::string to_string() const;  // Verilog order: column columns-1 first

  bool operator==(const ActivationRow& other) const { return columns_ == other.columns_ && words_ == other.words_; }
  bool operator!=(const ActivationRow& other) const { return !(*this == other); }

 private:
  int columns_ = 0;                   // row width in pixels
  std::vector<std::uint64_t> words_;  // packed bits; bits beyond columns_ are always 0
};

std::ostream& operator<<(std::ostream& os, const ActivationRow& row);

// Lowest and highest activated column of a row (-1: none): all the address search reads of it.
struct ActivationExtent {
  int first = -1, last = -1;
  bool operator==(const ActivationExtent& o) const { return first == o.first && last == o.last; }
};

// The RTL output ports during one clock cycle.
struct AddressSearchPins {
  bool busy = false;        // busy_o
  bool found = false;       // found_o
  bool addr_valid = false;  // addr_valid_o
  bool addr_bit = false;    // addr_bit_o
  bool done = false;        // done_o
  bool operator==(const AddressSearchPins& o) const {
    return busy == o.busy && found == o.found && addr_valid == o.addr_valid && addr_bit == o.addr_bit && done == o.done;
  }
};

// Outcome of one search operation.
struct AddressSearchResult {
  bool found = false;  // an activated pixel exists
  int left = 0;        // streamed left address (0 when !found)
  int right = 0;       // streamed right address (0 when !found)
  int done_cycle = 0;  // cycle k (after the start cycle k = 0) in which done_o is high
};

class AddressSearchKernel {
 public:
  // Throws std::invalid_argument naming the field if the parameters cannot be built in RTL.
  AddressSearchKernel(const AddressSearchConfig& config, int search_cycles);

  // One rising clock edge, with the inputs as sampled at that edge (synchronous reset).
  // `act` is only read when the edge latches it (start while idle); then its width must match.
  void tick(bool rst, bool start, const ActivationRow& act);
  void reset() { tick(true, false, ActivationRow{}); }

  // Output ports during the current cycle (after the last tick).
  AddressSearchPins pins() const;
  bool idle() const { return state_ == State::Idle; }

  // Run-to-completion helper, tick by tick: from idle, start with `act`, clock until done_o and
  // one edge more (so the kernel is idle again, ready for a start in the next cycle).
  // The addresses are decoded from the addr_bit_o stream, not copied from the state.
  AddressSearchResult run(const ActivationRow& act);

  // The same result in closed form, no ticks (the event-skipping path; tests prove it equal). The
  // search reads nothing of the row but its lowest and highest activated column.
  AddressSearchResult evaluate(const ActivationExtent& e) const {
    AddressSearchResult r;
    if (e.first >= 0) {
      r.found = true;
      r.left = e.first;
      r.right = e.last;
    }
    r.done_cycle = operation_cycles(r.found);
    return r;
  }
  AddressSearchResult evaluate(const ActivationRow& act) const { return evaluate(ActivationExtent{act.first(), act.last()}); }

  // Cycles from start (k = 0, exclusive) to done_o (inclusive): S + 2B, or S if nothing found.
  // Start-to-next-start is one more (the latch cycle).
  int operation_cycles(bool found) const { return found ? search_cycles_ + stream_bits_ : search_cycles_; }

  const AddressSearchConfig& config() const { return config_; }
  int search_cycles() const { return search_cycles_; }
  long long edges() const { return edges_; }  // ticks since construction

 private:
  enum class State { Idle, Search, Stream };

  AddressSearchConfig config_;  // columns, address_bits (RTL parameters)
  int search_cycles_;           // chain settle time S (RTL SEARCH_CYCLES)
  int stream_bits_;             // 2 * address_bits
  State state_ = State::Idle;   // RTL state_q
  int count_ = 0;               // RTL count_q: cycles spent in the current state
  ActivationRow act_;           // RTL act_q: latched activation bits (none before the first latch: all off)
  std::uint64_t shift_ = 0;     // RTL shift_q: {left, right}, MSB streamed first
  long long edges_ = 0;         // clock edges seen
};

}  // namespace rangesim::systemc
