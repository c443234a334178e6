// SPDX-License-Identifier: MIT
#include "diagnose/effect_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "core/errors.hpp"
#include "sim/effect_table.hpp"
#include "sim/effects.hpp"

namespace acore {

namespace {

constexpr double kTempRef = 25.0;
// excess_noise is rejected when more than this share of its variance is correlated sample to
// sample.
constexpr double kWhiteShare = 0.2;

// Per-channel columns of one parameter: col[c][i] = d channel_c(i) / d parameter.
using Column = std::vector<std::vector<double>>;

int nsignals(const Recording& r) { return r.channels == 4 ? 4 : 2; }

// The noise-decoupled signals of a channel vector (see the header).
inline void to_signals(const Recording& r, size_t i, const std::function<double(int, size_t)>& ch,
                       double* s) {
  if (r.channels == 4) {
    s[0] = ch(0, i) - ch(2, i);
    s[1] = ch(1, i) - ch(3, i);
    s[2] = 0.5 * (ch(0, i) + ch(2, i));
    s[3] = 0.5 * (ch(1, i) + ch(3, i));
  } else {
    s[0] = ch(0, i);
    s[1] = ch(1, i);
  }
}

double sq(double v) { return v * v; }

// Weighted least squares over signals: returns phi and -2 log L of the fit.
std::pair<Eigen::VectorXd, double> solve_linear(const FitProblem& fp, const Recording& base,
                                                const std::vector<Column>& cols) {
  const Recording& real = *fp.real;
  const size_t n = real.size();
  const int S = nsignals(real);
  const int k = static_cast<int>(cols.size());
  Eigen::MatrixXd A(static_cast<Eigen::Index>(n) * S, k);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n) * S);
  double s[4], t[4];
  for (size_t i = 0; i < n; ++i) {
    to_signals(
        real, i, [&](int c, size_t j) { return real.ch[c][j] - base.ch[c][j]; }, s);
    for (int q = 0; q < S; ++q) b(i * S + q) = s[q] / fp.signal_sigma[q];
    for (int p = 0; p < k; ++p) {
      to_signals(
          real, i, [&](int c, size_t j) { return cols[p][c].empty() ? 0.0 : cols[p][c][j]; }, t);
      for (int q = 0; q < S; ++q) A(i * S + q, p) = t[q] / fp.signal_sigma[q];
    }
  }
  const Eigen::VectorXd phi = A.colPivHouseholderQr().solve(b);
  return {phi, (b - A * phi).squaredNorm()};
}

// Channel c of the model evaluated at shifted mechanical angles, minus at the true ones (which
// fp.predicted holds).
std::vector<double> angle_shift(const FitProblem& fp, int c,
                                const std::function<double(size_t)>& delta) {
  const Recording& real = *fp.real;
  std::vector<double> v(real.size());
  for (size_t i = 0; i < real.size(); ++i) {
    const double d = delta(i);
    v[i] = d == 0 ? 0.0 : fp.model->sensor.value(c, real.theta_ref[i] + d) - fp.predicted.ch[c][i];
  }
  return v;
}

// Index of a channel around the circle (its 90-degree position): c1..c4 -> 0..3; sin, cos -> 0, 1.
int position(int c) { return c; }

// The factor on the field (later field scalings of a set, see fit_effect), 1 without one.
double scale_at(const std::vector<double>* scale, size_t i) { return scale ? (*scale)[i] : 1.0; }

// The field part of a prediction: the channel less the model's electrical offset (its constant
// Fourier term), which field changes (amplitude, eccentricity) do not scale.
double field_part(const FitProblem& fp, const Recording& pred, int c, size_t i) {
  return pred.ch[c][i] - fp.model->sensor.coef[c][0];
}

}  // namespace

const std::vector<std::string>& fittable_effects() { return effect_names(); }

namespace {
constexpr double kSpeedSpread = 0.2;  // a fifth (effect_fit.hpp, speed_changes)
}  // namespace

bool speed_changes(const FitProblem& fp) {
  std::vector<double> w = fp.omega;
  if (w.size() < 3) return false;
  std::sort(w.begin(), w.end());
  // Percentiles, not extremes: a wrapped reference jumps by a turn in one sample.
  auto at = [&](double q) { return w[static_cast<size_t>(q * static_cast<double>(w.size() - 1))]; };
  if (at(0.05) < 0 && at(0.95) > 0) return true;
  const double mid = std::fabs(at(0.5));
  return at(0.95) - at(0.05) >= kSpeedSpread * mid;
}

FitProblem make_fit_problem(const GapModel& m, const Recording& real) {
  FitProblem fp;
  fp.model = &m;
  fp.real = &real;
  fp.predicted = m.sensor.resample(real);
  fp.omega = angular_velocity(real);
  fp.basis = make_gap_basis(real);
  if (real.has_temp())
    for (double t : real.temp) fp.dtemp.push_back(t - kTempRef);
  fp.deriv.resize(real.channels);
  for (int c = 0; c < real.channels; ++c) {
    fp.deriv[c].resize(real.size());
    for (size_t i = 0; i < real.size(); ++i)
      fp.deriv[c][i] = m.sensor.derivative(c, real.theta_ref[i]);
  }
  // Noise per signal from the simulation's fit residual statistics.
  const auto& sg = m.sensor.noise_sigma;
  const double floor = 1e-5 * std::max(std::fabs(m.est.amp[0]), std::fabs(m.est.amp[1]));
  if (real.channels == 4) {
    const auto& rho = m.sensor.noise_corr;
    const double v13 = sq(sg[0]) + sq(sg[2]) - 2 * rho[0] * sg[0] * sg[2];
    const double v24 = sq(sg[1]) + sq(sg[3]) - 2 * rho[1] * sg[1] * sg[3];
    const double w13 = 0.25 * (sq(sg[0]) + sq(sg[2]) + 2 * rho[0] * sg[0] * sg[2]);
    const double w24 = 0.25 * (sq(sg[1]) + sq(sg[3]) + 2 * rho[1] * sg[1] * sg[3]);
    for (double v : {v13, v24, w13, w24})
      fp.signal_sigma.push_back(std::max(floor, std::sqrt(std::max(0.0, v))));
  } else {
    fp.signal_sigma = {std::max(floor, sg[0]), std::max(floor, sg[1])};
  }
  return fp;
}

