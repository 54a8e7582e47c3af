// Placeholder until the golden model of this sensor lands.
#include <stdexcept>

#include "golden/evaluate_sensor.h"

namespace rangesim::golden {

EvalResult evaluate_ls_demodulation(const ParamSet&, ProgressFn) { throw std::logic_error("not modelled yet"); }
std::vector<PublishedFigure> published_figures_ls_demodulation(const ParamSet&) { return {}; }

}  // namespace rangesim::golden
