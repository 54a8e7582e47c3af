#include "golden/common/published_figure.h"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace rangesim::golden {

const char* to_string(FigureBasis b) {
  switch (b) {
    case FigureBasis::Calibrated: return "calibrated";
    case FigureBasis::Fitted: return "fitted";
    case FigureBasis::Arithmetic: return "arithmetic";
    case FigureBasis::Predicted: return "predicted";
  }
  return "?";
}

bool PublishedFigure::reproduced() const {
  return std::isfinite(ours) && std::fabs(ours - published) <= tolerance * std::fabs(published);
}

std::string PublishedFigure::basis_text() const {
  std::string t = to_string(basis);
  if (basis == FigureBasis::Calibrated) t += ": " + basis_key;
  if (basis == FigureBasis::Fitted) t += fmt::format(": {} to {} figures", basis_key, fitted_to.size());
  const bool named = basis == FigureBasis::Calibrated || basis == FigureBasis::Fitted;
  if (!basis_note.empty()) t += (named ? "; " : ": ") + basis_note;
  return t;
}

void set_basis(std::vector<PublishedFigure>& figs, const std::string& id, FigureBasis basis, std::string key,
               std::vector<std::string> fitted_to, std::string note) {
  for (auto& f : figs)
    if (f.id == id) {
      f.basis = basis;
      f.basis_key = std::move(key);
      f.fitted_to = std::move(fitted_to);
      f.basis_note = std::move(note);
      return;
    }
  throw std::logic_error("set_basis: no published figure '" + id + "'");
}

}  // namespace rangesim::golden