namespace {
// How much of a channel's extra white-noise variance each signal carries: c1 - c3 two channels',
// (c1 + c3)/2 a quarter of two; sin, cos one.
double signal_weight(const Recording& r, int q) {
  return r.channels == 4 ? (q < 2 ? 2.0 : 0.5) : 1.0;
}
}  // namespace

double neg2_log_likelihood(const FitProblem& fp, const Recording& pred, double extra_sigma) {
  const Recording& real = *fp.real;
  const int S = nsignals(real);
  double s[4], rss[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < real.size(); ++i) {
    to_signals(
        real, i, [&](int c, size_t j) { return real.ch[c][j] - pred.ch[c][j]; }, s);
    for (int q = 0; q < S; ++q) rss[q] += s[q] * s[q];
  }
  // Gaussian, known variance per signal: sum r^2 / v + N ln(v / sigma^2) (0 without extra noise).
  double total = 0;
  const double n = static_cast<double>(real.size());
  for (int q = 0; q < S; ++q) {
    const double s2 = sq(fp.signal_sigma[q]),
                 v = s2 + signal_weight(real, q) * extra_sigma * extra_sigma;
    total += rss[q] / v + n * std::log(v / s2);
  }
  return total;
}

namespace {

// -2 log L (known variance, no extra noise) of the signals the angle is computed from: c1 - c3 and
// c2 - c4 on four channels (their common modes left out), sin and cos on two.
double pair_neg2_log_likelihood(const FitProblem& fp, const Recording& pred) {
  const Recording& real = *fp.real;
  double s[4], total = 0;
  for (size_t i = 0; i < real.size(); ++i) {
    to_signals(
        real, i, [&](int c, size_t j) { return real.ch[c][j] - pred.ch[c][j]; }, s);
    for (int q = 0; q < 2; ++q) total += sq(s[q] / fp.signal_sigma[q]);
  }
  return total;
}

// How much worse than the best group a phase error's group may fit the pairs (in -2 log L, the
// scale of the diagnosis's dBIC threshold) and still be chosen for its fit of every signal.
constexpr double kPairTolerance = 10;

// A fitted effect's parameters; its prediction comes from predict_effect(), the one place that
// applies an effect, so fitting and carrying the effect to a holdout cannot disagree.
struct Fitted {
  ParamList params;
  int k = 0;
  bool applicable = true;  // false: the recording cannot show this effect (drift without temp, ...)
  std::string
      rejected;  // why the effect's own assumptions fail on this recording (empty: they hold)
};

std::string chan_name(const Recording& r, int c) { return effect_channel_name(r.channels, c); }

// Every fit takes the same arguments (the fitter table below): the problem, the prediction it
// fits on top of, the extra white noise that prediction carries, and the factor later field
// scalings put on the angle change it causes (nullptr: 1).
using FieldScale = const std::vector<double>*;

Fitted fit_offset(const FitProblem& fp, const Recording& base, double, FieldScale) {
  const Recording& r = *fp.real;
  std::vector<Column> cols;
  for (int c = 0; c < r.channels; ++c) {
    Column col(r.channels);
    col[c].assign(r.size(), 1.0);
    cols.push_back(col);
  }
  const auto [phi, _] = solve_linear(fp, base, cols);
  Fitted f;
  for (int c = 0; c < r.channels; ++c) f.params.push_back({"offset_" + chan_name(r, c), phi(c)});
  f.k = r.channels;
  return f;
}

Fitted fit_gain_mismatch(const FitProblem& fp, const Recording& base, double, FieldScale) {
  const Recording& r = *fp.real;
  std::vector<Column> cols;
  for (int c = 0; c < r.channels; ++c) {
    Column col(r.channels);
    col[c] = base.ch[c];
    cols.push_back(col);
  }
  const auto [phi, _] = solve_linear(fp, base, cols);
  Fitted f;
  for (int c = 0; c < r.channels; ++c)
    f.params.push_back({"gain_" + chan_name(r, c), 1.0 + phi(c)});
  f.k = r.channels;
  return f;
}

// Angle-shift effects: channel c sees theta + delta_c(i) with delta linear in the parameters.
// basis[p](c, i) is d delta_c(i) / d phi_p; the fit is linearized (predict_effect is exact).
Fitted fit_angle_shift(const FitProblem& fp, const Recording& base,
                       const std::vector<std::function<double(int, size_t)>>& basis,
                       const std::vector<double>* scale) {
  const Recording& r = *fp.real;
  std::vector<Column> cols;
  for (const auto& b : basis) {
    Column col(r.channels);
    for (int c = 0; c < r.channels; ++c) {
      col[c].resize(r.size());
      for (size_t i = 0; i < r.size(); ++i)
        col[c][i] = scale_at(scale, i) * fp.deriv[c][i] * b(c, i);
    }
    cols.push_back(col);
  }
  const auto [phi, _] = solve_linear(fp, base, cols);
  Fitted f;
  for (size_t p = 0; p < basis.size(); ++p)
    f.params.push_back({"", phi(static_cast<Eigen::Index>(p))});
  f.k = static_cast<int>(basis.size());
  return f;
}

// zero_offset: every channel sees theta + z. A reference zero may be off by anything up to half a
// turn, far beyond the linearization of fit_angle_shift, so z starts at the circular mean of the
// electrical-angle difference atan2(d13, d24) (atan2(sin, cos)) of real minus base, over the
// periodicity and the sense in which the electrical angle turns, and is refined by Gauss-Newton on
// the exact shift (the same model(theta + z) - model(theta) predict_effect applies).
Fitted fit_zero_offset(const FitProblem& fp, const Recording& base, double, FieldScale scale) {
  const Recording& r = *fp.real;
  const size_t n = r.size();
  auto elec = [&](const Recording& x, size_t i) {
    return r.channels == 4 ? std::atan2(x.ch[0][i] - x.ch[2][i], x.ch[1][i] - x.ch[3][i])
                           : std::atan2(x.ch[0][i], x.ch[1][i]);
  };
  // cs, sn: the circular mean's sums; turn: the model's d elec / d theta summed (its sign is the
  // sense in which the electrical angle turns with theta).
  double cs = 0, sn = 0, turn = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = elec(r, i) - elec(base, i);
    cs += std::cos(d);
    sn += std::sin(d);
    const auto& pr = fp.predicted.ch;
    const auto& dv = fp.deriv;
    const double x = r.channels == 4 ? pr[1][i] - pr[3][i] : pr[1][i],
                 y = r.channels == 4 ? pr[0][i] - pr[2][i] : pr[0][i],
                 dx = r.channels == 4 ? dv[1][i] - dv[3][i] : dv[1][i],
                 dy = r.channels == 4 ? dv[0][i] - dv[2][i] : dv[0][i];
    turn += (x * dy - y * dx) / std::max(x * x + y * y, 1e-300);
  }
  const double sense = turn >= 0 ? 1.0 : -1.0;
  double z = sense * std::atan2(sn, cs) / fp.model->periodicity;
  for (int it = 0; it < 3; ++it) {
    Recording shifted = base;
    Column col(r.channels);
    for (int c = 0; c < r.channels; ++c) {
      col[c].resize(n);
      for (size_t i = 0; i < n; ++i) {
        const double th = r.theta_ref[i] + z;
        shifted.ch[c][i] +=
            scale_at(scale, i) * (fp.model->sensor.value(c, th) - fp.predicted.ch[c][i]);
        col[c][i] = scale_at(scale, i) * fp.model->sensor.derivative(c, th);
      }
    }
    z += solve_linear(fp, shifted, {col}).first(0);
  }
  Fitted f;
  f.params = {{"zero_rad", std::remainder(z, 2 * M_PI)}};
  f.k = 1;
  return f;
}

