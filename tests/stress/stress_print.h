#pragma once
// Printers RapidCheck uses for a failing case of the ls-demodulation, tof-lockin and tof-spad
// stress properties: the keys the generators vary, at full precision, so the case can be pasted.
#include <ostream>

#include "core/ls_demodulation/config.h"
#include "core/tof_lockin/config.h"
#include "core/tof_spad/config.h"

namespace rangesim {

inline std::ostream& operator<<(std::ostream& os, const LsDemodulationConfig& c) {
  os.precision(17);
  return os << "{integration_time_s=" << c.pixel.integration_time_s << " cycles=" << c.correlator.cycles
            << " frequency_Hz=" << c.modulation.frequency_Hz << " clock_Hz=" << c.readout.clock_Hz
            << " columns=" << c.pixel.columns << " source_duty=" << c.modulation.source_duty_cycle
            << " reference_duty=" << c.correlator.reference_duty_cycle
            << " reference_phase_rad=" << c.modulation.reference_phase_rad
            << " mirror_gain=" << c.suppression.mirror_gain << " mirror_mismatch=" << c.suppression.mirror_mismatch
            << " tau_s=" << c.suppression.lpf_time_constant_s << " log_gain=" << c.log_converter.gain
            << " slope_V=" << c.log_converter.slope_V << " offset_current_A=" << c.log_converter.offset_current_A
            << " leakage_current_A=" << c.log_converter.leakage_current_A << " C1_F=" << c.correlator.capacitance_plus_F
            << " C2_F=" << c.correlator.capacitance_minus_F << " gm_S=" << c.correlator.transconductance_S
            << " vsat_V=" << c.correlator.saturation_voltage_V << " vcmp_V=" << c.comparator.threshold_V
            << " false_activation_max=" << c.comparator.false_activation_max << " T_K=" << c.noise.temperature_K
            << " dark_A=" << c.noise.dark_current_A << " read_V=" << c.noise.read_noise_V
            << " fpn_V=" << c.noise.fixed_pattern_rms_V << " fwhm_px=" << c.spot.fwhm_px
            << " subpixel_points=" << c.grid.subpixel_points << " detections=" << c.grid.detections
            << " frames=" << c.grid.frames_averaged << "}";
}

inline std::ostream& operator<<(std::ostream& os, const TofLockinConfig& c) {
  os.precision(17);
  return os << "{fd1_F=" << c.pixel.fd1_capacitance_F << " fd2_F=" << c.pixel.fd2_capacitance_F
            << " sf_gain=" << c.pixel.source_follower_gain << " vsat_V=" << c.pixel.saturation_voltage_V
            << " offset_V=" << c.pixel.offset_voltage_V << " eta=" << c.pixel.charge_separation
            << " drain_eff=" << c.pixel.drain_efficiency << " T0_s=" << c.source.pulse_width_s
            << " duty=" << c.source.duty_cycle << " rise_s=" << c.source.rise_time_s
            << " gate_clock_Hz=" << c.gates.clock_Hz << " n_acc=" << c.gates.accumulations_per_frame
            << " adc_bits=" << c.readout.adc_bits << " full_scale_V=" << c.readout.adc_full_scale_V
            << " threshold_V=" << c.readout.detection_threshold_V << " min_snr=" << c.readout.min_snr
            << " cds=" << c.readout.cds_enabled << " ambient=" << c.readout.ambient_subtraction
            << " v_cal_V=" << c.readout.offset_calibration_V << " T_K=" << c.noise.temperature_K
            << " dark_A=" << c.noise.dark_current_A << " read_V=" << c.noise.read_noise_V
            << " fpn_V=" << c.noise.fixed_pattern_rms_V << "}";
}

inline std::ostream& operator<<(std::ostream& os, const TofSpadConfig& c) {
  os.precision(17);
  return os << "{lsb_s=" << c.tdc.lsb_s << " rep_Hz=" << c.laser.repetition_rate_Hz << " bits=" << c.tdc.bits
            << " full_range_s=" << c.tdc.full_range_s << " dnl=" << c.tdc.dnl_rms_lsb << " inl=" << c.tdc.inl_rms_lsb
            << " cpt=" << c.tdc.columns_per_tdc << " neighbour=" << c.tdc.neighbour_rate_fraction
            << " busy_s=" << c.tdc.busy_time_s << " dead_s=" << c.spad.dead_time_s
            << " dcr_Hz=" << c.spad.dark_count_rate_Hz << " jitter_s=" << c.spad.jitter_sigma_s
            << " fwhm_s=" << c.laser.pulse_fwhm_s << " integration_s=" << c.histogram.integration_time_s
            << " pw=" << c.histogram.peak_window_bins << " coates=" << c.histogram.coates_correction
            << " subtract=" << c.histogram.subtract_background << " frames=" << c.evaluation.frames_averaged
            << " k_sigma=" << c.evaluation.detection_sigma << " min_counts=" << c.evaluation.min_signal_counts
            << " min_armed=" << c.evaluation.min_armed_fraction << "}";
}

}  // namespace rangesim
