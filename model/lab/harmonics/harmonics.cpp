// SPDX-License-Identifier: MIT
// Kuntz's harmonic analysis of the arctangent error: spec, normalisation, exact error, Taylor
// predictions of first and second order, bounds. See harmonics.hpp.
#include "harmonics/harmonics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "core/json_input.hpp"

namespace acore {

namespace {

constexpr double kDeg = 180.0 / kPi;

double number_field(const nlohmann::json& j, const std::string& key, const std::string& where,
                    double def, bool required = false) {
  if (!j.contains(key)) {
    if (required) throw InputError(fmt::format("harmonics spec: missing field '{}{}'", where, key));
    return def;
  }
  const auto& v = j.at(key);
  if (!v.is_number())
    throw InputError(fmt::format("harmonics spec: field '{}{}' must be a number", where, key));
  const double x = v.get<double>();
  if (!std::isfinite(x))
    throw InputError(fmt::format("harmonics spec: field '{}{}' is not finite", where, key));
  return x;
}

int int_field(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const double x = number_field(j, key, where, 0, true);
  if (x != std::floor(x) || std::fabs(x) > 1e6)
    throw InputError(
        fmt::format("harmonics spec: field '{}{}' = {} must be an integer", where, key, x));
  return static_cast<int>(x);
}

void reject_unknown(const nlohmann::json& j, const std::set<std::string>& known,
                    const std::string& where) {
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!known.count(it.key()))
      throw InputError(fmt::format("harmonics spec: unknown field '{}{}'", where, it.key()));
}

void require_finite(double x, const std::string& field) {
  if (!std::isfinite(x))
    throw InputError(fmt::format("harmonics spec: field '{}' is not finite", field));
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

}  // namespace

SignalSpec parse_signal_spec(const nlohmann::json& j) {
  if (!j.is_object()) throw InputError("harmonics spec: expected a JSON object");
  reject_unknown(j, {"p", "A0", "B0", "Ap", "Bp", "delta_p", "terms"}, "");
  SignalSpec s;
  s.p = int_field(j, "p", "");
  s.A0 = number_field(j, "A0", "", 0);
  s.B0 = number_field(j, "B0", "", 0);
  s.Ap = number_field(j, "Ap", "", 1);
  s.Bp = number_field(j, "Bp", "", 1);
  s.delta_p = number_field(j, "delta_p", "", 0);
  if (j.contains("terms")) {
    const auto& t = j.at("terms");
    if (!t.is_array()) throw InputError("harmonics spec: field 'terms' must be an array");
    for (size_t i = 0; i < t.size(); ++i) {
      const std::string where = fmt::format("terms[{}].", i);
      if (!t[i].is_object())
        throw InputError(fmt::format("harmonics spec: field 'terms[{}]' must be an object", i));
      reject_unknown(t[i], {"n", "A", "theta", "B", "psi"}, where);
      Disturbance d;
      d.n = int_field(t[i], "n", where);
      d.A = number_field(t[i], "A", where, 0);
      d.theta = number_field(t[i], "theta", where, 0);
      d.B = number_field(t[i], "B", where, 0);
      d.psi = number_field(t[i], "psi", where, 0);
      s.terms.push_back(d);
    }
  }
  validate(s);
  return s;
}

SignalSpec load_signal_spec(const std::string& path) {
  return parse_signal_spec(read_json_file(path, "harmonics spec"));
}

void validate(const SignalSpec& s) {
  if (s.p < 1 || s.p > kMaxOrder)
    throw InputError(
        fmt::format("harmonics spec: field 'p' = {} must lie in 1..{}", s.p, kMaxOrder));
  for (const auto& [name, v] : {std::pair<const char*, double>{"A0", s.A0},
                                {"B0", s.B0},
                                {"Ap", s.Ap},
                                {"Bp", s.Bp},
                                {"delta_p", s.delta_p}})
    require_finite(v, name);
  if (!(s.Ap > 0))
    throw InputError(fmt::format("harmonics spec: field 'Ap' = {} must be > 0", s.Ap));
  if (!(s.Bp > 0))
    throw InputError(fmt::format("harmonics spec: field 'Bp' = {} must be > 0", s.Bp));
  if (!(std::fabs(s.delta_p) < kPi / 2))
    throw InputError(fmt::format(
        "harmonics spec: field 'delta_p' = {} rad must lie in (-pi/2, pi/2)", s.delta_p));
  for (size_t i = 0; i < s.terms.size(); ++i) {
    const auto& t = s.terms[i];
    const std::string w = fmt::format("terms[{}].", i);
    for (const auto& [name, v] :
         {std::pair<const char*, double>{"A", t.A}, {"theta", t.theta}, {"B", t.B}, {"psi", t.psi}})
      require_finite(v, w + name);
    if (t.n < 1 || t.n > kMaxOrder)
      throw InputError(
          fmt::format("harmonics spec: field '{}n' = {} must lie in 1..{} (offsets are A0, B0)", w,
                      t.n, kMaxOrder));
    if (t.n == s.p)
      throw InputError(fmt::format(
          "harmonics spec: field '{}n' = {} equals p: a main-harmonic mismatch must be given "
          "as Ap, Bp (amplitude) and delta_p (phase), not as a term",
          w, t.n));
    // Eq. 1: amplitudes are >= 0 so that the phase is unambiguous.
    if (t.A < 0)
      throw InputError(fmt::format(
          "harmonics spec: field '{}A' = {} must be >= 0 (add pi to theta instead)", w, t.A));
    if (t.B < 0)
      throw InputError(fmt::format(
          "harmonics spec: field '{}B' = {} must be >= 0 (add pi to psi instead)", w, t.B));
  }
  const double a = geometric_amplitude_sum(equivalent_disturbances(s));
  if (!(a < 1))
    throw InputError(
        fmt::format("harmonics spec: outside the convergence domain: the normalised disturbance "
                    "sum (Eq. 28) is {:.4f} >= 1, "
                    "so the signal vector can reach zero and the angle error is unbounded; reduce "
                    "A0, B0, the Ap/Bp "
                    "mismatch, delta_p or the term amplitudes",
                    a));
}

std::vector<Disturbance> equivalent_disturbances(const SignalSpec& s) {
  const double g = (s.Ap + s.Bp) / 2;  // Eq. 36
  std::vector<Disturbance> out;
  for (const auto& t : s.terms) {
    Disturbance d = t;
    d.A /= g;
    d.B /= g;
    d.source = "term";
    if (d.A != 0 || d.B != 0) out.push_back(d);
  }
  // Eq. 37: offset as an n = 0 harmonic whose sine phase is pi/2.
  if (s.A0 != 0 || s.B0 != 0) out.push_back({0, s.A0 / g, kPi / 2, s.B0 / g, 0, "offset"});
  // Eq. 38: amplitude mismatch at n = p.
  if (s.Ap != s.Bp) out.push_back({s.p, s.Ap / g - 1, 0, s.Bp / g - 1, 0, "amplitude"});
  // Eq. 34: phase mismatch at n = p, scaled by Ap/g to stay exact (see header).
  if (s.delta_p != 0)
    out.push_back(
        {s.p, s.Ap / g * 2 * std::sin(s.delta_p / 2), (s.delta_p + kPi) / 2, 0, 0, "phase"});
  return out;
}

double geometric_amplitude_sum(const std::vector<Disturbance>& d) {
  double a = 0;
  for (const auto& x : d) a += std::hypot(x.A, x.B);
  return a;
}

double taylor_amplitude_sum(const std::vector<Disturbance>& d) {
  double a = 0;
  for (const auto& x : d) a += std::fabs(x.A) + std::fabs(x.B);
  return a;
}

double geometric_bound(double a) {
  if (!(a >= 0 && a < 1))
    throw InputError(
        fmt::format("geometric bound (Eq. 29) needs 0 <= sum_amplitude < 1, got {:.4f}", a));
  return std::atan(a * std::sqrt(1 - a * a) / (1 - a * a));
}

double geometric_bound_linear(double a) {
  if (!(a >= 0 && a < 0.5))
    throw InputError(fmt::format(
        "linear geometric bound (Eq. 30) needs 0 <= sum_amplitude < 1/2, got {:.4f}", a));
  return kPi / 3 * a;
}

double taylor_remainder_bound(double at, int k) {
  if (!(at >= 0 && at < 1))
    throw InputError(
        fmt::format("Taylor remainder bound (Eq. 32) needs 0 <= sum(|A|+|B|) < 1 (convergence "
                    "domain), got {:.4f}",
                    at));
  if (k < 0) throw InputError("Taylor remainder bound: order k must be >= 0");
  // -log(1 - At) - sum_{q=1..k} At^q/q: summed directly as sum_{q>k} At^q/q where that converges
  // quickly (no cancellation for small At), in closed form otherwise.
  double r = 0;
  if (at < 0.9) {
    double term = std::pow(at, k + 1);
    for (int q = k + 1; q < 2000 && term > 0; ++q, term *= at) r += term / q;
  } else {
    r = -std::log1p(-at);
    double term = at;
    for (int q = 1; q <= k; ++q, term *= at) r -= term / q;
  }
  return r;
}

std::vector<double> turn_grid(int n) {
  if (n < 1) throw InputError("harmonics: grid size must be >= 1");
  std::vector<double> phi(n);
  for (int j = 0; j < n; ++j) phi[j] = 2 * kPi * j / n;
  return phi;
}

namespace {

std::vector<double> unwrapped_error(const std::vector<double>& a, const std::vector<double>& b,
                                    int p, const std::vector<double>& phi) {
  const size_t n = phi.size();
  std::vector<double> e(n);
  double prev = 0, shift = 0;
  for (size_t j = 0; j < n; ++j) {
    // atan2(a, b) - p phi, wrapped to (-pi, pi], then unwrapped along the samples (section 1.2).
    // Wrapping each sample first makes the result independent of how far apart the phi are (any
    // order, several turns); inside the convergence domain |error| < pi/2, so no jump is removed.
    const double raw = std::remainder(std::atan2(a[j], b[j]) - p * phi[j], 2 * kPi);
    if (j > 0) {
      const double d = raw + shift - prev;
      if (d > kPi) shift -= 2 * kPi;
      if (d < -kPi) shift += 2 * kPi;
    }
    e[j] = raw + shift;
    prev = e[j];
  }
  double mean = 0;
  for (double x : e) mean += x;
  mean /= std::max<size_t>(n, 1);
  const double k = std::ceil((mean - kPi) / (2 * kPi));
  for (double& x : e) x -= 2 * kPi * k;
  return e;
}

}  // namespace

std::vector<double> exact_error(const std::vector<Disturbance>& d, int p,
                                const std::vector<double>& phi) {
  std::vector<double> a(phi.size()), b(phi.size());
  for (size_t j = 0; j < phi.size(); ++j) {
    a[j] = std::sin(p * phi[j]);
    b[j] = std::cos(p * phi[j]);
    for (const auto& x : d) {
      a[j] += x.A * std::sin(x.n * phi[j] + x.theta);
      b[j] += x.B * std::cos(x.n * phi[j] + x.psi);
    }
  }
  return unwrapped_error(a, b, p, phi);
}

std::vector<double> exact_error(const SignalSpec& s, const std::vector<double>& phi) {
  std::vector<double> a(phi.size()), b(phi.size());
  for (size_t j = 0; j < phi.size(); ++j) {
    a[j] = s.A0 + s.Ap * std::sin(s.p * phi[j] + s.delta_p);
    b[j] = s.B0 + s.Bp * std::cos(s.p * phi[j]);
    for (const auto& x : s.terms) {
      a[j] += x.A * std::sin(x.n * phi[j] + x.theta);
      b[j] += x.B * std::cos(x.n * phi[j] + x.psi);
    }
  }
  return unwrapped_error(a, b, s.p, phi);
}

std::vector<double> first_order_term(const std::vector<Disturbance>& d, int p,
                                     const std::vector<double>& phi) {
  std::vector<double> e(phi.size(), 0.0);
  for (size_t j = 0; j < phi.size(); ++j) {
    const double f = phi[j];
    for (const auto& x : d) {
      // Eq. 18.
      e[j] +=
          0.5 * (x.A * std::sin((x.n - p) * f + x.theta) + x.B * std::sin((x.n - p) * f + x.psi) +
                 x.A * std::sin((x.n + p) * f + x.theta) - x.B * std::sin((x.n + p) * f + x.psi));
    }
  }
  return e;
}

std::vector<double> second_order_term(const std::vector<Disturbance>& d, int p,
                                      const std::vector<double>& phi) {
  std::vector<double> e(phi.size(), 0.0);
  for (size_t j = 0; j < phi.size(); ++j) {
    const double f = phi[j];
    const double s2 = std::sin(2 * p * f), c2 = std::cos(2 * p * f);
    double sum = 0;
    for (const auto& x : d) {
      const double sa = std::sin(x.n * f + x.theta), cb = std::cos(x.n * f + x.psi);
      for (const auto& y : d) {
        const double sa2 = std::sin(y.n * f + y.theta), cb2 = std::cos(y.n * f + y.psi);
        // Eq. 26, second-order part.
        sum +=
            -x.A * y.A * s2 * sa * sa2 - 2 * x.A * y.B * c2 * sa * cb2 + x.B * y.B * s2 * cb * cb2;
      }
    }
    e[j] = 0.5 * sum;
  }
  return e;
}

void TrigSeries::add_sin(int k, double phase, double amplitude) {
  // a sin(k phi + ph) = a/(2i) e^{i ph} e^{i k phi} - a/(2i) e^{-i ph} e^{-i k phi}.
  const std::complex<double> i(0, 1);
  c_[k] += amplitude / (2.0 * i) * std::exp(i * phase);
  c_[-k] -= amplitude / (2.0 * i) * std::exp(-i * phase);
}

void TrigSeries::add_cos(int k, double phase, double amplitude) {
  const std::complex<double> i(0, 1);
  c_[k] += amplitude / 2.0 * std::exp(i * phase);
  c_[-k] += amplitude / 2.0 * std::exp(-i * phase);
}

TrigSeries TrigSeries::operator*(const TrigSeries& o) const {
  TrigSeries r;
  for (const auto& [k1, v1] : c_)
    for (const auto& [k2, v2] : o.c_) r.c_[k1 + k2] += v1 * v2;
  return r;
}

TrigSeries& TrigSeries::operator+=(const TrigSeries& o) {
  for (const auto& [k, v] : o.c_) c_[k] += v;
  return *this;
}

TrigSeries TrigSeries::scaled(double s) const {
  TrigSeries r = *this;
  for (auto& kv : r.c_) kv.second *= s;
  return r;
}

double TrigSeries::amplitude(int k) const {
  const auto it = c_.find(k);
  if (it == c_.end()) return 0;
  return k == 0 ? std::fabs(it->second.real()) : 2 * std::abs(it->second);
}

double TrigSeries::value(double phi) const {
  std::complex<double> s = 0;
  for (const auto& [k, v] : c_) s += v * std::exp(std::complex<double>(0, k * phi));
  return s.real();
}

int TrigSeries::max_order() const {
  int m = 0;
  for (const auto& kv : c_)
    if (std::abs(kv.second) > 0) m = std::max(m, std::abs(kv.first));
  return m;
}

TrigSeries first_order_series(const std::vector<Disturbance>& d, int p) {
  TrigSeries t;
  for (const auto& x : d) {
    // Eq. 18, term by term: orders n - p and n + p.
    t.add_sin(x.n - p, x.theta, 0.5 * x.A);
    t.add_sin(x.n - p, x.psi, 0.5 * x.B);
    t.add_sin(x.n + p, x.theta, 0.5 * x.A);
    t.add_sin(x.n + p, x.psi, -0.5 * x.B);
  }
  return t;
}

TrigSeries second_order_series(const std::vector<Disturbance>& d, int p) {
  TrigSeries s2, c2;
  s2.add_sin(2 * p, 0, 1);
  c2.add_cos(2 * p, 0, 1);
  std::vector<TrigSeries> sa(d.size()), cb(d.size());
  for (size_t k = 0; k < d.size(); ++k) {
    sa[k].add_sin(d[k].n, d[k].theta, 1);
    cb[k].add_cos(d[k].n, d[k].psi, 1);
  }
  // Eq. 26 with the products of sines expanded: orders 2p +- n +- m.
  TrigSeries t;
  for (size_t a = 0; a < d.size(); ++a)
    for (size_t b = 0; b < d.size(); ++b) {
      t += (s2 * sa[a] * sa[b]).scaled(-0.5 * d[a].A * d[b].A);
      t += (c2 * sa[a] * cb[b]).scaled(-d[a].A * d[b].B);
      t += (s2 * cb[a] * cb[b]).scaled(0.5 * d[a].B * d[b].B);
    }
  return t;
}

std::vector<double> dft_amplitudes(const std::vector<double>& x, int max_order) {
  const size_t n = x.size();
  if (n == 0) throw InputError("harmonics: DFT of an empty series");
  if (max_order < 0 || 2 * static_cast<size_t>(max_order) >= n)
    throw InputError(fmt::format("harmonics: {} samples cannot resolve order {}", n, max_order));
  std::vector<double> out(max_order + 1);
  for (int k = 0; k <= max_order; ++k) {
    std::complex<double> s = 0;
    for (size_t j = 0; j < n; ++j)
      s += x[j] * std::exp(std::complex<double>(0, -2 * kPi * k * double(j) / n));
    s /= double(n);
    out[k] = k == 0 ? std::fabs(s.real()) : 2 * std::abs(s);
  }
  return out;
}

HarmonicAnalysis analyze(const SignalSpec& spec, int grid) {
  validate(spec);
  HarmonicAnalysis r;
  r.spec = spec;
  r.disturbances = equivalent_disturbances(spec);
  r.sum_amplitude = geometric_amplitude_sum(r.disturbances);
  r.taylor_sum = taylor_amplitude_sum(r.disturbances);
  const int p = spec.p;
  const TrigSeries t1 = first_order_series(r.disturbances, p);
  TrigSeries t12 = t1;
  t12 += second_order_series(r.disturbances, p);
  int max_order = std::max({t12.max_order(), 2 * p, 1});
  if (grid <= 0) {
    grid = 4096;
    while (grid < 32 * max_order) grid *= 2;
  }
  if (grid < 2 * max_order + 2)
    throw InputError(
        fmt::format("harmonics: grid of {} points is too coarse for order {}", grid, max_order));
  r.phi = turn_grid(grid);
  r.exact = exact_error(r.disturbances, p, r.phi);
  r.first = first_order_term(r.disturbances, p, r.phi);
  const auto t2 = second_order_term(r.disturbances, p, r.phi);
  r.second.resize(grid);
  for (int j = 0; j < grid; ++j) r.second[j] = r.first[j] + t2[j];
  for (double x : r.exact) r.max_error = std::max(r.max_error, std::fabs(x));
  r.residual_first = max_abs_diff(r.exact, r.first);
  r.residual_second = max_abs_diff(r.exact, r.second);
  r.bound_geometric = geometric_bound(r.sum_amplitude);
  if (r.sum_amplitude < 0.5) r.bound_geometric_linear = geometric_bound_linear(r.sum_amplitude);
  if (r.taylor_sum < 1) {
    r.bound_taylor_first = taylor_remainder_bound(r.taylor_sum, 1);
    r.bound_taylor_second = taylor_remainder_bound(r.taylor_sum, 2);
  } else {
    r.notes.push_back(
        fmt::format("sum(|A|+|B|) = {:.4f} >= 1: outside the Taylor convergence domain (Eq. 32); "
                    "the Taylor bounds are not defined",
                    r.taylor_sum));
  }
  if (r.sum_amplitude >= 0.5)
    r.notes.push_back(
        fmt::format("sum sqrt(A^2+B^2) = {:.4f} >= 1/2: the linear bound of Eq. 30 does not apply",
                    r.sum_amplitude));
  const auto ex = dft_amplitudes(r.exact, max_order);
  for (int k = 0; k <= max_order; ++k)
    r.harmonics.push_back({k, ex[k], t1.amplitude(k), t12.amplitude(k)});
  return r;
}

nlohmann::json HarmonicAnalysis::to_json() const {
  auto opt = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v * kDeg) : nlohmann::json(nullptr);
  };
  nlohmann::json j;
  j["p"] = spec.p;
  j["grid"] = phi.size();
  j["max_error_deg"] = max_error * kDeg;
  j["residual_first_deg"] = residual_first * kDeg;
  j["residual_second_deg"] = residual_second * kDeg;
  j["bounds"] = {{"geometric_deg", bound_geometric * kDeg},
                 {"geometric_linear_deg", opt(bound_geometric_linear)},
                 {"taylor_first_deg", opt(bound_taylor_first)},
                 {"taylor_second_deg", opt(bound_taylor_second)}};
  j["sum_amplitude"] = sum_amplitude;
  j["taylor_sum"] = taylor_sum;
  j["harmonics"] = nlohmann::json::array();
  for (const auto& h : harmonics)
    j["harmonics"].push_back({{"order", h.order},
                              {"exact_deg", h.exact * kDeg},
                              {"first_deg", h.first * kDeg},
                              {"second_deg", h.second * kDeg}});
  j["disturbances"] = nlohmann::json::array();
  for (const auto& d : disturbances)
    j["disturbances"].push_back({{"source", d.source},
                                 {"n", d.n},
                                 {"A", d.A},
                                 {"theta", d.theta},
                                 {"B", d.B},
                                 {"psi", d.psi}});
  j["notes"] = notes;
  return j;
}

}  // namespace acore