bool sine_pair(const Recording& r, int c) { return r.channels == 4 ? (c == 0 || c == 2) : c == 0; }

// amplitude: every channel's field part scaled by 1 + phi.
Fitted fit_amplitude(const FitProblem& fp, const Recording& base, double, FieldScale) {
  const Recording& r = *fp.real;
  Column col(r.channels);
  for (int c = 0; c < r.channels; ++c) {
    col[c].resize(r.size());
    for (size_t i = 0; i < r.size(); ++i) col[c][i] = field_part(fp, base, c, i);
  }
  const auto [phi, _] = solve_linear(fp, base, {col});
  Fitted f;
  f.params = {{"scale", 1.0 + phi(0)}};
  f.k = 1;
  return f;
}

// eccentricity: theta + u sin(theta) - v cos(theta) (u = eps cos phi0, v = eps sin phi0) and the
// field part times 1 + a cos(theta) + b sin(theta) (a = m cos phi_m, b = m sin phi_m).
Fitted fit_eccentricity(const FitProblem& fp, const Recording& base, double, FieldScale scale) {
  const Recording& r = *fp.real;
  std::vector<Column> cols(4, Column(r.channels));
  for (int c = 0; c < r.channels; ++c) {
    for (auto& col : cols) col[c].resize(r.size());
    for (size_t i = 0; i < r.size(); ++i) {
      const double th = r.theta_ref[i], s = std::sin(th), co = std::cos(th);
      const double d = scale_at(scale, i) * fp.deriv[c][i], fld = field_part(fp, base, c, i);
      cols[0][c][i] = d * s;
      cols[1][c][i] = -d * co;
      cols[2][c][i] = fld * co;
      cols[3][c][i] = fld * s;
    }
  }
  const auto [phi, _] = solve_linear(fp, base, cols);
  Fitted f;
  f.params = {{"epsilon_rad", std::hypot(phi(0), phi(1))},
              {"phi0_rad", std::atan2(phi(1), phi(0))},
              {"am_depth", std::hypot(phi(2), phi(3))},
              {"am_phase_rad", std::atan2(phi(3), phi(2))}};
  f.k = 4;
  return f;
}

