#pragma once
// The grid files of `rangesim evaluate` written as the rows of the evaluation arrive
// (golden::EvalSink), so that no grid is ever held whole: points.csv, detectable_area.csv,
// accuracy_mm.csv and accuracy_px.csv (where the sensor has it) go straight to the staging folder,
// and only the cells the heat maps show are kept (app/plot.h, plot_indices: every cell of a grid up
// to 1000 x 1000, a regular subset of a larger one).
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/output_dir.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::app {

class GridWriter : public golden::EvalSink {
 public:
  explicit GridWriter(OutputDir& out) : out_(out) {}
  void begin(const golden::EvalResult& r) override;
  void row(size_t ib, const std::vector<golden::EvalPoint>& points) override;
  // Closes the files (throws std::runtime_error when one could not be written) and returns the
  // result to plot: `ev` (the streamed evaluation, without points) with the kept cells.
  golden::EvalResult finish(const golden::EvalResult& ev);

 private:
  struct File {
    std::string cell;  // matrix cell ("detect", "accuracy_mm", a metric) or "" for points.csv
    std::string path;
    std::ofstream stream;
  };
  OutputDir& out_;
  golden::EvalResult shape_;  // axes, reasons and metric names of the evaluation
  std::vector<std::unique_ptr<File>> files_;
  std::vector<size_t> plot_rows_, plot_columns_;  // cells kept for the heat maps
  size_t next_plot_row_ = 0;                      // index into plot_rows_
  int px_metric_ = -1;                            // accuracy_px in the metrics, -1: none
  std::vector<golden::EvalPoint> plot_points_;
};

}  // namespace rangesim::app
