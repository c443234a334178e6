// SPDX-License-Identifier: MIT
#include "engine/fixed_model.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/errors.hpp"
#include "core/fixed_point.hpp"
#include "stages/correction.hpp"
#include "stages/fourier_correct.hpp"
#include "stages/prefilter.hpp"
#include "stages/region_select.hpp"
#include "stages/scaler.hpp"

namespace acore {

namespace {
// Each mode's bit-accurate kernel (the FIXED column of core/correction_modes.hpp), by ID.
using FixedKernel = void (*)(int64_t, int64_t, int64_t, int, const int64_t*, const DatapathConfig&,
                             int64_t*, int64_t*, bool*);
constexpr FixedKernel kFixedKernels[] = {ACORE_CORRECTION_MODES(ACORE_MODE_FIXED)};
}  // namespace

StatusWindow StatusWindow::defaults(const DatapathConfig& cfg) {
  // CORDIC gain prod sqrt(1 + 2^-2i) for K iterations.
  double gain = 1.0;
  for (int i = 0; i < cfg.iterations; ++i) gain *= std::sqrt(1.0 + std::ldexp(1.0, -2 * i));
  const double nominal = gain * std::ldexp(1.0, cfg.s_f);
  return {static_cast<int64_t>(std::llround(0.5 * nominal)),
          static_cast<int64_t>(std::llround(1.5 * nominal))};
}

bool FixedSample::operator==(const FixedSample& o) const {
  return angle == o.angle && region == o.region && ovf == o.ovf && los == o.los && dos == o.dos &&
         magnitude == o.magnitude;
}

FixedOutput to_output(const FixedSample& s) {
  return {s.angle, static_cast<uint8_t>(s.region),
          static_cast<uint8_t>((s.ovf ? 1 : 0) | (s.los ? 2 : 0) | (s.dos ? 4 : 0))};
}

FixedModel::FixedModel(const RegImage& img) : FixedModel(img, StatusWindow::defaults(img.cfg)) {}

FixedModel::FixedModel(const RegImage& img, StatusWindow window) : img_(img), window_(window) {
  const DatapathConfig& cfg = img_.cfg;
  cfg.validate();
  if (!correction_mode(cfg.correction).runs_on(kEngineFixed))
    throw InputError(fmt::format("the bit-accurate model does not run the correction mode {}",
                                 correction_name(cfg.correction)));
  for (int c = 0; c < 2; ++c) {
    offset_[c] = img_.offset(c);
    recip_[c] = img_.recip(c);
  }
  for (int r = 0; r < cfg.regions; ++r)
    for (int c = 0; c < 2; ++c)
      for (int t = 0; t < cfg.coef_per_curve(); ++t) coef_.push_back(img_.poly(r, c, t));
  for (int i = 0; i < cfg.iterations; ++i) atan_.push_back(img_.atan(i));
  for (int j = 0; j < cfg.fourier_words(); ++j) fourier_.push_back(img_.fourier(j));
  if (cfg.zero_word) zero_ = img_.zero_position();
}

CordicConfig FixedModel::cordic_config() const {
  const DatapathConfig& cfg = img_.cfg;
  CordicConfig c;
  c.in_w = cfg.s_w;
  c.guard = cfg.cordic_guard;
  c.z_w = cfg.z_w;
  c.angle_w = cfg.angle_w;
  c.iterations = cfg.iterations;
  c.normalize = false;
  return c;
}

int64_t FixedModel::to_code(double v, double in_scale, int in_w) {
  const double code = std::nearbyint(v * in_scale);
  if (!(code <= static_cast<double>(fx::smax(in_w)))) return fx::smax(in_w);  // also NaN
  if (code < static_cast<double>(fx::smin(in_w))) return fx::smin(in_w);
  return static_cast<int64_t>(code);
}

FixedSample FixedModel::step(const ChannelCodes& c) const {
  const DatapathConfig& cfg = img_.cfg;
  FixedSample out;
  const DiffPair d = prefilter(c[0], c[1], c[2], c[3]);
  out.s13 = scale_curve(d.d13, offset_[0], recip_[0], cfg, &out.ovf);
  out.s24 = scale_curve(d.d24, offset_[1], recip_[1], cfg, &out.ovf);
  const RegionChoice rc = select_region(out.s13, out.s24, cfg.regions);
  out.region = rc.region;
  const int terms = cfg.coef_per_curve();
  const int64_t* coef = coef_.data() + static_cast<size_t>(rc.region) * 2 * terms;
  kFixedKernels[correction_mode(cfg.correction).id](out.s13, out.s24, rc.x, rc.region, coef, cfg,
                                                    &out.y13, &out.y24, &out.ovf);
  const CordicConfig cc = cordic_config();
  const CordicResult r = cordic_vector(out.y24, out.y13, cc, atan_.data());
  out.cordic_angle = r.angle;
  out.angle =
      cfg.fourier_k > 0 ? fourier_correct(r.angle, fourier_.data(), atan_.data(), cfg) : r.angle;
  out.magnitude = r.magnitude;
  out.los = r.magnitude < window_.mag_lo;
  out.dos = r.magnitude > window_.mag_hi;
  out.uncorrected_angle = cordic_vector(out.s24, out.s13, cc, atan_.data()).angle;
  if (cfg.zero_word) {  // the ZERO word's adder, modulo a turn (on both angles)
    const uint32_t mask = (uint32_t{1} << cfg.angle_w) - 1;
    out.angle = (out.angle - zero_) & mask;
    out.uncorrected_angle = (out.uncorrected_angle - zero_) & mask;
  }
  return out;
}

}  // namespace acore
