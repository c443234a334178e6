// SPDX-License-Identifier: MIT
// An independent, test-only generator of the paper's default scenario (docs/contracts.md, paper
// scenario), written from the table and not from model/lab/sim/simulator.cpp, so tests compare two
// implementations.
#pragma once
#include <cmath>

#include "core/recording.hpp"

namespace acore::test {

// The paper scenario's table (docs/contracts.md): AF = cosine, BF = sine coefficients of orders
// 1..5 per channel, written here again on purpose: the tests compare the simulator against it.
inline constexpr double kPaperAF[4][5] = {{.11, .20, .13, 0, .03},
                                          {.10, .19, .07, .09, .03},
                                          {.50, .10, .17, .04, 0},
                                          {.13, 0, .10, .01, .01}};
inline constexpr double kPaperBF[4][5] = {{.10, .11, .13, .06, .03},
                                          {.10, .19, .13, .04, .04},
                                          {.13, .17, 0, .07, .01},
                                          {0, .13, .10, .03, .01}};

// The paper's four channels (Eq. 2 and 7) at electrical angle th.
inline void paper_channels(double th, double out[4]) {
  const double ideal[4] = {std::sin(th), std::cos(th), -std::sin(th), -std::cos(th)};
  for (int c = 0; c < 4; ++c) {
    out[c] = ideal[c];
    for (int h = 1; h <= 5; ++h)
      out[c] += kPaperAF[c][h - 1] * std::cos(h * th) + kPaperBF[c][h - 1] * std::sin(h * th);
  }
}

inline Recording paper_recording(size_t n, bool four_channel = true) {
  Recording r;
  r.channels = four_channel ? 4 : 2;
  for (size_t k = 0; k < n; ++k) {
    const double th = 2 * M_PI * k / n;
    double e[4] = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c)
      for (int h = 1; h <= 5; ++h)
        e[c] += kPaperAF[c][h - 1] * std::cos(h * th) + kPaperBF[c][h - 1] * std::sin(h * th);
    const double ideal[4] = {std::sin(th), std::cos(th), -std::sin(th), -std::cos(th)};
    r.theta_ref.push_back(th);
    if (four_channel) {
      for (int c = 0; c < 4; ++c) r.ch[c].push_back(ideal[c] + e[c]);
    } else {
      r.ch[0].push_back(ideal[0] + e[0] - ideal[2] - e[2]);
      r.ch[1].push_back(ideal[1] + e[1] - ideal[3] - e[3]);
    }
  }
  return r;
}

inline Recording ideal_recording(size_t n, double amp, double o13, double o24) {
  Recording r;
  r.channels = 2;
  for (size_t k = 0; k < n; ++k) {
    const double th = 2 * M_PI * (k + 0.25) / n;
    r.theta_ref.push_back(th);
    r.ch[0].push_back(amp * std::sin(th) + o13);
    r.ch[1].push_back(amp * std::cos(th) + o24);
  }
  return r;
}

}  // namespace acore::test