// phase_error: one group of channels sees the electrical angle + delta. The groups a placement or
// orthogonality error moves: the sine pair, the cosine pair, or (four channels) one plate. The best
// by likelihood is kept; the choice counts as a parameter (k = 2), as a harmonic's order does.
// Only a plate that also fits the pairs (c1 - c3, c2 - c4, what the angle sees) is a candidate:
// a plate ring off the shaft axis turns opposite plates by opposite angles, which moves the
// common modes strongly and the pairs' phases only at second order; one plate fitted to its
// pair's common mode would then make the angle gap worse than no shift at all.
Fitted fit_phase_error(const FitProblem& fp, const Recording& base, double, FieldScale scale) {
  const Recording& r = *fp.real;
  const int p = fp.model->periodicity;
  struct Group {
    std::string param;
    std::function<bool(int)> moves;
  };
  std::vector<Group> groups = {{"delta_rad", [&](int c) { return sine_pair(r, c); }},
                               {"delta_cos_rad", [&](int c) { return !sine_pair(r, c); }}};
  if (r.channels == 4)
    for (int k = 0; k < 4; ++k)
      groups.push_back({"phase_" + effect_channel_name(4, k), [k](int c) { return c == k; }});
  struct Tried {
    double delta, l, l_pairs;
  };
  std::vector<Tried> tried;
  double best_pairs = std::numeric_limits<double>::infinity();
  for (const Group& g : groups) {
    Fitted f = fit_angle_shift(fp, base,
                               {[&](int c, size_t) { return g.moves(c) ? 1.0 / p : 0.0; }}, scale);
    const double delta = f.params[0].second;
    Recording pred = base;
    for (int c = 0; c < r.channels; ++c) {
      if (!g.moves(c)) continue;
      const auto add = angle_shift(fp, c, [&](size_t) { return delta / p; });
      for (size_t i = 0; i < r.size(); ++i) pred.ch[c][i] += scale_at(scale, i) * add[i];
    }
    const double lp = pair_neg2_log_likelihood(fp, pred);
    tried.push_back({delta, neg2_log_likelihood(fp, pred), lp});
    best_pairs = std::min(best_pairs, lp);
  }
  Fitted best;
  double best_l = std::numeric_limits<double>::infinity();
  for (size_t q = 0; q < groups.size(); ++q) {
    if (tried[q].l_pairs > best_pairs + kPairTolerance || tried[q].l >= best_l) continue;
    best_l = tried[q].l;
    best.params = effect_spec(EffectId::phase_error).defaults(r.channels);
    for (auto& kv : best.params)
      if (kv.first == groups[q].param) kv.second = tried[q].delta;
    best.k = 2;
  }
  return best;
}

Fitted fit_harmonic(const FitProblem& fp, const Recording& base, double, FieldScale) {
  const Recording& r = *fp.real;
  const int p = fp.model->periodicity;
  Fitted best;
  double best_l = 1e300;
  for (int n = 2; n <= 9; ++n) {
    // On four channels an even order is the same on opposite plates (n·π apart): it cancels in
    // c1 - c3 and c2 - c4 and never reaches the angle. Fitted, it would pick the order by the
    // common mode alone: a magnet off the shaft axis adds a large 2nd harmonic there, common to
    // opposite plates, beside the 3rd (a 4th-order angle error) that carries the gap.
    if (r.channels == 4 && n % 2 == 0) continue;
    Column cc(r.channels), cs(r.channels);
    for (int c = 0; c < r.channels; ++c) {
      cc[c].resize(r.size());
      cs[c].resize(r.size());
      for (size_t i = 0; i < r.size(); ++i) {
        const double a = n * (p * r.theta_ref[i] + position(c) * M_PI / 2);
        cc[c][i] = std::cos(a);
        cs[c][i] = std::sin(a);
      }
    }
    // With a common scale of every channel's field part as a nuisance: a compressing nonlinearity
    // (x - a x^3) shrinks the fundamental by 3a/4 along with its 3rd harmonic, and that scale,
    // unmodelled, would decide the order and bias the amplitude. It is not part of the effect
    // (atan2 never sees it; `amplitude` names it when it is the gap).
    Column scale(r.channels);
    for (int c = 0; c < r.channels; ++c) {
      scale[c].resize(r.size());
      for (size_t i = 0; i < r.size(); ++i) scale[c][i] = field_part(fp, base, c, i);
    }
    const auto [phi, l] = solve_linear(fp, base, {cc, cs, scale});
    if (l < best_l) {
      best_l = l;
      best = Fitted{};
      // amplitude * sin(a + phase) = amplitude cos(phase) sin a + amplitude sin(phase) cos a
      const double amp = std::hypot(phi(0), phi(1)), phase = std::atan2(phi(0), phi(1));
      best.params = {{"order", n}, {"amplitude", amp}, {"phase_rad", phase}};
      best.k = 3;  // order, amplitude, phase
    }
  }
  return best;
}

Fitted fit_drift(const FitProblem& fp, const Recording& base, double, FieldScale) {
  const Recording& r = *fp.real;
  std::vector<Column> cols;
  for (int c = 0; c < r.channels; ++c) {
    Column co(r.channels), cg(r.channels);
    co[c] = fp.dtemp;
    cg[c].resize(r.size());
    for (size_t i = 0; i < r.size(); ++i) cg[c][i] = fp.dtemp[i] * base.ch[c][i];
    cols.push_back(co);
    cols.push_back(cg);
  }
  const auto [phi, _] = solve_linear(fp, base, cols);
  Fitted f;
  for (int c = 0; c < r.channels; ++c) {
    f.params.push_back({"offset_per_C_" + chan_name(r, c), phi(2 * c)});
    f.params.push_back({"gain_per_C_" + chan_name(r, c), phi(2 * c + 1)});
  }
  f.k = 2 * r.channels;
  return f;
}

// channel_skew: channel k sampled at t + tau_k: theta + omega tau_k, one time per channel (their
// common part included: a multiplexer's slots count from the time stamp).
Fitted fit_channel_skew(const FitProblem& fp, const Recording& base, double, FieldScale scale) {
  const Recording& r = *fp.real;
  std::vector<std::function<double(int, size_t)>> basis;
  for (int k = 0; k < r.channels; ++k)
    basis.push_back([&, k](int c, size_t i) { return c == k ? fp.omega[i] : 0.0; });
  Fitted f = fit_angle_shift(fp, base, basis, scale);
  ParamList taus;
  for (int k = 0; k < r.channels; ++k)
    taus.push_back({"tau_" + effect_channel_name(r.channels, k), f.params[k].second});
  f.params = make_effect(effect_name(EffectId::channel_skew), taus, r.channels).params;
  return f;
}

