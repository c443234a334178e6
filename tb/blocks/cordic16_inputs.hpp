// SPDX-License-Identifier: MIT
// The input set of the 16-bit CORDIC tests (tb/blocks/test_cordic16.cpp: the pipelined and the
// word-serial CORDIC), in a fixed order: the square of IN_W-bit codes with a stride, every short
// vector, the edges.
#pragma once
#include <functional>

namespace acore {

inline void cordic16_for_each_input(int in_w, int stride, int short_max,
                                    const std::function<void(int, int)>& f) {
  const int lo = -(1 << (in_w - 1)), hi = (1 << (in_w - 1)) - 1;
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

}  // namespace acore
