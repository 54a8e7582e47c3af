#pragma once
// Run time against error for each sensor (docs/bench.md): every fidelity setting of
// `rangesim simulate` (harness kernel / SystemC, event skipping, sparse, aggregation, noise,
// frames) run as a child process of this binary on the sensor's example scene; wall time of the
// run and the rms range error against the scene's exact ground truth. Rows not dominated in
// (time, error) within their sensor are marked Pareto-optimal.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/sweep_journal.h"

namespace rangesim::app::bench {

// One fidelity setting of a sensor: `rangesim simulate <sensor> --scene scenes/<scene> <extra>`.
// Each sensor lists its own in app/bench/pareto_<sensor>.cpp (its bench settings).
struct ParetoSetting {
  std::string sensor, scene, setting, harness;  // harness: kernel, systemc
  std::vector<std::string> extra;
};

struct ParetoRow {
  std::string sensor, setting, harness;  // harness: kernel, systemc, rtl
  std::vector<std::string> args;         // rangesim simulate arguments after the sensor
  long long frames = 0;                  // frames simulated
  double wall_s = 0;                     // wall time of the child process
  double cpu_s = 0;                      // CPU time of the child process (the Pareto axis)
  double error_m = 0;                    // rms range error against the ground truth (NaN: none detected)
  long long points = 0;                  // points detected (error sample size)
  bool pareto = false;                   // not dominated within the sensor
  std::string note;
};

// Runs every setting; scratch_dir receives the children's output folders. With a journal, rows
// it holds (by setting index) are taken from it and each new row is appended when it finishes.
std::vector<ParetoRow> run_pareto(bool quick, const std::string& scratch_dir, SweepJournal* journal = nullptr);
// One row as a journal record and back (exact: doubles round-trip through JSON).
std::string pareto_row_record(const ParetoRow& r);
ParetoRow pareto_row_from_record(const std::string& record);
void mark_pareto(std::vector<ParetoRow>& rows);
std::string pareto_markdown(const std::vector<ParetoRow>& rows);
std::string pareto_csv(const std::vector<ParetoRow>& rows);
nlohmann::json pareto_json(const std::vector<ParetoRow>& rows);
// gnuplot script for pareto.{png,svg} from the data file `data_path` (written by the caller).
std::string pareto_gnuplot_data(const std::vector<ParetoRow>& rows);
// The sensors of the rows in order of first appearance: data block i of pareto_gnuplot_data.
std::vector<std::string> pareto_sensors(const std::vector<ParetoRow>& rows);

}  // namespace rangesim::app::bench
