// SPDX-License-Identifier: MIT
#include "stages/tracker.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"

namespace acore {

namespace {

using fx::mask;

int64_t sext(uint64_t x, int w) { return fx::sext(static_cast<int64_t>(x), w); }

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("tracking observer: " + what);
}

// The -3 dB frequency of a type-II loop with damping 1/sqrt(2), in units of wn:
// sqrt(1 + 2 zeta^2 + sqrt((1 + 2 zeta^2)^2 + 1)) = sqrt(2 + sqrt(5)).
const double kBandwidthOverWn = std::sqrt(2.0 + std::sqrt(5.0));

}  // namespace

void TrackConfig::validate() const {
  require(angle_w >= 8 && angle_w <= 24,
          "ANGLE_W must be 8..24 (is " + std::to_string(angle_w) + ")");
  require(frac_w >= 5 && frac_w <= 31, "FRAC_W must be 5..31 (is " + std::to_string(frac_w) + ")");
  require(angle_w + frac_w <= 48,
          "ANGLE_W+FRAC_W must be <= 48 (is " + std::to_string(angle_w + frac_w) + ")");
  require(turn_w >= 2 && turn_w <= 32, "TURN_W must be 2..32 (is " + std::to_string(turn_w) + ")");
  require(turn_w + angle_w + frac_w <= 64, "TURN_W+ANGLE_W+FRAC_W must be <= 64 (is " +
                                               std::to_string(turn_w + angle_w + frac_w) + ")");
  require(comp_latency >= 0 && comp_latency <= 255,
          "COMP_LATENCY must be 0..255 (is " + std::to_string(comp_latency) + ")");
  require(lead_w >= 1 && lead_w <= 12, "LEAD_W must be 1..12 (is " + std::to_string(lead_w) + ")");
  require(lead_f >= 0 && lead_f <= lead_w,
          "LEAD_F must be 0..LEAD_W (is " + std::to_string(lead_f) + ")");
}

void TrackRegs::validate(const TrackConfig& c) const {
  require(bw >= TrackConfig::kMin && bw <= c.k_max(),
          "bandwidth code must be " + std::to_string(TrackConfig::kMin) + ".." +
              std::to_string(c.k_max()) + " (is " + std::to_string(bw) + ")");
  require(lead <= mask(c.lead_w), "LEAD must be 0.." + std::to_string(mask(c.lead_w)) + " (is " +
                                      std::to_string(lead) + ", " + std::to_string(c.lead_f) +
                                      " fraction bits)");
  require(lot_thr <= mask(c.angle_w - 1), "LOT threshold must be 0.." +
                                              std::to_string(mask(c.angle_w - 1)) + " (is " +
                                              std::to_string(lot_thr) + ")");
}

Tracker::Tracker(const TrackConfig& c, const TrackRegs& r) : c_(c), r_(r) {
  c_.validate();
  r_.validate(c_);
}

TrackOutput Tracker::step(uint32_t theta) {
  const int pw = c_.p_w();
  const int xw = c_.turn_w + pw;
  const uint64_t theta_s = (static_cast<uint64_t>(theta) & mask(c_.angle_w)) << c_.frac_w;
  TrackOutput o;
  if (!started_) {
    started_ = true;
    x_ = theta_s;
    v_ = 0;
  } else {
    const int k = r_.bw;
    const uint64_t pred = (x_ + static_cast<uint64_t>(v_)) & mask(xw);
    const int64_t e = sext(theta_s - pred, pw);
    x_ = (pred + static_cast<uint64_t>(e >> k)) & mask(xw);
    v_ = sext(static_cast<uint64_t>(v_ + (e >> (2 * k + 1))), pw);
    const int64_t thr = static_cast<int64_t>(r_.lot_thr) << c_.frac_w;
    o.lot = e > thr || e < -thr;
  }
  const uint64_t half = uint64_t{1} << (c_.frac_w - 1);
  const uint64_t xr = (x_ + half) & mask(xw);
  o.angle = static_cast<uint32_t>((xr >> c_.frac_w) & mask(c_.angle_w));
  o.turns = sext(xr >> pw, c_.turn_w);
  o.velocity = v_;
  // v * D modulo 2^(P_W + LEAD_F), then floor by 2^LEAD_F: the RTL's shift-add product.
  const uint64_t d = (static_cast<uint64_t>(c_.comp_latency) << c_.lead_f) + r_.lead;
  const uint64_t prod = (static_cast<uint64_t>(v_) * d) & mask(pw + c_.lead_f);
  const uint64_t comp = ((x_ & mask(pw)) + (prod >> c_.lead_f) + half) & mask(pw);
  o.angle_comp = static_cast<uint32_t>(comp >> c_.frac_w);
  return o;
}

double track_wn(int k) { return std::ldexp(1.0, -k) / std::sqrt(2.0); }

double track_bandwidth_hz(int k, double sample_rate) {
  return kBandwidthOverWn * track_wn(k) * sample_rate / (2 * M_PI);
}

int track_code_for_bandwidth(double hz, double sample_rate, const TrackConfig& c) {
  require(std::isfinite(hz) && hz > 0, "bandwidth must be a positive number of Hz");
  require(std::isfinite(sample_rate) && sample_rate > 0, "the sample rate must be positive");
  int best = TrackConfig::kMin;
  double best_d = 1e300;
  for (int k = TrackConfig::kMin; k <= c.k_max(); ++k) {
    const double d = std::fabs(std::log2(track_bandwidth_hz(k, sample_rate) / hz));
    if (d < best_d) best_d = d, best = k;
  }
  require(best_d <= 0.5, "bandwidth " + std::to_string(hz) + " Hz is outside " +
                             std::to_string(track_bandwidth_hz(c.k_max(), sample_rate)) + ".." +
                             std::to_string(track_bandwidth_hz(TrackConfig::kMin, sample_rate)) +
                             " Hz at " + std::to_string(sample_rate) + " samples/s");
  return best;
}

std::vector<TrackOutput> track_codes(const std::vector<uint32_t>& codes, const TrackConfig& c,
                                     const TrackRegs& r) {
  Tracker t(c, r);
  std::vector<TrackOutput> out;
  out.reserve(codes.size());
  for (uint32_t code : codes) out.push_back(t.step(code));
  return out;
}

double track_velocity_turns(int64_t v, const TrackConfig& c) {
  return std::ldexp(static_cast<double>(v), -c.p_w());
}

}  // namespace acore
