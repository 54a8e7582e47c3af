#include "app/grid_writer.h"

#include <fmt/format.h>
#include <stdexcept>

#include "app/evaluation_output.h"
#include "app/plot.h"

namespace rangesim::app {

void GridWriter::begin(const golden::EvalResult& r) {
  shape_.signal = r.signal;
  shape_.background = r.background;
  shape_.metric_names = r.metric_names;
  std::vector<std::pair<std::string, std::string>> files = {
      {"points.csv", ""}, {"detectable_area.csv", "detect"}, {"accuracy_mm.csv", "accuracy_mm"}};
  for (size_t k = 0; k < r.metric_names.size(); ++k)
    if (r.metric_names[k] == "accuracy_px") {
      files.emplace_back("accuracy_px.csv", "accuracy_px");
      px_metric_ = static_cast<int>(k);
    }
  for (const auto& [name, cell] : files) {
    auto f = std::make_unique<File>();
    f->cell = cell;
    f->path = out_.staged(name);
    f->stream.open(f->path, std::ios::binary);
    f->stream << (cell.empty() ? points_csv_header(r) : matrix_csv_header(r));
    files_.push_back(std::move(f));
  }
  plot_rows_ = plot_indices(r.background.values.size());
  plot_columns_ = plot_indices(r.signal.values.size());
}

void GridWriter::row(size_t ib, const std::vector<golden::EvalPoint>& points) {
  for (auto& f : files_)
    f->stream << (f->cell.empty() ? points_csv_rows(points)
                                  : matrix_csv_row(shape_, shape_.background.values[ib], points, f->cell));
  if (next_plot_row_ >= plot_rows_.size() || plot_rows_[next_plot_row_] != ib) return;
  ++next_plot_row_;
  // A kept cell needs its verdict and the accuracy the map draws, not every metric.
  for (size_t is : plot_columns_) {
    golden::EvalPoint p;
    p.detect = points[is].detect;
    p.accuracy_m = points[is].accuracy_m;
    if (px_metric_ >= 0) p.metrics = {points[is].metrics[static_cast<size_t>(px_metric_)]};
    plot_points_.push_back(std::move(p));
  }
}

golden::EvalResult GridWriter::finish(const golden::EvalResult& ev) {
  for (auto& f : files_) {
    f->stream.close();
    if (!f->stream) throw std::runtime_error(fmt::format("cannot write {}", f->path));
  }
  golden::EvalResult plot = ev;
  plot.signal.values.clear();
  plot.background.values.clear();
  for (size_t is : plot_columns_) plot.signal.values.push_back(ev.signal.values[is]);
  for (size_t ib : plot_rows_) plot.background.values.push_back(ev.background.values[ib]);
  plot.metric_names = px_metric_ >= 0 ? std::vector<std::string>{"accuracy_px"} : std::vector<std::string>{};
  plot.points = std::move(plot_points_);
  return plot;
}

}  // namespace rangesim::app
