// SPDX-License-Identifier: MIT
#include "engine/track_series.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/angle.hpp"
#include "core/errors.hpp"

namespace acore {

TrackConfig track_config_for(int angle_w) {
  TrackConfig c;
  c.angle_w = angle_w;
  c.frac_w = std::min(c.frac_w, 48 - angle_w);
  return c;
}

TrackRegs track_regs_for(const TrackSettings& s, double sample_rate, TrackConfig& c) {
  TrackRegs r;
  if (s.bandwidth_hz != 0) {
    if (!(sample_rate > 0))
      throw InputError("--track-bandwidth needs the recording's t column (increasing)");
    r.bw = track_code_for_bandwidth(s.bandwidth_hz, sample_rate, c);
  }
  // LATENCY + LEAD, rounded to 2^-lead_f samples.
  const double most = 255 + static_cast<double>((1u << c.lead_w) - 1) / (1 << c.lead_f);
  if (!(s.lead >= 0 && s.lead <= most))
    throw InputError(fmt::format("--track-lead must be 0..{} samples (is {})", most, s.lead));
  // Whole samples to COMP_LATENCY (at most 255), the rest to LEAD: its fraction, and beyond 255
  // samples its whole part too (LEAD_W bits hold up to 15.9375).
  const long q = std::lround(s.lead * (1 << c.lead_f));
  c.comp_latency = static_cast<int>(std::min<long>(q >> c.lead_f, 255));
  r.lead = static_cast<uint32_t>(q - (static_cast<long>(c.comp_latency) << c.lead_f));
  if (s.lot_threshold) {
    const uint32_t most_lot = (1u << (c.angle_w - 1)) - 1;
    if (*s.lot_threshold > most_lot)
      throw InputError("--track-lot must be 0.." + std::to_string(most_lot) + " angle LSBs (is " +
                       std::to_string(*s.lot_threshold) + ")");
    r.lot_thr = *s.lot_threshold;
  }
  return r;
}

double sample_rate_of_times(const double* t, size_t n) {
  if (t == nullptr || n < 2) return 0;
  const double span = t[n - 1] - t[0];
  return span > 0 ? static_cast<double>(n - 1) / span : 0;
}

double recording_sample_rate(const Recording& rec) {
  return rec.has_t() ? sample_rate_of_times(rec.t.data(), rec.t.size()) : 0;
}

namespace {

// The observer's outputs for one series with fixed configuration and registers.
TrackedSeries run_observer(const std::vector<double>& angle_rad, double sample_rate, int p,
                           const TrackConfig& c, const TrackRegs& r) {
  std::vector<uint32_t> codes(angle_rad.size());
  for (size_t i = 0; i < angle_rad.size(); ++i) codes[i] = angle_code(angle_rad[i], c.angle_w);
  const auto out = track_codes(codes, c, r);
  TrackedSeries t;
  t.sample_rate = sample_rate;
  t.config = c;
  t.regs = r;
  const size_t n = out.size();
  t.turns.reserve(n);
  t.comp.reserve(n);
  t.lot.reserve(n);
  if (t.has_rate()) t.rpm.reserve(n);
  for (const auto& o : out) {
    if (t.has_rate()) t.rpm.push_back(track_velocity_turns(o.velocity, c) * sample_rate * 60 / p);
    t.turns.push_back(o.turns);
    t.comp.push_back(std::ldexp(static_cast<double>(o.angle_comp), -c.angle_w) * 2 * M_PI);
    t.lot.push_back(o.lot ? 1 : 0);
  }
  return t;
}

}  // namespace

TrackedSeries track_series(const std::vector<double>& angle_rad, double sample_rate, int p,
                           int angle_w, const TrackSettings& s) {
  TrackConfig c = track_config_for(angle_w);
  const TrackRegs r = track_regs_for(s, sample_rate, c);
  return run_observer(angle_rad, sample_rate, p, c, r);
}

std::vector<double> track_velocity_error_rpm(const TrackedSeries& tracked,
                                             const std::vector<double>& theta_ref, int p) {
  if (!tracked.has_rate()) throw InputError("velocity error: the recording has no sample rate (t)");
  if (theta_ref.size() != tracked.rpm.size())
    throw InputError("velocity error: theta_ref differs in length from the angles");
  // The reference angle (mechanical, unwrapped) as the electrical angle.
  std::vector<double> ref(theta_ref.size());
  for (size_t i = 0; i < ref.size(); ++i) ref[i] = p * theta_ref[i];
  const TrackedSeries tref =
      run_observer(ref, tracked.sample_rate, p, tracked.config, tracked.regs);
  std::vector<double> dv(ref.size());
  for (size_t i = 0; i < dv.size(); ++i) dv[i] = tracked.rpm[i] - tref.rpm[i];
  return dv;
}

nlohmann::json track_json(const TrackedSeries& t) {
  size_t lost = 0;
  for (uint8_t l : t.lot) lost += l;
  return {{"code", t.regs.bw},
          {"bandwidth_hz", track_bandwidth_hz(t.regs.bw, t.sample_rate)},
          {"sample_rate_hz", t.sample_rate},
          {"lead_samples",
           t.config.comp_latency + std::ldexp(static_cast<double>(t.regs.lead), -t.config.lead_f)},
          {"lot_threshold", t.regs.lot_thr},
          {"lot_samples", lost}};
}

int equal_bandwidth_difference_span(int code) {
  const double wn = track_wn(code);
  int n = 1;
  while (std::fabs(std::sin(wn * (n + 1) / 2) / ((n + 1) * std::sin(wn / 2))) > 1 / std::sqrt(2.0))
    ++n;
  return n;
}

std::vector<double> finite_difference_rpm(const std::vector<double>& angle_rad, int n,
                                          double sample_rate, int p) {
  if (n < 1) throw InputError("finite difference: the span must be >= 1 sample");
  std::vector<double> v;
  if (angle_rad.size() <= static_cast<size_t>(n)) return v;
  v.reserve(angle_rad.size() - n);
  for (size_t i = n; i < angle_rad.size(); ++i)
    v.push_back(std::remainder(angle_rad[i] - angle_rad[i - n], 2 * M_PI) / (2 * M_PI) / n *
                sample_rate * 60 / p);
  return v;
}

}  // namespace acore
