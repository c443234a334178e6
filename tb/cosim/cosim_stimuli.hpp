// SPDX-License-Identifier: MIT
// What every co-sim program shares (tb/cosim/test_cosim.cpp, tb/cosim/cosim_config.cpp,
// tb/shell/test_apb_shell.cpp, tb/board/test_board.cpp): the output comparison against the
// bit-accurate model, random and paper input codes, and the identity register image. Header-only,
// test code.
#pragma once
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "stages/cordic.hpp"
#include "support/paper_signals.hpp"

namespace acore::cosim {

inline std::string show(const FixedSample& s) {
  char b[128];
  std::snprintf(b, sizeof b, "angle=%u region=%d ovf=%d los=%d dos=%d magnitude=%lld", s.angle,
                s.region, s.ovf, s.los, s.dos, static_cast<long long>(s.magnitude));
  return b;
}

struct Comparison {
  size_t mismatches = 0;  // samples whose RTL-visible outputs differ (+1 when the counts differ)
  std::string first;      // the first difference, described
};

// Every RTL output against FixedModel::step of the same input.
inline Comparison compare(const std::vector<FixedSample>& rtl, const FixedModel& model,
                          const std::vector<ChannelCodes>& in) {
  Comparison r;
  if (rtl.size() != in.size()) {
    r.mismatches = 1;
    r.first = std::to_string(rtl.size()) + " outputs for " + std::to_string(in.size()) + " inputs";
  }
  for (size_t i = 0; i < std::min(rtl.size(), in.size()); ++i) {
    const FixedSample m = model.step(in[i]);
    if (rtl[i] == m) continue;
    if (r.first.empty())
      r.first = "first mismatch at sample " + std::to_string(i) +
                " (c = " + std::to_string(in[i][0]) + ", " + std::to_string(in[i][1]) + ", " +
                std::to_string(in[i][2]) + ", " + std::to_string(in[i][3]) + "): rtl " +
                show(rtl[i]) + ", model " + show(m);
    ++r.mismatches;
  }
  return r;
}

// n samples of IN_W-bit codes: a quarter of the channels at the extremes, the rest uniform.
inline std::vector<ChannelCodes> random_codes(std::mt19937_64& rng, size_t n, int in_w) {
  std::vector<ChannelCodes> v(n);
  const int64_t lo = -(int64_t{1} << (in_w - 1)), span = int64_t{1} << in_w;
  for (auto& c : v)
    for (int k = 0; k < 4; ++k) {
      const uint64_t r = rng();
      c[k] = static_cast<int32_t>((r & 3) == 0 ? ((r >> 2) & 1 ? lo : lo + span - 1)
                                               : lo + static_cast<int64_t>((r >> 2) % span));
    }
  return v;
}

// n samples of the paper scenario (tests/support/paper_signals.hpp) at the image's input scale.
inline std::vector<ChannelCodes> paper_codes(const RegImage& img, size_t n) {
  return to_codes(test::paper_recording(n, true), img.in_scale, img.cfg.in_w);
}

// No correction: offsets 0, gain 1 at 8192 codes per unit, zero polynomials, the real atan table.
inline RegImage identity_image(const DatapathConfig& cfg) {
  RegImage img;
  img.cfg = cfg;
  img.in_scale = 8192.0;
  img.words.assign(img.cfg.words(), 0);
  const int64_t recip = std::llround(std::ldexp(1.0, img.cfg.s_f + img.cfg.r_shift) / img.in_scale);
  img.set_unsigned(img.cfg.addr_recip(0), recip);
  img.set_unsigned(img.cfg.addr_recip(1), recip);
  const auto at = cordic_atan_table(img.cfg.z_w, img.cfg.iterations);
  for (int i = 0; i < img.cfg.iterations; ++i) img.set_unsigned(img.cfg.addr_atan(i), at[i]);
  return img;
}

// Random register words over a base image (the saturating paths as well as the normal ones): every
// word below the CORDIC constants random (REG_W bits), half of the time tamed to small offsets,
// sane gains and small coefficients; every Fourier word and the ZERO word random (only the ZERO
// word's low ANGLE_W bits count); the CORDIC constants random too when random_atan (the Fourier
// rotations' trimmed angle registers then wrap, in the model as in the RTL).
inline RegImage random_image(const RegImage& base, std::mt19937_64& rng, bool random_atan) {
  RegImage img = base;
  const DatapathConfig& c = img.cfg;
  const uint64_t mask = (uint64_t{1} << c.reg_w) - 1;
  for (int a = 0; a < c.addr_atan(0); ++a) img.words[a] = rng() & mask;
  if (rng() & 1) {
    for (int ch = 0; ch < 2; ++ch) {
      img.set_signed(c.addr_offset(ch), static_cast<int64_t>(rng() % 2001) - 1000);
      img.set_unsigned(c.addr_recip(ch), static_cast<int64_t>(40000 + rng() % 60000));
    }
    for (int a = 4; a < c.addr_atan(0); ++a)
      img.set_signed(a, static_cast<int64_t>(rng() % 8001) - 4000);
  }
  if (random_atan)
    for (int i = 0; i < c.iterations; ++i) img.words[c.addr_atan(i)] = rng() & mask;
  for (int j = 0; j < c.fourier_words(); ++j) img.words[c.addr_fourier(j)] = rng() & mask;
  if (c.zero_word) img.words[c.addr_zero()] = rng() & mask;
  return img;
}

// The paper scenario calibrated for cfg: the calibration may only lower COEF_F
// (quantize_auto_range); the result must be exactly the build's configuration.
inline RegImage config_paper_image(const DatapathConfig& cfg) {
  const Recording cal = test::paper_recording(8000, true);
  const RegImage img = calibrate_image(cal, cfg, 1);
  if (img.cfg != cfg)
    throw InputError("the paper calibration for this configuration needs " + img.cfg.describe() +
                     "; set those parameters in rtl/configs.txt");
  return img;
}

// A fine sweep through every 45-degree boundary plus the zero vector and full scale.
inline std::vector<ChannelCodes> corner_codes(int in_w) {
  const int32_t F = (1 << (in_w - 1)) - 1, N = -(1 << (in_w - 1)), q = 1 << (in_w - 3);
  std::vector<ChannelCodes> in;
  for (int32_t a : {0, 1, -1, F, N, q, -q})
    for (int32_t b : {0, 1, -1, F, N, q, -q})
      for (int32_t c : {0, F, N})
        for (int32_t d : {0, F, N}) in.push_back({a, b, c, d});
  for (int k = 0; k < 8; ++k)
    for (int j = -50; j <= 50; ++j) {
      const double th = k * M_PI / 4 + j * 1e-5;
      in.push_back({static_cast<int32_t>(std::lround(q * std::sin(th))),
                    static_cast<int32_t>(std::lround(q * std::cos(th))), 0, 0});
    }
  return in;
}

// One run of a configuration's co-sim (cosim_config NAME): an image, its inputs, and the random
// input gaps and output backpressure of the harness.
struct Case {
  std::string what;
  RegImage img;
  std::vector<ChannelCodes> in;
  double gaps = 0, backpressure = 0;
  uint64_t seed = 1;
};

// Every run cosim_config makes for a configuration, in order: the paper scenario calibrated for it
// (`samples` inputs), corner inputs on that image, then 8 random images with 2000 random inputs
// each (the saturation paths). tb/cosim/sat_coverage.cpp replays the same runs through the model.
inline std::vector<Case> config_cases(const DatapathConfig& cfg, const std::string& name,
                                      size_t samples) {
  std::vector<Case> v;
  const RegImage paper = config_paper_image(cfg);
  v.push_back({"paper scenario", paper,
               to_codes(test::paper_recording(samples, true), paper.in_scale, cfg.in_w), 0.3, 0.3,
               1});
  v.push_back({"corner inputs", paper, corner_codes(cfg.in_w), 0.3, 0.3, 1});
  std::mt19937_64 rng(std::hash<std::string>{}(name));
  for (int k = 0; k < 8; ++k) {
    RegImage img = random_image(paper, rng, cfg.fourier_k > 0 && (rng() & 1));
    auto in = random_codes(rng, 2000, cfg.in_w);
    v.push_back(
        {"random image", std::move(img), std::move(in), 0.2, 0.2, static_cast<uint64_t>(k + 1)});
  }
  return v;
}

}  // namespace acore::cosim