Fitted fit_common_delay(const FitProblem& fp, const Recording& base, double, FieldScale scale) {
  Fitted f = fit_angle_shift(fp, base, {[&](int, size_t i) { return -fp.omega[i]; }}, scale);
  f.params = {{"tau_s", f.params[0].second}};
  return f;
}

Fitted fit_hysteresis(const FitProblem& fp, const Recording& base, double, FieldScale scale) {
  Fitted f = fit_angle_shift(fp, base,
                             {[&](int, size_t i) { return fp.omega[i] >= 0 ? 1.0 : -1.0; }}, scale);
  f.params = {{"h_rad", f.params[0].second}};
  return f;
}

// The resolution a file was printed with. A value x written with d decimals satisfies
// x 10^d = integer; with s significant digits, x 10^(s - 1 - floor(log10 |x|)) = integer. The
// file's decimals D and digits S are the most any of its values needs (printing is the same for
// every value), and the resolution of one value is the coarser of the two: 10^-D for fixed
// decimals, 10^(e - S + 1) for significant digits. A value printed to full precision needs 17
// digits and leaves a resolution of the double's own rounding.
struct PrintPrecision {
  int decimals = 0, digits = 1;
  double resolution(double x) const {
    const double fixed = std::pow(10.0, -decimals);
    if (x == 0) return fixed;
    const double e = std::floor(std::log10(std::fabs(x)));
    return std::max(fixed, std::pow(10.0, e - digits + 1));
  }
};

bool integral(double v) { return std::fabs(v - std::nearbyint(v)) <= 1e-6 + 4e-16 * std::fabs(v); }

PrintPrecision print_precision(const std::vector<double>& values) {
  PrintPrecision p;
  for (double x : values) {
    int d = 0;
    while (d < 17 && !integral(x * std::pow(10.0, d))) ++d;
    p.decimals = std::max(p.decimals, d);
    if (x == 0) continue;
    const double e = std::floor(std::log10(std::fabs(x)));
    int s = 1;
    while (s < 17 && !integral(x * std::pow(10.0, s - 1 - e))) ++s;
    p.digits = std::max(p.digits, s);
  }
  return p;
}

// An ADC leaves every value of every channel on a lattice origin + k * step, up to the rounding of
// the file's printing (print_precision). The step is read from the data (the smallest gap between
// distinct values, refined over wider spans so that a fine lattice is resolved to full
// precision), not fitted to the residual; nothing is assumed about the units or the ADC's range.
// The lattice is tested within each value's printing resolution: a value counts as evidence only
// where that resolution is well below a step (the printing could not put it on the lattice by
// chance), and a lattice that is the printing's own (the step one unit of the last decimal) is a
// quantization too, tested exactly. No lattice, no quantization.
Fitted fit_quantization(const FitProblem& fp, const Recording&, double, FieldScale) {
  const Recording& r = *fp.real;
  Fitted f;
  f.k = 1;
  std::vector<double> all;
  for (int c = 0; c < r.channels; ++c)
    for (double x : r.ch[c]) all.push_back(x);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  const PrintPrecision prec = print_precision(all);
  double peak = 0, rho_max = 0;
  for (double x : all) {
    peak = std::max(peak, std::fabs(x));
    rho_max = std::max(rho_max, prec.resolution(x));
  }
  // Distinct printed values closer than the printing's resolution could be one level.
  const double tiny = std::max(1e-12 * std::max(peak, 1e-300), 0.5 * prec.resolution(0.0));
  double step = 0;
  for (size_t i = 1; i < all.size(); ++i)
    if (all[i] - all[i - 1] > tiny && (step == 0 || all[i] - all[i - 1] < step))
      step = all[i] - all[i - 1];
  if (step == 0) {
    f.applicable = false;  // one value only: nothing to read a step from
    return f;
  }
  for (size_t span = 1; span < 2 * all.size(); span *= 2) {
    const double d = all[std::min(all.size() - 1, span)] - all[0];
    const double m = std::round(d / step);
    if (m >= 1) step = d / m;
  }
  // The printing's own lattice (fixed decimals, one unit of the last one): exact.
  const double unit = std::pow(10.0, -prec.decimals);
  const bool print_lattice = std::fabs(step / unit - 1) < 1e-3;
  if (print_lattice) step = unit;
  // Origin: the circular mean of the values' position within a step.
  double cs = 0, sn = 0;
  for (double x : all) {
    const double ph = 2 * M_PI * (x / step - std::floor(x / step));
    cs += std::cos(ph);
    sn += std::sin(ph);
  }
  double origin = step * std::atan2(sn, cs) / (2 * M_PI);
  // Step and origin refined together by least squares on the levels' indices, each value weighted
  // by its printing resolution (1/rho^2: significant digits print large values more coarsely), so
  // that the printing's rounding averages out instead of adding up over many levels.
  if (!print_lattice && all.size() >= 3) {
    double sw = 0, sk = 0, skk = 0, sx = 0, skx = 0;
    for (double x : all) {
      const double k = std::nearbyint((x - origin) / step), w = 1 / sq(prec.resolution(x));
      sw += w, sk += w * k, skk += w * k * k, sx += w * x, skx += w * k * x;
    }
    const double det = sw * skk - sk * sk;
    if (det > 0) {
      step = (sw * skx - sk * sx) / det;
      origin = (sx - step * sk) / sw;
    }
  }
  size_t on = 0, informative = 0, total = 0;
  double lo = 0, hi = 0;
  for (int c = 0; c < r.channels; ++c)
    for (double x : r.ch[c]) {
      const double u = (x - origin) / step;
      // Half a unit of the last printed digit, with a margin for the step's own error.
      const double tol = print_lattice
                             ? 1e-6 + 1e-12 * std::fabs(u)
                             : 0.75 * prec.resolution(x) / step + 1e-6 + 1e-12 * std::fabs(u);
      ++total;
      lo = std::min(lo, x - origin);
      hi = std::max(hi, x - origin);
      if (tol > 0.1) continue;  // printed too coarsely to tell this lattice from none
      ++informative;
      on += std::fabs(u - std::round(u)) <= tol;
    }
  if (informative < 0.5 * static_cast<double>(total) ||
      on < 0.99 * static_cast<double>(informative)) {
    f.applicable = false;  // the values are not on a lattice: not quantized
    return f;
  }
  // Bits: those the levels the recording spans need about the origin (the ADC's range is not
  // assumed a power of two in any unit); the full scale is what they cover.
  const double span_levels = 2 * std::max(std::fabs(lo), std::fabs(hi)) / step + 1;
  const double bits = std::max(1.0, std::ceil(std::log2(span_levels)));
  f.params = {{"bits", bits},
              {"full_scale", 0.5 * step * std::ldexp(1.0, static_cast<int>(bits))},
              {"step", step},
              {"origin", origin}};
  return f;
}

