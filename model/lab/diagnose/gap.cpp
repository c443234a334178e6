// SPDX-License-Identifier: MIT
#include "diagnose/gap.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/error_stats.hpp"
#include "core/errors.hpp"
#include "engine/float_model.hpp"

namespace acore {

GapModel build_gap_model(const Recording& sim, int periodicity, int fourier_order) {
  GapModel m;
  m.periodicity = periodicity;
  m.sensor = fit_sensor(sim, fourier_order, periodicity);
  // Calibrate on the noise-free model over one uniform turn, so the trajectory of the simulation
  // does not weigh the fit.
  Recording grid;
  const size_t n = 4096;
  for (size_t k = 0; k < n; ++k) grid.theta_ref.push_back(2 * M_PI * k / (n * periodicity));
  grid = m.sensor.resample(grid);
  CalOptions opt;
  opt.periodicity = periodicity;
  // The probe estimator fits against theta_ref itself (zero offset 0, as before the zero offset
  // existed): the diagnosis measures its errors against the reference directly, and its effect
  // fits are tuned to this estimator's sensitivity (docs/datapath.md "Zero offset").
  opt.estimate_zero = false;
  m.est = calibrate(grid, opt);
  return m;
}

namespace {
constexpr int kNoiseDraws = 4;

std::vector<double> float_errors(const GapModel& m, const Recording& rec) {
  std::vector<double> e(rec.size());
  for (size_t i = 0; i < rec.size(); ++i)
    e[i] = wrap_deg(
        (float_estimate(rec.d13(i), rec.d24(i), m.est).angle - m.periodicity * rec.theta_ref[i]) *
        180.0 / M_PI);
  return e;
}

double mean_sq(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : s / v.size();
}
}  // namespace

GapBasis make_gap_basis(const Recording& rec) {
  constexpr int kOrders = 16;
  const size_t n = rec.size();
  const std::vector<double> w = angular_velocity(rec);
  double wmax = 0, tmin = 1e300, tmax = -1e300;
  for (double v : w) wmax = std::max(wmax, std::fabs(v));
  if (rec.has_temp())
    for (double v : rec.temp) tmin = std::min(tmin, v), tmax = std::max(tmax, v);
  bool reverses = false;
  for (size_t i = 1; i < n; ++i) reverses = reverses || ((w[i] >= 0) != (w[0] >= 0));
  std::vector<std::vector<double>> factors = {std::vector<double>(n, 1.0)};
  if (wmax > 0) {
    std::vector<double> f(n);
    for (size_t i = 0; i < n; ++i) f[i] = w[i] / wmax;
    factors.push_back(f);
  }
  if (reverses) {
    std::vector<double> f(n);
    for (size_t i = 0; i < n; ++i) f[i] = w[i] >= 0 ? 1.0 : -1.0;
    factors.push_back(f);
  }
  if (rec.has_temp() && tmax > tmin) {
    std::vector<double> f(n);
    for (size_t i = 0; i < n; ++i) f[i] = (rec.temp[i] - tmin) / (tmax - tmin) - 0.5;
    factors.push_back(f);
  }
  const int per = 2 * kOrders + 1;
  GapBasis b;
  b.X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(per * factors.size()));
  double cs[kOrders + 1], sn[kOrders + 1];
  for (size_t i = 0; i < n; ++i) {
    // cos(k theta), sin(k theta) by rotation: one sincos per sample.
    const double c1 = std::cos(rec.theta_ref[i]), s1 = std::sin(rec.theta_ref[i]);
    cs[0] = 1;
    sn[0] = 0;
    for (int k = 1; k <= kOrders; ++k) {
      cs[k] = cs[k - 1] * c1 - sn[k - 1] * s1;
      sn[k] = sn[k - 1] * c1 + cs[k - 1] * s1;
    }
    for (size_t f = 0; f < factors.size(); ++f) {
      const double v = factors[f][i];
      const Eigen::Index c0 = static_cast<Eigen::Index>(f * per);
      b.X(i, c0) = v;
      for (int k = 1; k <= kOrders; ++k) {
        b.X(i, c0 + 2 * k - 1) = v * cs[k];
        b.X(i, c0 + 2 * k) = v * sn[k];
      }
    }
  }
  // A whisker of ridge keeps collinear factors (constant speed, say) solvable.
  Eigen::MatrixXd G = b.X.transpose() * b.X;
  G.diagonal().array() += 1e-9 * G.diagonal().maxCoeff() + 1e-12;
  b.gram.compute(G);
  return b;
}

