#include "golden/common/published_figure.h"

#include <cmath>

namespace rangesim::golden {

bool PublishedFigure::reproduced() const {
  return std::isfinite(ours) && std::fabs(ours - published) <= tolerance * std::fabs(published);
}

}  // namespace rangesim::golden