Fitted fit_saturation(const FitProblem& fp, const Recording& base, double, FieldScale) {
  const Recording& r = *fp.real;
  double peak_model = 0;
  for (int c = 0; c < r.channels; ++c)
    for (double v : base.ch[c]) peak_model = std::max(peak_model, std::fabs(v));
  auto clip = [&](double level) {
    Recording p = base;
    for (int c = 0; c < r.channels; ++c)
      for (auto& v : p.ch[c]) v = std::clamp(v, -level, level);
    return p;
  };
  double best_level = peak_model, best_l = neg2_log_likelihood(fp, base);
  for (int k = 0; k <= 80; ++k) {
    const double level = peak_model * (0.4 + 0.6 * k / 80.0);
    const double l = neg2_log_likelihood(fp, clip(level));
    if (l < best_l) best_l = l, best_level = level;
  }
  // Refine around the best grid point.
  double lo = best_level - 0.0075 * peak_model, hi = best_level + 0.0075 * peak_model;
  for (int it = 0; it < 30; ++it) {
    const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
    if (neg2_log_likelihood(fp, clip(a)) < neg2_log_likelihood(fp, clip(b)))
      hi = b;
    else
      lo = a;
  }
  const double level = 0.5 * (lo + hi);
  Fitted f;
  f.params = {{"level", level}};
  f.k = 1;
  return f;
}

// Extra white noise sigma_e on each channel, on top of what `base` already carries (base_extra):
// maximum likelihood over sigma_e by a ternary search (the likelihood is unimodal in sigma_e^2).
Fitted fit_excess_noise(const FitProblem& fp, const Recording& base, double base_extra,
                        FieldScale) {
  const Recording& r = *fp.real;
  const int S = nsignals(r);
  std::vector<double> rss(S, 0.0), lag1(S, 0.0);
  double s[4], prev[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < r.size(); ++i) {
    to_signals(
        r, i, [&](int c, size_t j) { return r.ch[c][j] - base.ch[c][j]; }, s);
    for (int q = 0; q < S; ++q) {
      rss[q] += s[q] * s[q];
      if (i > 0) lag1[q] += s[q] * prev[q];
      prev[q] = s[q];
    }
  }
  const double n = static_cast<double>(r.size());
  auto nll = [&](double var_e) {
    double t = 0;
    for (int q = 0; q < S; ++q) {
      const double v = sq(fp.signal_sigma[q]) + signal_weight(r, q) * (sq(base_extra) + var_e);
      t += rss[q] / v + n * std::log(v);
    }
    return t;
  };
  double lo = 0, hi = 0;
  for (int q = 0; q < S; ++q) hi = std::max(hi, rss[q] / n / signal_weight(r, q));
  hi = std::max(hi, 1e-30);
  for (int it = 0; it < 100; ++it) {
    const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
    if (nll(a) < nll(b))
      hi = b;
    else
      lo = a;
  }
  Fitted f;
  f.params = {{"sigma", std::sqrt(0.5 * (lo + hi))}};
  f.k = 1;
  // The excess must be white noise (docs/contracts.md, effect vocabulary). Its part that is
  // correlated from one sample to the next (the residual's lag-1 autocovariance; white noise adds
  // none) is anything but noise: a glitch, a dropout, interference. Pooled over signals in channel
  // units, with the spread white noise alone would give.
  double excess = 0, correlated = 0, spread2 = 0;
  for (int q = 0; q < S; ++q) {
    const double w = signal_weight(r, q), v = rss[q] / n;
    excess += (v - sq(fp.signal_sigma[q]) - w * sq(base_extra)) / w;
    correlated += lag1[q] / std::max(1.0, n - 1) / w;
    spread2 += sq(v / w) / n;
  }
  if (excess > 0 && correlated > kWhiteShare * excess + 4 * std::sqrt(spread2))
    f.rejected = fmt::format(
        "not white noise: {:.0f} % of the excess variance is correlated from sample to sample",
        100 * std::min(1.0, correlated / excess));
  return f;
}

