#include "systemc/common/address_search_kernel.h"

#include <cassert>
#include <ostream>
#include <stdexcept>
#include <string>

namespace rangesim::systemc {

// ---- ActivationRow ----

ActivationRow::ActivationRow(int columns)
    : columns_(columns), words_(static_cast<std::size_t>((columns + 63) / 64), 0) {
  assert(columns >= 0);
}

bool ActivationRow::any() const {
  for (std::uint64_t w : words_) {
    if (w != 0) return true;
  }
  return false;
}

int ActivationRow::first() const {
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if (words_[i] != 0) return static_cast<int>(i * 64) + __builtin_ctzll(words_[i]);
  }
  return -1;
}

int ActivationRow::last() const {
  for (std::size_t i = words_.size(); i-- > 0;) {
    if (words_[i] != 0) return static_cast<int>(i * 64) + 63 - __builtin_clzll(words_[i]);
  }
  return -1;
}

std::string ActivationRow::to_string() const {
  std::string s;
  s.reserve(static_cast<std::size_t>(columns_));
  for (int c = columns_ - 1; c >= 0; --c) s.push_back(test(c) ? '1' : '0');
  return s;
}

std::ostream& operator<<(std::ostream& os, const ActivationRow& row) { return os << row.to_string(); }

// ---- AddressSearchKernel ----

namespace {
// The message is made only when the check fails: a sensor builds one kernel a row (365 on the
// preset), and making every message up front was most of a kernel's construction.
template <class Message>
void require(bool ok, const Message& what) {
  if (!ok) throw std::invalid_argument("AddressSearchKernel: " + what());
}
}  // namespace

AddressSearchKernel::AddressSearchKernel(const AddressSearchConfig& config, int search_cycles)
    : config_(config), search_cycles_(search_cycles), stream_bits_(2 * config.address_bits) {
  require(config.columns >= 1, [&] { return "columns must be >= 1, got " + std::to_string(config.columns); });
  // 31: the two addresses share one 64-bit shift register here (the RTL has no such limit).
  require(config.address_bits >= 1 && config.address_bits <= 31,
          [&] { return "address_bits must be in [1, 31], got " + std::to_string(config.address_bits); });
  require((std::int64_t{1} << config.address_bits) >= config.columns, [&] {
    return "address_bits = " + std::to_string(config.address_bits) + " cannot address " +
           std::to_string(config.columns) + " columns";
  });
  require(config.addresses_per_sampling == 2, [&] {
    return "addresses_per_sampling must be 2 (left and right edge), got " +
           std::to_string(config.addresses_per_sampling);
  });
  require(search_cycles >= 1, [&] { return "search_cycles must be >= 1, got " + std::to_string(search_cycles); });
  // act_ stays without words (every column off, as the RTL's reset value) until a start latches a
  // row: a sensor builds a search per row, and with event skipping none of them ever latches one.
}

void AddressSearchKernel::tick(bool rst, bool start, const ActivationRow& act) {
  ++edges_;
  if (rst) {
    state_ = State::Idle;
    count_ = 0;
    act_.clear();  // in place (width kept): a sensor resets a kernel a row at every jump to a frame access
    shift_ = 0;
    return;
  }
  switch (state_) {
    case State::Idle:
      count_ = 0;
      if (start) {
        assert(act.columns() == config_.columns && "activation row width != columns");
        act_ = act;
        state_ = State::Search;
      }
      break;
    case State::Search:
      if (count_ == search_cycles_ - 1) {
        // The chain has settled: load {left, right} into the shift register.
        const bool found = act_.any();
        const std::uint64_t left = found ? static_cast<std::uint64_t>(act_.first()) : 0;
        const std::uint64_t right = found ? static_cast<std::uint64_t>(act_.last()) : 0;
        shift_ = (left << config_.address_bits) | right;
        count_ = 0;
        state_ = found ? State::Stream : State::Idle;
      } else {
        ++count_;
      }
      break;
    case State::Stream:
      shift_ = (shift_ << 1) & ((std::uint64_t{1} << stream_bits_) - 1);
      if (count_ == stream_bits_ - 1) {
        count_ = 0;
        state_ = State::Idle;
      } else {
        ++count_;
      }
      break;
  }
}

AddressSearchPins AddressSearchKernel::pins() const {
  AddressSearchPins p;
  p.busy = state_ != State::Idle;
  p.found = act_.any();
  p.addr_valid = state_ == State::Stream;
  p.addr_bit = p.addr_valid && ((shift_ >> (stream_bits_ - 1)) & 1U);
  const bool search_last = state_ == State::Search && count_ == search_cycles_ - 1;
  const bool stream_last = state_ == State::Stream && count_ == stream_bits_ - 1;
  p.done = (search_last && !p.found) || stream_last;
  return p;
}

AddressSearchResult AddressSearchKernel::run(const ActivationRow& act) {
  assert(idle() && "run() needs an idle kernel");
  AddressSearchResult r;
  tick(false, true, act);  // end of the start cycle k = 0
  std::uint64_t bits = 0;
  // Bounded: at most S + 2B cycles, plus slack so a broken kernel fails instead of hanging.
  for (int k = 1; k <= search_cycles_ + stream_bits_ + 1; ++k) {
    const AddressSearchPins p = pins();
    if (p.addr_valid) bits = (bits << 1) | (p.addr_bit ? 1U : 0U);
    if (p.done) {
      r.found = p.found;
      r.done_cycle = k;
      tick(false, false, act);  // end of the done cycle: idle again
      break;
    }
    tick(false, false, act);
  }
  assert(r.done_cycle > 0 && "done_o never came");
  const std::uint64_t mask = (std::uint64_t{1} << config_.address_bits) - 1;
  r.left = static_cast<int>((bits >> config_.address_bits) & mask);
  r.right = static_cast<int>(bits & mask);
  return r;
}

}  // namespace rangesim::systemc
