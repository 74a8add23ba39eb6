// Work-precision output: CSV rows, equal-time ratios by log-log interpolation, the gnuplot script.
#include "analysis/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "analysis/observed_order.hpp"
#include "output/atomic_file.hpp"

namespace analysis {
namespace {

namespace fs = std::filesystem;

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// An integrator's usable runs as (log10 time, log10 error), sorted by time.
struct Curve {
  std::vector<double> log_time, log_error;
};

Curve curve_of(const AccuracyResult& result, sim::IntegratorKind integrator) {
  std::vector<std::pair<double, double>> points;
  for (const AccuracyRun& run : result.runs) {
    if (run.integrator != integrator || run.status != RunStatus::Ok || run.wall_s <= 0.0 || run.rms_error_m <= 0.0) {
      continue;
    }
    points.emplace_back(std::log10(run.wall_s), std::log10(run.rms_error_m));
  }
  std::sort(points.begin(), points.end());
  Curve curve;
  for (const auto& [t, e] : points) {
    curve.log_time.push_back(t);
    curve.log_error.push_back(e);
  }
  return curve;
}

// log10 error at log10 time `t` by linear interpolation; `t` must lie inside the curve's range.
double error_at(const Curve& curve, double t) {
  const auto upper = std::upper_bound(curve.log_time.begin(), curve.log_time.end(), t);
  if (upper == curve.log_time.begin()) return curve.log_error.front();
  if (upper == curve.log_time.end()) return curve.log_error.back();
  const std::size_t i = static_cast<std::size_t>(upper - curve.log_time.begin());
  const double t0 = curve.log_time[i - 1], t1 = curve.log_time[i];
  const double w = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
  return (1.0 - w) * curve.log_error[i - 1] + w * curve.log_error[i];
}

std::vector<sim::IntegratorKind> integrators_in(const AccuracyResult& result) {
  std::vector<sim::IntegratorKind> seen;
  for (const AccuracyRun& run : result.runs) {
    if (std::find(seen.begin(), seen.end(), run.integrator) == seen.end()) seen.push_back(run.integrator);
  }
  return seen;
}

std::string gnuplot_script(const AccuracyResult& result, const fs::path& png) {
  std::ostringstream gp;
  gp << "# Work-precision plot of softbody's integrators (written by softbody bench accuracy).\n"
     << "set terminal pngcairo size 960,680 enhanced font 'Sans,11'\n"
     << "set output '" << png.filename().string() << "'\n"
     << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\n"
     << "set xlabel 'RMS vertex position error over all frames [m]'\n"
     << "set ylabel 'wall time of the run (stepping only) [s]'\n"
     << "set key outside right top\n"
     << "set title \"" << result.scene_name << ": " << result.vertices << " vertices, " << result.duration_s
     << " s simulated; reference " << result.reference.method << ", dt " << format("%.2g", result.reference.dt_s)
     << " s\" noenhanced\n"  // a scene name's _ is no subscript
     << "set arrow from " << format("%.6g", std::max(result.reference.uncertainty_m, 1e-16)) << ", graph 0 to "
     << format("%.6g", std::max(result.reference.uncertainty_m, 1e-16))
     << ", graph 1 nohead dashtype 2 lc rgb 'gray40'\n"
     << "set label 'reference uncertainty' at " << format("%.6g", std::max(result.reference.uncertainty_m, 1e-16))
     << ", graph 0.04 offset 0.5,0 font ',9' tc rgb 'gray30'\n";
  double smallest = result.reference.uncertainty_m;
  for (const AccuracyRun& run : result.runs) {
    if (run.status == RunStatus::Ok) smallest = std::min(smallest, run.rms_error_m);
  }
  gp << "set xrange [" << format("%.6g", std::max(smallest, 1e-16) / 3.0) << ":*]\n";
  std::vector<sim::IntegratorKind> plotted;
  for (sim::IntegratorKind integrator : integrators_in(result)) {
    if (!curve_of(result, integrator).log_time.empty()) plotted.push_back(integrator);
  }
  gp << "plot ";
  for (std::size_t i = 0; i < plotted.size(); ++i) {
    gp << (i ? ", " : "") << "'-' using 1:2 with linespoints lw 2 pt " << (i + 4) << " title '"
       << sim::to_string(plotted[i]) << "'";
  }
  gp << "\n";
  for (sim::IntegratorKind integrator : plotted) {
    for (const AccuracyRun& run : result.runs) {
      if (run.integrator != integrator || run.status != RunStatus::Ok) continue;
      gp << format("%.6e", run.rms_error_m) << " " << format("%.6e", run.wall_s) << "\n";
    }
    gp << "e\n";
  }
  return gp.str();
}

}  // namespace

std::string accuracy_csv(const AccuracyResult& result) {
  std::ostringstream csv;
  csv << kAccuracyCsvHeader << "\n";
  for (const AccuracyRun& run : result.runs) {
    const bool finite = run.status != RunStatus::Diverged;
    csv << sim::to_string(run.integrator) << "," << format("%.6e", run.dt_s) << ","
        << (run.tolerance > 0.0 ? format("%.1e", run.tolerance) : "") << "," << run.steps << "," << run.rejected_steps
        << "," << format("%.6f", run.wall_s) << "," << (finite ? format("%.6e", run.rms_error_m) : "") << ","
        << (finite ? format("%.6e", run.final_error_m) : "") << "," << to_string(run.status) << "\n";
  }
  return csv.str();
}

std::vector<EqualTimeRatio> equal_time_ratios(const AccuracyResult& result, sim::IntegratorKind baseline) {
  const Curve base = curve_of(result, baseline);
  std::vector<EqualTimeRatio> ratios;
  for (sim::IntegratorKind method : integrators_in(result)) {
    if (method == baseline) continue;
    const Curve other = curve_of(result, method);
    EqualTimeRatio ratio;
    ratio.method = method;
    if (base.log_time.empty() || other.log_time.empty()) {
      ratios.push_back(ratio);
      continue;
    }
    const double lo = std::max(base.log_time.front(), other.log_time.front());
    const double hi = std::min(base.log_time.back(), other.log_time.back());
    std::vector<double> times;
    for (const Curve* c : {&base, &other}) {
      for (double t : c->log_time) {
        if (t >= lo && t <= hi) times.push_back(t);
      }
    }
    double log_sum = 0.0;
    ratio.ratio_min = INFINITY;
    for (double t : times) {
      const double log_ratio = error_at(base, t) - error_at(other, t);
      log_sum += log_ratio;
      ratio.ratio_min = std::min(ratio.ratio_min, std::pow(10.0, log_ratio));
      ratio.ratio_max = std::max(ratio.ratio_max, std::pow(10.0, log_ratio));
    }
    ratio.samples = static_cast<int>(times.size());
    if (ratio.samples > 0) {
      ratio.time_lo_s = std::pow(10.0, lo);
      ratio.time_hi_s = std::pow(10.0, hi);
      ratio.ratio_geomean = std::pow(10.0, log_sum / ratio.samples);
    } else {
      ratio.ratio_min = 0.0;
    }
    ratios.push_back(ratio);
  }
  return ratios;
}

namespace {

// "    observed order over 3 of 4 runs ok (...): pairwise 4.23, 3.20; least squares 4.05 +- 0.40" (rk45: the
// exponent of error ~ tolerance^p).
std::string order_line(const AccuracyResult& result, sim::IntegratorKind integrator, int runs_ok) {
  const ObservedOrder order = observed_order(order_fit_points(result, integrator));
  const bool adaptive = integrator == sim::IntegratorKind::Rk45;
  std::ostringstream out;
  out << "    " << (adaptive ? "error ~ tolerance^p" : "observed order") << " over " << order.points.size() << " of "
      << runs_ok << " runs ok (error >= " << format("%.3g", result.floor_factor) << "x the reference's uncertainty";
  if (!adaptive) {
    out << ", dt <= " << format("%.2g", kOrderFitStableFraction) << " x its estimated stable dt "
        << format("%.3g", result.stable_dt_s[static_cast<std::size_t>(integrator)]) << " s";
  }
  out << ")";
  if (order.points.size() < 2) return out.str() + ": too few to fit\n";
  out << ": pairwise";
  for (std::size_t k = 0; k < order.pairwise.size(); ++k) out << (k ? ", " : " ") << format("%.2f", order.pairwise[k]);
  out << "; least squares " << format("%.2f", order.fitted);
  if (std::isfinite(order.fitted_standard_error)) out << " +- " << format("%.2f", order.fitted_standard_error);
  out << "\n";
  return out.str();
}

}  // namespace

std::string accuracy_summary(const AccuracyResult& result) {
  std::ostringstream out;
  out << "scene " << result.scene_name << ": " << result.vertices << " vertices, " << result.duration_s
      << " s simulated at " << result.fps << " fps; body size (RMS radius) " << format("%.3g", result.body_size_m)
      << " m\n";
  out << "reference: " << result.reference.method << " at dt = " << format("%.3g", result.reference.dt_s)
      << " s; RMS distance to the same at twice the step: " << format("%.2e", result.reference.uncertainty_m) << " m";
  double smallest = INFINITY;
  for (const AccuracyRun& run : result.runs) {
    if (run.status == RunStatus::Ok) smallest = std::min(smallest, run.rms_error_m);
  }
  if (std::isfinite(smallest)) {
    out << " (smallest error measured " << format("%.2e", smallest)
        << " m: " << format("%.0f", smallest / std::max(result.reference.uncertainty_m, 1e-300)) << "x above it"
        << (smallest < 100.0 * result.reference.uncertainty_m ? "; NOT converged enough: below 100x" : "") << ")";
  }
  out << "\n";
  for (sim::IntegratorKind integrator : integrators_in(result)) {
    int ok = 0, failed = 0, above_stable = 0;
    const AccuracyRun* best = nullptr;
    for (const AccuracyRun& run : result.runs) {
      if (run.integrator != integrator) continue;
      if (run.above_stable_dt) ++above_stable;
      if (run.status != RunStatus::Ok) {
        ++failed;
        continue;
      }
      ++ok;
      if (best == nullptr || run.rms_error_m < best->rms_error_m) best = &run;
    }
    out << "  " << sim::to_string(integrator) << ": " << ok << " runs ok, " << failed
        << " diverged, blown up or at the reference's floor";
    if (best != nullptr) {
      out << "; smallest error " << format("%.2e", best->rms_error_m) << " m in " << format("%.3f", best->wall_s)
          << " s";
    }
    if (above_stable > 0) {
      out << "; " << above_stable << " at a dt above its estimated stable dt "
          << format("%.3g", result.stable_dt_s[static_cast<std::size_t>(integrator)])
          << " s (such a run may stay bounded without converging: leave it out of an order fit)";
    }
    out << "\n" << order_line(result, integrator, ok);
  }
  out << "error of euler / error of method at equal wall time (log-log interpolation):\n";
  for (const EqualTimeRatio& r : equal_time_ratios(result, sim::IntegratorKind::Euler)) {
    out << "  " << sim::to_string(r.method) << ": ";
    if (r.samples == 0) {
      out << "no shared time range with euler\n";
      continue;
    }
    out << "geometric mean " << format("%.3g", r.ratio_geomean) << ", range " << format("%.3g", r.ratio_min) << " .. "
        << format("%.3g", r.ratio_max) << " over " << format("%.3g", r.time_lo_s) << " .. "
        << format("%.3g", r.time_hi_s) << " s (" << r.samples << " samples)\n";
  }
  out << "benchmark wall time: " << format("%.1f", result.total_wall_s) << " s\n";
  return out.str();
}

std::vector<fs::path> write_work_precision(const AccuracyResult& result, const fs::path& dir) {
  fs::create_directories(dir);
  const std::string stem = "work_precision_" + result.scene_name;
  const fs::path csv = dir / (stem + ".csv"), txt = dir / (stem + ".txt"), gp = dir / (stem + ".gp"),
                 png = dir / (stem + ".png");
  output::write_file_atomically(csv, accuracy_csv(result));
  output::write_file_atomically(txt, accuracy_summary(result));
  output::write_file_atomically(gp, gnuplot_script(result, png));
  const std::string command = "cd '" + dir.string() + "' && gnuplot '" + gp.filename().string() + "'";
  if (std::system(command.c_str()) != 0) {
    throw std::runtime_error("gnuplot failed on " + gp.string() +
                             " (is gnuplot installed? scripts/setup installs gnuplot-nox)");
  }
  return {csv, txt, gp, png};
}

}  // namespace analysis