// Mean and variance of an ADC's output Q(x + n), n ~ N(0, sigma^2), Q rounding to origin + k step.
void quantized_moments(double x, double sigma, double step, double origin, double& mean,
                       double& var) {
  const double u = (x - origin) / step;
  if (sigma < 1e-3 * step) {
    mean = origin + step * std::nearbyint(u);
    var = 0;
    return;
  }
  if (sigma > 8 * step) {  // finely quantized: the error is uniform and independent of x
    mean = x;
    var = sigma * sigma + step * step / 12;
    return;
  }
  const double z = sigma / step;
  const int lo = static_cast<int>(std::floor(u - 7 * z)) - 1,
            hi = static_cast<int>(std::ceil(u + 7 * z)) + 1;
  double m1 = 0, m2 = 0;
  double cdf_lo = 0.5 * std::erfc(-((lo - 0.5) - u) / (z * M_SQRT2));
  for (int k = lo; k <= hi; ++k) {
    const double cdf_hi = 0.5 * std::erfc(-((k + 0.5) - u) / (z * M_SQRT2));
    const double pk = cdf_hi - cdf_lo;
    cdf_lo = cdf_hi;
    m1 += pk * (k - u);
    m2 += pk * (k - u) * (k - u);
  }
  mean = x + step * m1;
  var = step * step * std::max(0.0, m2 - m1 * m1);
}

// ---- Predictions: each effect added to `base` from a candidate's parameters alone ----

// Channel c sees theta + delta(c, i): the model's change at the shifted angle, times the later
// field scalings.
void add_angle_shift(const FitProblem& fp, Recording& out, FieldScale field_scale,
                     const std::function<double(int, size_t)>& delta) {
  const Recording& r = *fp.real;
  for (int c = 0; c < r.channels; ++c) {
    const auto add = angle_shift(fp, c, [&](size_t i) { return delta(c, i); });
    for (size_t i = 0; i < r.size(); ++i) out.ch[c][i] += scale_at(field_scale, i) * add[i];
  }
}

// Every prediction takes the same arguments (the fitter table below): `out` starts as `base`;
// *extra_sigma (when given) starts at 0 and receives the white noise the effect adds per channel.
void predict_offset(const FitProblem& fp, const Recording&, const EffectCandidate& cand, FieldScale,
                    Recording& out, double*) {
  const Recording& r = *fp.real;
  for (int c = 0; c < r.channels; ++c)
    for (auto& v : out.ch[c]) v += cand.param("offset_" + chan_name(r, c));
}

void predict_gain_mismatch(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                           FieldScale, Recording& out, double*) {
  const Recording& r = *fp.real;
  for (int c = 0; c < r.channels; ++c)
    for (auto& v : out.ch[c]) v *= cand.param("gain_" + chan_name(r, c));
}

void predict_phase_error(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                         FieldScale field_scale, Recording& out, double*) {
  const Recording& r = *fp.real;
  const int p = fp.model->periodicity;
  const std::array<double, 4> d =
      phase_error_shifts(make_effect(cand.effect, cand.params, r.channels), r.channels);
  add_angle_shift(fp, out, field_scale,
                  [&](int c, size_t) { return d[static_cast<size_t>(c)] / p; });
}

void predict_zero_offset(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                         FieldScale field_scale, Recording& out, double*) {
  const double z = cand.param("zero_rad");
  add_angle_shift(fp, out, field_scale, [&](int, size_t) { return z; });
}

void predict_amplitude(const FitProblem& fp, const Recording& base, const EffectCandidate& cand,
                       FieldScale, Recording& out, double*) {
  const Recording& r = *fp.real;
  const double k = cand.param("scale");
  for (int c = 0; c < r.channels; ++c)
    for (size_t i = 0; i < r.size(); ++i) out.ch[c][i] += (k - 1) * field_part(fp, base, c, i);
}

void predict_harmonic(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                      FieldScale, Recording& out, double*) {
  const Recording& r = *fp.real;
  const int p = fp.model->periodicity;
  const int n = static_cast<int>(cand.param("order"));
  const double amp = cand.param("amplitude"), ph = cand.param("phase_rad");
  for (int c = 0; c < r.channels; ++c)
    for (size_t i = 0; i < r.size(); ++i)
      out.ch[c][i] += amp * std::sin(n * (p * r.theta_ref[i] + position(c) * M_PI / 2) + ph);
}

void predict_eccentricity(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                          FieldScale field_scale, Recording& out, double*) {
  const Recording& r = *fp.real;
  const double eps = cand.param("epsilon_rad"), phi0 = cand.param("phi0_rad");
  const double m = cand.param("am_depth"), phim = cand.param("am_phase_rad");
  add_angle_shift(fp, out, field_scale,
                  [&](int, size_t i) { return eps * std::sin(r.theta_ref[i] - phi0); });
  // The field part, at the shifted angle, times 1 + m cos(theta - phi_m).
  if (m != 0)
    for (int c = 0; c < r.channels; ++c)
      for (size_t i = 0; i < r.size(); ++i)
        out.ch[c][i] += m * std::cos(r.theta_ref[i] - phim) * field_part(fp, out, c, i);
}

void predict_channel_skew(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                          FieldScale field_scale, Recording& out, double*) {
  const Recording& r = *fp.real;
  const std::array<double, 4> tau =
      channel_skew_offsets(make_effect(cand.effect, cand.params, r.channels), r.channels);
  add_angle_shift(fp, out, field_scale,
                  [&](int c, size_t i) { return fp.omega[i] * tau[static_cast<size_t>(c)]; });
}

void predict_common_delay(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                          FieldScale field_scale, Recording& out, double*) {
  const double tau = cand.param("tau_s");
  add_angle_shift(fp, out, field_scale, [&](int, size_t i) { return -fp.omega[i] * tau; });
}

void predict_hysteresis(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                        FieldScale field_scale, Recording& out, double*) {
  const double h = cand.param("h_rad");
  add_angle_shift(fp, out, field_scale, [&](int, size_t i) { return fp.omega[i] >= 0 ? h : -h; });
}

