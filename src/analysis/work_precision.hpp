// Reading and writing an accuracy benchmark: the CSV, the equal-time comparison, the gnuplot figure.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"

namespace analysis {

// Columns of the benchmark CSV, one row per run.
inline constexpr const char* kAccuracyCsvHeader =
    "integrator,dt,tolerance,steps,rejected_steps,wall_s,rms_error,final_error,status";

// The CSV text (header + rows; errors in m, times in s; empty error fields for diverged runs).
std::string accuracy_csv(const AccuracyResult& result);

// Error of `method` against `baseline` at equal wall time: both work-precision curves interpolated
// linearly in log(time)–log(error), compared at every run time inside both curves' time ranges.
struct EqualTimeRatio {
  sim::IntegratorKind method = sim::IntegratorKind::Euler;
  int samples = 0;                          // 0: the two curves share no time range
  double time_lo_s = 0.0, time_hi_s = 0.0;  // the shared range
  double ratio_min = 0.0;                   // baseline error / method error, smallest over the samples
  double ratio_max = 0.0;
  double ratio_geomean = 0.0;
};
std::vector<EqualTimeRatio> equal_time_ratios(const AccuracyResult& result, sim::IntegratorKind baseline);

// A human summary: reference check, every integrator's best error, the equal-time ratios against euler.
std::string accuracy_summary(const AccuracyResult& result);

// Writes `<dir>/work_precision_<scene>.{csv,txt,gp,png}`; the PNG is drawn by gnuplot (pngcairo, no
// display). Returns the paths written. Throws std::runtime_error when gnuplot fails or is missing.
std::vector<std::filesystem::path> write_work_precision(const AccuracyResult& result, const std::filesystem::path& dir);

}  // namespace analysis