StageSeries compare(const GapModel& m, const Recording& rec, const Recording& predicted,
                    double extra_sigma, const GapBasis* basis) {
  if (rec.size() != predicted.size())
    throw InputError("gap: recording and prediction differ in length");
  StageSeries s;
  s.err_deg = float_errors(m, rec);
  s.model_err_deg = float_errors(m, predicted);
  // c1 - c3 carries two channels' extra noise; a two-channel sin or cos one.
  const double extra_var = (m.sensor.channels == 4 ? 2.0 : 1.0) * extra_sigma * extra_sigma;
  const double sd =
      std::sqrt(m.sensor.diff_noise_sigma() * m.sensor.diff_noise_sigma() + extra_var);
  s.g.resize(rec.size());
  s.noise_var.resize(rec.size());
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> unit(0.0, 1.0);
  double nv = 0;
  for (size_t i = 0; i < rec.size(); ++i) {
    s.g[i] = wrap_deg(s.err_deg[i] - s.model_err_deg[i]);
    // The angle noise the simulation's noise level causes, through the estimator itself (region
    // switches included): Monte-Carlo draws of differential noise on the prediction, fixed seed.
    const double p13 = predicted.d13(i), p24 = predicted.d24(i);
    const double a0 = float_estimate(p13, p24, m.est).angle;
    double acc = 0;
    for (int k = 0; k < kNoiseDraws; ++k) {
      const double a = float_estimate(p13 + sd * unit(rng), p24 + sd * unit(rng), m.est).angle;
      acc += std::pow(std::remainder(a - a0, 2 * M_PI), 2);
    }
    s.noise_var[i] = acc / kNoiseDraws * std::pow(180.0 / M_PI, 2);
    nv += s.noise_var[i];
  }
  const double n = static_cast<double>(std::max<size_t>(1, rec.size()));
  nv /= n;
  s.noise_deg = std::sqrt(nv);
  s.raw_rms_deg = std::sqrt(mean_sq(s.g));
  GapBasis local;
  if (!basis) {
    local = make_gap_basis(rec);
    basis = &local;
  }
  const Eigen::Map<const Eigen::VectorXd> g(s.g.data(), static_cast<Eigen::Index>(s.g.size()));
  const Eigen::VectorXd beta = basis->gram.solve(basis->X.transpose() * g);
  const Eigen::VectorXd fit = basis->X * beta;
  s.g_systematic.assign(fit.data(), fit.data() + fit.size());
  const double cols = static_cast<double>(basis->X.cols());
  const double sys2 = fit.squaredNorm() / n - cols / n * nv;
  // Excess noise: the residual's variance above the expected, with its standard error.
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < s.g.size(); ++i) {
    const double r = s.g[i] - fit(static_cast<Eigen::Index>(i));
    const double d = r * r - s.noise_var[i];
    sum += d;
    sum2 += d * d;
  }
  const double exc2 = sum / n;
  const double se = std::sqrt(std::max(0.0, sum2 / n - exc2 * exc2) / n);
  // The residual's block means, in sample (time) order.
  constexpr size_t kBlocks = 16;
  double slow2 = 0;
  for (size_t b = 0; b < kBlocks; ++b) {
    const size_t lo = s.g.size() * b / kBlocks, hi = s.g.size() * (b + 1) / kBlocks;
    double m = 0;
    for (size_t i = lo; i < hi; ++i) m += s.g[i] - fit(static_cast<Eigen::Index>(i));
    if (hi > lo) slow2 += m * m / static_cast<double>(hi - lo);
  }
  slow2 = slow2 / n - static_cast<double>(kBlocks) / n * nv;
  s.slow_deg = std::sqrt(std::max(0.0, slow2));
  s.systematic_deg = std::sqrt(std::max(0.0, sys2));
  s.excess_noise_deg = exc2 > 4 * se ? std::sqrt(exc2) : 0.0;
  s.gap_deg = std::hypot(s.systematic_deg, s.excess_noise_deg);
  return s;
}

