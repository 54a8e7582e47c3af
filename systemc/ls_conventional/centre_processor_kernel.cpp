#include "systemc/ls_conventional/centre_processor_kernel.h"

#include <stdexcept>
#include <string>

namespace rangesim::systemc {

CentreProcessorKernel::CentreProcessorKernel(int address_bits) : address_bits_(address_bits) {
  if (address_bits < 1 || address_bits > 20)
    throw std::invalid_argument("CentreProcessorKernel: address_bits must be in [1, 20], got " +
                                std::to_string(address_bits));
}

void CentreProcessorKernel::tick(bool clear_in, const AddressSearchPins& search) {
  if (clear_in) {
    clear();
    return;
  }
  if (!search.addr_valid) return;
  shift_ = (shift_ << 1) | (search.addr_bit ? 1U : 0U);
  if (++bits_ == 2 * address_bits_) {
    const std::uint64_t mask = (std::uint64_t{1} << address_bits_) - 1;
    sum_ += static_cast<std::uint32_t>(((shift_ >> address_bits_) & mask) + (shift_ & mask));
    ++count_;
    shift_ = 0;
    bits_ = 0;
  }
}

}  // namespace rangesim::systemc
