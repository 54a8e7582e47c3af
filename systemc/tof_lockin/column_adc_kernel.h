#pragma once
// The tof-lockin column ADC as a plain C++ kernel (rtl/tof_lockin/column_adc.sv).
#include "systemc/tof_lockin/kernel_types.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- column ADC
class ColumnAdcKernel {
 public:
  explicit ColumnAdcKernel(const TofLockinConfig& cfg);
  // floor(v / LSB) clipped to 0 .. 2^bits - 1 (the clip first, so the truncation is the floor).
  long long code(double v) const {
    const double q = v / lsb_;
    return q >= top_ ? codes_ - 1 : q < 1.0 ? 0 : static_cast<long long>(q);
  }
  double value_V(long long c) const { return static_cast<double>(c) * lsb_; }
  double lsb_V() const { return lsb_; }
  long long top_code() const { return codes_ - 1; }
  long long conversion_cycles() const { return conv_; }

 private:
  double lsb_;       // full scale / 2^bits
  double top_;       // 2^bits - 1
  long long codes_;  // 2^bits
  long long conv_;   // cycles of one conversion
};

}  // namespace rangesim::systemc::lockin
