// SPDX-License-Identifier: MIT
// Attribution of angle-error orders to signal imperfections; see harmonic_attribution.hpp.
#include "harmonics/harmonic_attribution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "harmonics/harmonic_mismatch.hpp"

namespace acore {

namespace {

constexpr double kDeg = kDegPerRad;

// The observed electrical amplitude (rad) at order k, or -1 when the spectrum does not reach k.
struct Observed {
  std::vector<double> h;
  double at(int k) const { return k >= 0 && k < static_cast<int>(h.size()) ? h[k] : -1; }
};

double consistency(const Observed& obs, const std::vector<std::pair<int, double>>& predicted) {
  double num = 0, den = 0;
  for (const auto& [k, pred] : predicted) {
    const double o = obs.at(k);
    if (o < 0 || pred <= 0) continue;
    num += std::min(o, pred);
    den += pred;
  }
  return den > 0 ? num / den : 1.0;
}

}  // namespace

std::vector<OrderCauses> attribute(const std::vector<OrderAmplitude>& spectrum,
                                   const AttributionOptions& opt) {
  if (opt.p < 1) throw InputError(fmt::format("attribution: p = {} must be >= 1", opt.p));
  for (size_t k = 0; k < spectrum.size(); ++k)
    if (spectrum[k].order != static_cast<int>(k))
      throw InputError("attribution: the spectrum must list orders 0, 1, 2, ... in sequence");
  const int p = opt.p;
  // Electrical error in radians, the units of Kuntz's formulas.
  const double to_rad = (opt.mechanical ? p : 1) / kDeg;
  Observed obs;
  for (const auto& o : spectrum) obs.h.push_back(o.amplitude_deg * to_rad);
  double largest = 0;
  for (size_t k = 1; k < spectrum.size(); ++k)
    largest = std::max(largest, spectrum[k].amplitude_deg);
  const double threshold = std::max(opt.min_amplitude_deg, opt.relative_threshold * largest);

  // Mismatch parameters fitted from their first-order orders.
  const double offset = std::max(obs.at(p), 0.0);
  const double amp_diff = 2 * std::max(obs.at(2 * p), 0.0);
  double delta_2p = 0;
  try {
    delta_2p = phase_from_h2p(std::max(obs.at(2 * p), 0.0));
  } catch (const InputError&) {
    delta_2p = -1;  // H_2p too large for any phase mismatch below pi/2
  }
  const auto phase_row = [](double d) { return table1(MismatchType::Phase, {0, 0, 0, 0, d}); };
  const auto amp_row = [](double diff) {
    return table1(MismatchType::Amplitude, {0, 0, diff / 2, -diff / 2, 0});
  };
  const auto off_row = [](double c) { return table1(MismatchType::Offset, {c, 0, 0, 0, 0}); };

  std::vector<OrderCauses> out;
  for (size_t ku = 0; ku < spectrum.size(); ++ku) {
    const int k = static_cast<int>(ku);
    if (k == 0 && !opt.include_dc) continue;
    if (!(spectrum[ku].amplitude_deg > 0) || spectrum[ku].amplitude_deg < threshold) continue;
    OrderCauses oc{k, spectrum[ku].amplitude_deg, {}};
    const double h = obs.h[ku];
    auto add = [&](Cause c, double pred_rad, std::vector<std::pair<int, double>> others) {
      c.predicted_deg = pred_rad / to_rad;
      c.explained = h > 0 ? std::min(pred_rad, h) / h : 0;
      c.consistency = consistency(obs, others);
      oc.causes.push_back(std::move(c));
    };
    // Main-harmonic mismatches (Table 1).
    if (k == p) {
      const auto r = off_row(h);
      add({"offset", 0, 1, "sqrt(A0^2+B0^2)", h, 0, 0, 1,
           fmt::format(
               "offset sqrt(A0^2+B0^2) = {:.4g} of the main amplitude (first order, Table 1)", h)},
          r.Hp, {{2 * p, r.H2p}});
    }
    if (k == 2 * p) {
      const auto r = off_row(offset);
      add({"offset", 0, 2, "sqrt(A0^2+B0^2)", offset, 0, 0, 1,
           fmt::format("offset {:.4g} (fitted at order {}) at second order", offset, p)},
          r.H2p, {});
      const auto ra = amp_row(amp_diff);
      add({"amplitude", p, 1, "|A_n-B_n|", amp_diff, 0, 0, 1,
           fmt::format("amplitude mismatch |A_n-B_n| = {:.4g} (first order)", amp_diff)},
          ra.H2p, {{4 * p, ra.H4p}});
      if (delta_2p >= 0) {
        const auto rp = phase_row(delta_2p);
        std::vector<std::pair<int, double>> others = {{4 * p, rp.H4p}};
        if (opt.include_dc) others.push_back({0, rp.H0});
        add({"phase", p, 1, "|delta_p|", delta_2p, 0, 0, 1,
             fmt::format("phase mismatch |delta_p| = {:.4g} rad = {:.3f} deg (first order)",
                         delta_2p, delta_2p * kDeg)},
            rp.H2p, others);
      }
    }
    if (k == 4 * p) {
      const auto ra = amp_row(amp_diff);
      add({"amplitude", p, 2, "|A_n-B_n|", amp_diff, 0, 0, 1,
           fmt::format("amplitude mismatch {:.4g} (fitted at order {}) at second order", amp_diff,
                       2 * p)},
          ra.H4p, {});
      if (delta_2p >= 0)
        add({"phase", p, 2, "|delta_p|", delta_2p, 0, 0, 1,
             fmt::format("phase mismatch {:.4g} rad (fitted at order {}) at second order", delta_2p,
                         2 * p)},
            phase_row(delta_2p).H4p, {});
    }
    if (k == 0) {
      // H_0 of the phase row, inverted by bisection (monotone for |delta| < pi/2 in this range).
      double lo = 0, hi = kPi / 2;
      if (phase_row(hi).H0 >= h) {
        for (int i = 0; i < 100; ++i) {
          const double mid = 0.5 * (lo + hi);
          (phase_row(mid).H0 < h ? lo : hi) = mid;
        }
        const double d = 0.5 * (lo + hi);
        const auto rp = phase_row(d);
        add({"phase", p, 1, "|delta_p|", d, 0, 0, 1,
             fmt::format("phase mismatch |delta_p| = {:.4g} rad (first order, constant error)", d)},
            rp.H0, {{2 * p, rp.H2p}, {4 * p, rp.H4p}});
      }
    }
    // Signal harmonics at first order: n - p = +-k or n + p = k.
    for (int n : {k + p, std::abs(k - p)}) {
      if (n == 0 || n == p) continue;
      bool seen = false;
      for (const auto& c : oc.causes) seen |= c.kind == "harmonic" && c.signal_order == n;
      if (seen) continue;
      add({"harmonic", n, 1, "A_n+B_n", 2 * h, 0, 0, 1,
           fmt::format("signal harmonic n = {} with A_n + B_n >= {:.4g} (order {} = {} {} p)", n,
                       2 * h, k, n, n > p ? "-" : "+")},
          h, {});
    }
    std::stable_sort(oc.causes.begin(), oc.causes.end(), [](const Cause& a, const Cause& b) {
      if (std::fabs(a.explained - b.explained) > 1e-9) return a.explained > b.explained;
      const bool ca = a.consistency >= 0.5, cb = b.consistency >= 0.5;
      if (ca != cb) return ca;
      const bool ma = a.kind != "harmonic", mb = b.kind != "harmonic";
      if (ma != mb) return ma;
      return a.consistency > b.consistency;
    });
    out.push_back(std::move(oc));
  }
  std::stable_sort(out.begin(), out.end(), [](const OrderCauses& a, const OrderCauses& b) {
    return a.amplitude_deg > b.amplitude_deg;
  });
  return out;
}

std::vector<OrderCauses> attribute_exact(const HarmonicAnalysis& a) {
  std::vector<OrderAmplitude> spectrum;
  for (const auto& h : a.harmonics) spectrum.push_back({h.order, h.exact * kDegPerRad, 0, 0, 0});
  AttributionOptions opt;
  opt.p = a.spec.p;
  opt.mechanical = false;
  opt.include_dc = true;
  return attribute(spectrum, opt);
}

nlohmann::json attribution_json(const std::vector<OrderCauses>& orders) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& o : orders) {
    nlohmann::json causes = nlohmann::json::array();
    for (const auto& c : o.causes)
      causes.push_back({{"kind", c.kind},
                        {"signal_order", c.signal_order},
                        {"taylor_order", c.taylor_order},
                        {"parameter_name", c.parameter_name},
                        {"parameter", c.parameter},
                        {"predicted_deg", c.predicted_deg},
                        {"explained", c.explained},
                        {"consistency", c.consistency}});
    j.push_back({{"order", o.order}, {"amplitude_deg", o.amplitude_deg}, {"causes", causes}});
  }
  return j;
}

}  // namespace acore