std::vector<StageDivergence> stage_divergence(const GapModel& m, const Recording& rec,
                                              const Recording& pred, const StageSeries& s) {
  std::vector<StageDivergence> out;
  const size_t n = rec.size();
  const double threshold =
      1.0 + 6.0 / std::sqrt(static_cast<double>(std::max<size_t>(n, 1))) + 0.05;
  auto ratio = [&](auto&& diff, double sigma) {
    double ss = 0;
    for (size_t i = 0; i < n; ++i) {
      const double d = diff(i);
      ss += d * d;
    }
    return std::sqrt(ss / std::max<size_t>(n, 1)) / std::max(sigma, 1e-12);
  };
  auto finish = [&](StageDivergence d) {
    for (double r : d.ratio) d.diverges = d.diverges || r > threshold;
    out.push_back(std::move(d));
  };
  // Noise floors: a small absolute floor keeps noise-free simulations from dividing by zero.
  const double floor = 1e-6;
  StageDivergence raw{"raw", {}, {}, false};
  for (int c = 0; c < rec.channels; ++c) {
    raw.signals.push_back(rec.channels == 4 ? fmt::format("c{}", c + 1) : (c ? "cos" : "sin"));
    raw.ratio.push_back(ratio([&](size_t i) { return rec.ch[c][i] - pred.ch[c][i]; },
                              std::max(floor, m.sensor.noise_sigma[c])));
  }
  finish(raw);
  const double sd = std::max(floor, m.sensor.diff_noise_sigma());
  finish({"prefilter",
          {"d13", "d24"},
          {ratio([&](size_t i) { return rec.d13(i) - pred.d13(i); }, sd),
           ratio([&](size_t i) { return rec.d24(i) - pred.d24(i); }, sd)},
          false});
  finish({"scaling",
          {"s13", "s24"},
          {ratio([&](size_t i) { return (rec.d13(i) - pred.d13(i)) / m.est.amp[0]; },
                 sd / m.est.amp[0]),
           ratio([&](size_t i) { return (rec.d24(i) - pred.d24(i)) / m.est.amp[1]; },
                 sd / m.est.amp[1])},
          false});
  std::vector<double> y13(n), y24(n), p13(n), p24(n);
  for (size_t i = 0; i < n; ++i) {
    const FloatSample a = float_estimate(rec.d13(i), rec.d24(i), m.est);
    const FloatSample b = float_estimate(pred.d13(i), pred.d24(i), m.est);
    y13[i] = a.y13 - b.y13;
    y24[i] = a.y24 - b.y24;
  }
  finish({"correction",
          {"y13", "y24"},
          {ratio([&](size_t i) { return y13[i]; }, sd / m.est.amp[0]),
           ratio([&](size_t i) { return y24[i]; }, sd / m.est.amp[1])},
          false});
  finish({"angle",
          {"angle"},
          {ratio([&](size_t i) { return s.g[i]; }, std::max(floor, s.noise_deg))},
          false});
  return out;
}

std::vector<double> angular_velocity(const Recording& rec) {
  const size_t n = rec.size();
  std::vector<double> w(n, 0.0);
  if (n < 2) return w;
  for (size_t i = 0; i < n; ++i) {
    const size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
    const double dt = rec.has_t() ? rec.t[b] - rec.t[a] : static_cast<double>(b - a);
    w[i] = dt != 0 ? (rec.theta_ref[b] - rec.theta_ref[a]) / dt : 0.0;
  }
  return w;
}

std::vector<DomainScore> gap_domains(const Recording& rec, const std::vector<double>& g, int p) {
  const size_t n = rec.size();
  const Eigen::Map<const Eigen::VectorXd> y(g.data(), static_cast<Eigen::Index>(n));
  const double mean = y.mean();
  const double tss = (y.array() - mean).square().sum();
  std::vector<DomainScore> out;
  if (n < 64 || tss <= 0) return out;
  const std::vector<double> w = angular_velocity(rec);
  double wmax = 0, tmin = 1e300, tmax = -1e300;
  for (double v : w) wmax = std::max(wmax, std::fabs(v));
  if (rec.has_temp())
    for (double v : rec.temp) tmin = std::min(tmin, v), tmax = std::max(tmax, v);
  // Each domain: a factor f_i (1 for angle) times the angle harmonics 0..H.
  auto score = [&](const std::string& name, auto&& factor, int harmonics) {
    const int cols = 2 * harmonics + 1 + (name == "angle" ? 0 : 1);
    Eigen::MatrixXd X(n, cols);
    for (size_t i = 0; i < n; ++i) {
      const double f = factor(i), e = p * rec.theta_ref[i];
      int c = 0;
      if (name != "angle") X(i, c++) = 1.0;  // intercept, so a constant offset is no evidence
      X(i, c++) = f;
      for (int h = 1; h <= harmonics; ++h) {
        X(i, c++) = f * std::cos(h * e);
        X(i, c++) = f * std::sin(h * e);
      }
    }
    const Eigen::VectorXd beta = X.colPivHouseholderQr().solve(y);
    const double rss = (y - X * beta).squaredNorm();
    double r2 = 1.0 - rss / tss;
    r2 = 1.0 - (1.0 - r2) * (n - 1.0) / std::max(1.0, n - 1.0 - cols);  // adjusted R^2
    out.push_back({name, r2});
  };
  score(
      "angle", [](size_t) { return 1.0; }, 8);
  if (wmax > 0) {
    score(
        "speed", [&](size_t i) { return w[i] / wmax; }, 4);
    score(
        "direction", [&](size_t i) { return w[i] >= 0 ? 1.0 : -1.0; }, 4);
  }
  if (rec.has_temp() && tmax > tmin)
    score(
        "time_temperature", [&](size_t i) { return (rec.temp[i] - tmin) / (tmax - tmin); }, 4);
  else if (rec.has_t())
    score(
        "time_temperature", [&](size_t i) { return rec.t[i] / std::max(1e-12, rec.t.back()); }, 4);
  {
    std::vector<double> mag(n);
    double mmax = 0;
    for (size_t i = 0; i < n; ++i) {
      mag[i] = std::hypot(rec.d13(i), rec.d24(i));
      mmax = std::max(mmax, mag[i]);
    }
    score(
        "signal_level", [&](size_t i) { return mag[i] / std::max(1e-12, mmax); }, 4);
  }
  return out;
}

}  // namespace acore
