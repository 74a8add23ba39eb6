// Observed convergence orders of an accuracy sweep: the pairwise orders of successive runs and a least-squares fit.
#pragma once

#include <limits>
#include <span>
#include <vector>

#include "analysis/accuracy.hpp"

namespace analysis {

// One run of a sweep: its step h (rk45: its tolerance) and its error e against the reference.
struct SweepPoint {
  double step = 0.0;
  double error_m = 0.0;
};

struct ObservedOrder {
  std::vector<SweepPoint> points;  // the runs fitted, largest step first
  // Successive runs: p_k = ln(e_k / e_{k+1}) / ln(h_k / h_{k+1}) (the Richardson estimate, e ≈ C h^p).
  std::vector<double> pairwise;
  // The least-squares slope of ln e against ln h over every point (NaN with fewer than two): one C for all, so
  // an error constant that wobbles from run to run (a contact event falling at a different place in its step)
  // averages out instead of swinging the pairwise orders.
  double fitted = std::numeric_limits<double>::quiet_NaN();
  // The fit's standard error, √(Σ residual² / (n − 2) / Σ (ln h − mean)²) (NaN with fewer than three points): how
  // far the scatter of the points about the line leaves the slope uncertain.
  double fitted_standard_error = std::numeric_limits<double>::quiet_NaN();
};

// Least-squares line of y against x: its slope and the slope's standard error (NaN where undefined: fewer than
// two distinct x, fewer than three points).
struct LineFit {
  double slope = std::numeric_limits<double>::quiet_NaN();
  double slope_standard_error = std::numeric_limits<double>::quiet_NaN();
};
LineFit least_squares_line(std::span<const double> x, std::span<const double> y);

// Pairwise and fitted orders of `points` (in any order; points with a non-positive step or error are dropped).
ObservedOrder observed_order(std::vector<SweepPoint> points);

// A fixed-step run counts towards its method's order only well inside the stability region: at most this
// fraction of the method's estimated stable dt (sim/step/stability.hpp). Nearer the edge the error can grow faster
// than h^p (a mode's amplification factor is far from e^{λh}), or stay bounded without converging (the smooth
// contact's friction is bounded by μN), and the fit reads too high or too low.
inline constexpr double kOrderFitStableFraction = 0.5;

// The runs of `integrator` in `result` that measure its order: status ok (so the error is at least floor_factor
// times the reference's uncertainty, finite and below the body's size) and, at fixed steps, dt at most
// kOrderFitStableFraction of its stable dt. rk45's points are (tolerance, error): their slope is the exponent of
// error ∝ tolerance^p.
std::vector<SweepPoint> order_fit_points(const AccuracyResult& result, sim::IntegratorKind integrator);

}  // namespace analysis
