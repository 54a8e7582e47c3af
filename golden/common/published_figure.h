#pragma once
// A figure published for one of the chips (thesis or chip paper, listed in docs/<sensor>.md) beside
// rangesim's value for it. `rangesim table --published` lists them; each sensor's tests assert
// the reproduced ones within their tolerance and pin the others with the reason they differ.
#include <string>
#include <vector>

namespace rangesim::golden {

struct PublishedFigure {
  std::string sensor;       // preset id
  std::string id;           // snake_case, unique per sensor, e.g. "resolution_t0_100ns_1p4V"
  std::string description;  // what was published and where (thesis section, figure, paper)
  double published = 0;     // as published, in `unit`
  std::string unit;         // "m", "dB", "px", "Hz", "1" ...
  double ours = 0;          // rangesim's value under the conditions in `note`
  double tolerance = 0;     // relative: reproduced when |ours - published| <= tolerance |published|
  std::string note;         // conditions and parameters used; for a difference, why it differs
  bool reproduced() const;
};

}  // namespace rangesim::golden
