#include "app/montecarlo/mc_model.h"

#include <stdexcept>

#include "app/montecarlo/mc_models.h"
#include "core/ls_conventional_config.h"
#include "core/ls_demodulation_config.h"
#include "core/tof_lockin_config.h"
#include "core/tof_spad_config.h"
#include "systemc/random_stream.h"

namespace rangesim::app::mc {

using systemc::splitmix64;

std::uint64_t point_key(std::uint64_t seed, std::uint64_t point_index) {
  return splitmix64(splitmix64(seed ^ 0x6d6f6e7465636172ULL) ^ point_index);  // "montecar"
}

std::uint64_t trial_key(std::uint64_t key, std::uint64_t trial) { return splitmix64(key ^ splitmix64(trial)); }

double trial_uniform(std::uint64_t key, std::uint64_t trial) {
  pcg32 rng = systemc::pixel_stream(trial_key(key ^ 0x706f736974696f6eULL, trial));  // "position"
  return systemc::uniform_open01(rng);
}

std::unique_ptr<McModel> make_mc_model(const ParamSet& params) {
  const std::string& id = params.sensor_id();
  if (id == "ls-conventional") return std::make_unique<LsConventionalMc>(ls_conventional_from_params(params));
  if (id == "ls-demodulation") return std::make_unique<LsDemodulationMc>(ls_demodulation_from_params(params));
  if (id == "tof-lockin") return std::make_unique<TofLockinMc>(tof_lockin_from_params(params));
  if (id == "tof-spad") return std::make_unique<TofSpadMc>(tof_spad_from_params(params));
  throw std::logic_error("no Monte Carlo model for sensor " + id);
}

}  // namespace rangesim::app::mc