void predict_drift(const FitProblem& fp, const Recording& base, const EffectCandidate& cand,
                   FieldScale, Recording& out, double*) {
  const Recording& r = *fp.real;
  if (fp.dtemp.empty()) return;
  for (int c = 0; c < r.channels; ++c) {
    const double ko = cand.param("offset_per_C_" + chan_name(r, c)),
                 kg = cand.param("gain_per_C_" + chan_name(r, c));
    for (size_t i = 0; i < r.size(); ++i)
      out.ch[c][i] = base.ch[c][i] * (1.0 + kg * fp.dtemp[i]) + ko * fp.dtemp[i];
  }
}

// The ADC sees the model plus the simulation's noise: predict its mean output, and carry the
// variance it adds beyond that noise (zero far from a step edge, step^2/12 when dithered).
void predict_quantization(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                          FieldScale, Recording& out, double* extra_sigma) {
  const Recording& r = *fp.real;
  const double step = cand.param("step"), origin = cand.param("origin");
  double added = 0;
  for (int c = 0; c < r.channels; ++c) {
    const double sigma = fp.model->sensor.noise_sigma[c];
    for (auto& v : out.ch[c]) {
      double mean, var;
      quantized_moments(v, sigma, step, origin, mean, var);
      v = mean;
      added += var - sigma * sigma;
    }
  }
  if (extra_sigma)
    *extra_sigma = std::sqrt(std::max(0.0, added / (r.channels * static_cast<double>(r.size()))));
}

void predict_saturation(const FitProblem& fp, const Recording&, const EffectCandidate& cand,
                        FieldScale, Recording& out, double*) {
  const Recording& r = *fp.real;
  const double level = cand.param("level");
  for (int c = 0; c < r.channels; ++c)
    for (auto& v : out.ch[c]) v = std::clamp(v, -level, level);
}

void predict_excess_noise(const FitProblem&, const Recording&, const EffectCandidate& cand,
                          FieldScale, Recording&, double* extra_sigma) {
  if (extra_sigma) *extra_sigma = cand.param("sigma");
}

// ---- The fitter table: one row per row of the effect table (effect_table.hpp), same order ----

struct EffectFitter {
  EffectId id;
  Fitted (*fit)(const FitProblem&, const Recording& base, double base_extra, FieldScale scale);
  void (*predict)(const FitProblem&, const Recording& base, const EffectCandidate&,
                  FieldScale field_scale, Recording& out, double* extra_sigma);
};

const std::array<EffectFitter, kEffectCount> kFitters = {{
    {EffectId::offset, fit_offset, predict_offset},
    {EffectId::gain_mismatch, fit_gain_mismatch, predict_gain_mismatch},
    {EffectId::phase_error, fit_phase_error, predict_phase_error},
    {EffectId::harmonic, fit_harmonic, predict_harmonic},
    {EffectId::eccentricity, fit_eccentricity, predict_eccentricity},
    {EffectId::channel_skew, fit_channel_skew, predict_channel_skew},
    {EffectId::common_delay, fit_common_delay, predict_common_delay},
    {EffectId::drift, fit_drift, predict_drift},
    {EffectId::quantization, fit_quantization, predict_quantization},
    {EffectId::saturation, fit_saturation, predict_saturation},
    {EffectId::excess_noise, fit_excess_noise, predict_excess_noise},
    {EffectId::hysteresis, fit_hysteresis, predict_hysteresis},
    {EffectId::zero_offset, fit_zero_offset, predict_zero_offset},
    {EffectId::amplitude, fit_amplitude, predict_amplitude},
}};

const EffectFitter& fitter_of(const EffectSpec& spec) {
  const EffectFitter& f = kFitters[static_cast<size_t>(spec.id)];
  if (f.id != spec.id)
    throw std::logic_error("effect fit: the fitter table is not in the effect table's order at " +
                           spec.name);
  return f;
}

}  // namespace

double EffectCandidate::param(const std::string& name) const {
  for (const auto& [k, v] : params)
    if (k == name) return v;
  throw std::out_of_range("effect " + effect + " has no parameter " + name);
}

Recording predict_effect(const FitProblem& fp, const Recording& base, const EffectCandidate& cand,
                         double* extra_sigma, const std::vector<double>* field_scale) {
  const EffectFitter& f = fitter_of(effect_spec(cand.effect));
  if (extra_sigma) *extra_sigma = 0;
  Recording out = base;
  f.predict(fp, base, cand, field_scale, out, extra_sigma);
  return out;
}

EffectCandidate fit_effect(const FitProblem& fp, const Recording& base, const std::string& effect,
                           double base_extra, const std::vector<double>* field_scale) {
  const Recording& r = *fp.real;
  const EffectSpec& spec = effect_spec(effect);
  Fitted f;
  if (spec.needs_speed_change && !speed_changes(fp)) {
    // At one speed a sampling time is an angle: common to every channel a zero offset, between
    // them a phase error. Only speed changes tell the effect from those simpler ones.
    f.applicable = false;
  } else if (spec.needs_temperature && fp.dtemp.empty()) {
    f.applicable = false;  // no temperature column: the effect cannot be observed
  } else {
    f = fitter_of(spec).fit(fp, base, base_extra, field_scale);
  }
  EffectCandidate cand;
  cand.effect = effect;
  cand.k = f.k;
  cand.params = f.params;
  cand.applicable = f.applicable;
  cand.rejected = f.rejected;
  if (!f.applicable) {
    cand.neg2logl = cand.bic = cand.delta_bic = std::numeric_limits<double>::infinity();
    return cand;
  }
  double extra = 0;
  const Recording pred = predict_effect(fp, base, cand, &extra, field_scale);
  cand.neg2logl = neg2_log_likelihood(fp, pred, std::hypot(base_extra, extra));
  const double n = static_cast<double>(r.size()) * nsignals(r);
  cand.bic = cand.neg2logl + cand.k * std::log(n);
  cand.delta_bic = cand.bic - neg2_log_likelihood(fp, base, base_extra);
  return cand;
}

}  // namespace acore
