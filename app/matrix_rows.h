#pragma once
// A matrix's rows where they lie: those of a std::vector<std::vector<double>>, without the outer
// vector. Moving the outer vector moves its object but not its rows, so a job of simulate's
// output may read a range map through this while the run that made the map hands it on
// (systemc::SimulationHost::map_ready).
#include <cstddef>
#include <vector>

namespace rangesim::app {

class MatrixRows {
 public:
  MatrixRows(const std::vector<std::vector<double>>& rows)  // NOLINT: implicit, as a view
      : first_(rows.data()), count_(rows.size()) {}
  const std::vector<double>* begin() const { return first_; }
  const std::vector<double>* end() const { return first_ + count_; }
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const std::vector<double>& operator[](std::size_t r) const { return first_[r]; }

 private:
  const std::vector<double>* first_;
  std::size_t count_;
};

}  // namespace rangesim::app
