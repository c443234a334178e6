// SPDX-License-Identifier: MIT
// The 16-bit stand-alone CORDIC (the registry line cordic16: 16-bit x/y, 16-bit angle, full circle,
// NORM=1):
//  1. the Verilated RTL equals the C++ model (model/cordic.cpp) bit for bit on a sweep of the input
//     square plus its edges and every short vector;
//  2. the model's angle error against double-precision atan2 of the integer inputs, in output
//     LSBs (one turn = 2^16): at most 0.5 RMS and 1 max over a dense sweep (every 6th code in x and
//     y, every vector with |x|,|y| <= 300, the edges);
//  3. no register of the RTL's widths overflows: |X| < 2^(XY_W-1) and |Y_i| < 2^(YW(i)-1).
// ACORE_C16_FULL=1 in the environment sweeps all 2^32 inputs instead (about 15 minutes).
#include <gtest/gtest.h>
#include <verilated.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>

#include "Vcordic16.h"
#include "stages/cordic.hpp"

namespace acore {
namespace {

CordicConfig c16() {
  CordicConfig c;
  c.in_w = ACORE_CORDIC16_IN_W;
  c.guard = ACORE_CORDIC16_G;
  c.z_w = ACORE_CORDIC16_Z_W;
  c.angle_w = ACORE_CORDIC16_ANGLE_W;
  c.iterations = ACORE_CORDIC16_K;
  c.normalize = ACORE_CORDIC16_NORM != 0;
  return c;
}

// Every input of the test set, in a fixed order: sweep with a stride, short vectors, edges.
void for_each_input(int stride, int short_max, const std::function<void(int, int)>& f) {
  const int lo = -(1 << (ACORE_CORDIC16_IN_W - 1)), hi = (1 << (ACORE_CORDIC16_IN_W - 1)) - 1;
  for (int x = lo; x <= hi; x += stride)
    for (int y = lo; y <= hi; y += stride) f(x, y);
  for (int x = -short_max; x <= short_max; ++x)
    for (int y = -short_max; y <= short_max; ++y) f(x, y);
  const int edge[] = {lo, lo + 1, -1, 0, 1, hi - 1, hi};
  for (int e : edge)
    for (int v = lo; v <= hi; ++v) {
      f(e, v);
      f(v, e);
    }
}

TEST(Cordic16, RtlEqualsModel) {
  const CordicConfig cfg = c16();
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->randReset(2);
  auto top = std::make_unique<Vcordic16>(ctx.get());
  for (int i = 0; i < cfg.iterations; ++i)
    for (int b = 0; b < ACORE_CORDIC16_AT_W; ++b) {
      const int bit = i * ACORE_CORDIC16_AT_W + b;
      if ((table[i] >> b) & 1)
        top->atan_i[bit / 32] |= 1u << (bit % 32);
      else
        top->atan_i[bit / 32] &= ~(1u << (bit % 32));
    }
  top->en_i = 1;
  top->clk_i = 0;
  top->eval();
  // LATENCY of rtl/acore_cordic.v: NORM 5 clocks, K stages of SPLIT+1 clocks, output 1 clock.
  const int latency =
      (ACORE_CORDIC16_NORM ? 5 : 1) + cfg.iterations * (ACORE_CORDIC16_SPLIT + 1) + 1;
  size_t n = 0, bad = 0;
  auto clock = [&](int x, int y) {
    top->x_i = static_cast<uint16_t>(x);
    top->y_i = static_cast<uint16_t>(y);
    top->clk_i = 1;
    top->eval();
    top->clk_i = 0;
    top->eval();
  };
  // Feed a sample every clock; the output of clock t is the input of clock t - latency.
  std::vector<std::pair<int, int>> in;
  for_each_input(41, 40, [&](int x, int y) { in.emplace_back(x, y); });
  for (size_t t = 0; t < in.size() + latency; ++t) {
    const bool valid = t < in.size();
    clock(valid ? in[t].first : 0, valid ? in[t].second : 0);
    if (t + 1 >= static_cast<size_t>(latency)) {
      const auto [x, y] = in[t + 1 - latency];
      const CordicResult m = cordic_vector(x, y, cfg, table.data());
      ++n;
      if (top->angle_o != m.angle || static_cast<int64_t>(top->mag_o) != m.magnitude) {
        if (bad++ == 0)
          ADD_FAILURE() << "x=" << x << " y=" << y << ": rtl angle " << top->angle_o << " mag "
                        << top->mag_o << ", model " << m.angle << " " << m.magnitude;
      }
    }
  }
  top->final();
  std::printf("cordic16 RTL vs model: %zu inputs, %zu mismatches\n", n, bad);
  EXPECT_EQ(bad, 0u);
  EXPECT_GT(n, 2000000u);
}

TEST(Cordic16, AccuracyAndNoOverflow) {
  const CordicConfig cfg = c16();
  const auto table = cordic_atan_table(cfg.z_w, cfg.iterations);
  const int xy_w = cfg.xy_w();
  const double turn = std::ldexp(1.0, cfg.angle_w);
  double se = 0, worst = 0, use_x = 0, use_y = 0;
  int wx = 0, wy = 0;
  size_t n = 0, model_diff = 0;
  auto check = [&](int x0, int y0) {
    if (x0 == 0 && y0 == 0) return;  // atan2(0, 0) has no angle
    // The model's loop with every intermediate X, Y measured against the RTL's register widths.
    int64_t x = x0, y = y0;
    const uint64_t mag =
        static_cast<uint64_t>(std::llabs(x)) | static_cast<uint64_t>(std::llabs(y));
    const int shift = (cfg.in_w - 2) - (63 - __builtin_clzll(mag));
    if (cfg.normalize && shift > 0) {
      x *= int64_t{1} << shift;
      y *= int64_t{1} << shift;
    }
    int64_t X = x * (int64_t{1} << cfg.guard), Y = y * (int64_t{1} << cfg.guard);
    if (X < 0) {
      X = -X;
      Y = -Y;
    }
    for (int i = 0; i < cfg.iterations; ++i) {
      const int yw = std::min(xy_w, xy_w + 2 - i);
      use_y = std::max(use_y, std::fabs(static_cast<double>(Y)) / std::ldexp(1.0, yw - 1));
      const int64_t xs = X >> i, ys = Y >> i;
      if (Y >= 0) {
        X += ys;
        Y -= xs;
      } else {
        X -= ys;
        Y += xs;
      }
      use_x = std::max(use_x, static_cast<double>(X) / std::ldexp(1.0, xy_w - 1));
    }
    const CordicResult r = cordic_vector(x0, y0, cfg, table.data());
    const double ref =
        std::atan2(static_cast<double>(y0), static_cast<double>(x0)) / (2 * M_PI) * turn;
    const double e = std::remainder(r.angle - ref, turn);
    if (r.magnitude != (X >> cfg.guard)) ++model_diff;
    se += e * e;
    if (std::fabs(e) > worst) {
      worst = std::fabs(e);
      wx = x0;
      wy = y0;
    }
    ++n;
  };
  const bool full = std::getenv("ACORE_C16_FULL") != nullptr;
  for_each_input(full ? 1 : 6, full ? 0 : 300, check);
  const double rms = std::sqrt(se / n);
  char line[256];
  std::snprintf(
      line, sizeof line,
      "cordic16 accuracy vs atan2 (%s): %zu inputs, RMS %.4f LSB, max %.4f LSB at (%d, %d); "
      "X uses %.3f, Y uses %.3f of its register range\n",
      full ? "all 2^32 inputs" : "stride 6 + short vectors + edges", n, rms, worst, wx, wy, use_x,
      use_y);
  std::fputs(line, stdout);
  // ACORE_CORDIC16_REPORT=FILE keeps the line for synth/reports (scripts/synth_summary.py).
  if (const char* path = std::getenv("ACORE_CORDIC16_REPORT")) {
    if (FILE* f = std::fopen(path, "w")) {
      std::fputs(line, f);
      std::fclose(f);
    }
  }
  EXPECT_EQ(model_diff, 0u);
  EXPECT_LE(rms, 0.5);
  EXPECT_LE(worst, 1.0);
  EXPECT_LT(use_x, 1.0);
  EXPECT_LT(use_y, 0.5);  // the 2x margin the RTL comment promises
}

}  // namespace
}  // namespace acore
