// Pairwise and least-squares observed orders, and which runs of an accuracy sweep enter them.
#include "analysis/observed_order.hpp"

#include <algorithm>
#include <cmath>

namespace analysis {

LineFit least_squares_line(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = std::min(x.size(), y.size());
  LineFit fit;
  if (n < 2) return fit;
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    mean_x += x[k] / static_cast<double>(n);
    mean_y += y[k] / static_cast<double>(n);
  }
  double sxy = 0.0, sxx = 0.0;  // centred sums: no cancellation when x is far from 0
  for (std::size_t k = 0; k < n; ++k) {
    sxy += (x[k] - mean_x) * (y[k] - mean_y);
    sxx += (x[k] - mean_x) * (x[k] - mean_x);
  }
  if (!(sxx > 0.0)) return fit;
  fit.slope = sxy / sxx;
  if (n < 3) return fit;
  double residuals = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double r = y[k] - mean_y - fit.slope * (x[k] - mean_x);
    residuals += r * r;
  }
  fit.slope_standard_error = std::sqrt(residuals / static_cast<double>(n - 2) / sxx);
  return fit;
}

ObservedOrder observed_order(std::vector<SweepPoint> points) {
  std::erase_if(points, [](const SweepPoint& p) { return !(p.step > 0.0) || !(p.error_m > 0.0); });
  std::sort(points.begin(), points.end(), [](const SweepPoint& a, const SweepPoint& b) { return a.step > b.step; });
  ObservedOrder order;
  std::vector<double> log_step, log_error;
  for (std::size_t k = 0; k < points.size(); ++k) {
    log_step.push_back(std::log(points[k].step));
    log_error.push_back(std::log(points[k].error_m));
    if (k > 0 && log_step[k - 1] > log_step[k]) {
      order.pairwise.push_back((log_error[k - 1] - log_error[k]) /
                               (log_step[k - 1] - log_step[k]));  // ln(e_k/e_k+1) / ln(h_k/h_k+1)
    }
  }
  const LineFit fit = least_squares_line(log_step, log_error);
  order.fitted = fit.slope;
  order.fitted_standard_error = fit.slope_standard_error;
  order.points = std::move(points);
  return order;
}

std::vector<SweepPoint> order_fit_points(const AccuracyResult& result, sim::IntegratorKind integrator) {
  const bool adaptive = integrator == sim::IntegratorKind::Rk45;
  const auto kind = static_cast<std::size_t>(integrator);
  const double stable_dt = kind < result.stable_dt_s.size() ? result.stable_dt_s[kind] : 0.0;
  std::vector<SweepPoint> points;
  for (const AccuracyRun& run : result.runs) {
    if (run.integrator != integrator || run.status != RunStatus::Ok) continue;
    if (adaptive) {
      points.push_back({run.tolerance, run.rms_error_m});
    } else if (stable_dt > 0.0 && run.dt_s <= kOrderFitStableFraction * stable_dt) {
      points.push_back({run.dt_s, run.rms_error_m});
    }
  }
  return points;
}

}  // namespace analysis
