#pragma once
// A figure published for one of the chips (thesis or chip paper, listed in docs/<sensor>.md) beside
// rangesim's value for it. `rangesim table --published` lists them; each sensor's tests assert
// the reproduced ones within their tolerance and pin the others with the reason they differ.
//
// Every figure also says how much its agreement is worth (its basis): a figure a preset value was
// tuned to agrees by construction, so "reproduced" counts as evidence of fidelity only for the
// predicted ones.
#include <string>
#include <vector>

namespace rangesim::golden {

enum class FigureBasis {
  Calibrated,  // a preset value (basis_key) was tuned to this very figure
  Fitted,      // follows from a preset value (basis_key) fitted to several figures at once (fitted_to)
  Arithmetic,  // follows from the published numbers or the structure alone (basis_note says how)
  Predicted,   // the model's output from values not tuned to it
};
const char* to_string(FigureBasis b);  // "calibrated", "fitted", "arithmetic", "predicted"
inline constexpr FigureBasis kFigureBases[] = {FigureBasis::Calibrated, FigureBasis::Fitted, FigureBasis::Arithmetic,
                                               FigureBasis::Predicted};

struct PublishedFigure {
  std::string sensor;       // preset id
  std::string id;           // snake_case, unique per sensor, e.g. "resolution_t0_100ns_1p4V"
  std::string description;  // what was published and where (thesis section, figure, paper)
  double published = 0;     // as published, in `unit`
  std::string unit;         // "m", "dB", "px", "Hz", "1" ...
  double ours = 0;          // rangesim's value under the conditions in `note`
  double tolerance = 0;     // relative: reproduced when |ours - published| <= tolerance |published|
  std::string note;         // conditions and parameters used; for a difference, why it differs
  FigureBasis basis = FigureBasis::Predicted;
  std::string basis_key{};               // calibrated / fitted: the preset key tuned (e.g. "timing.clock_Hz")
  std::vector<std::string> fitted_to{};  // fitted: ids of the figures basis_key was fitted to
  std::string basis_note{};              // arithmetic: the arithmetic; otherwise optional detail
  bool reproduced() const;
  // "calibrated: timing.clock_Hz", "fitted: noise.read_noise_V to 11 figures", "arithmetic: ...", "predicted".
  std::string basis_text() const;
};

// Sets the basis of figure `id` in `figs`; throws std::logic_error when no figure has that id (a
// renamed figure must not silently fall back to "predicted").
void set_basis(std::vector<PublishedFigure>& figs, const std::string& id, FigureBasis basis, std::string key = "",
               std::vector<std::string> fitted_to = {}, std::string note = "");

}  // namespace rangesim::golden
