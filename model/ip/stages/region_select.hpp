// SPDX-License-Identifier: MIT
// Stage 3, domain selection (paper Fig. 1, reconstructed). The most linear curve is the one nearest
// its zero crossing, i.e. the one with the smaller magnitude; it becomes the polynomial argument x.
//
//   |s13| <= |s24|, s24 >= 0  -> region 0 (around   0 deg), x = s13
//   |s13| >  |s24|, s13 >= 0  -> region 1 (around  90 deg), x = s24
//   |s13| <= |s24|, s24 <  0  -> region 2 (around 180 deg), x = s13
//   |s13| >  |s24|, s13 <  0  -> region 3 (around 270 deg), x = s24
//
// Ties go to the sine curve. With REGIONS = 8 each region is halved at its zero crossing:
// region8 = 2 * region4 + (x >= 0). Mirrors rtl/acore_region_select.v.
#pragma once
#include <cmath>
#include <cstdint>

namespace acore {

struct RegionChoice {
  int region;  // 0 .. regions-1
  int64_t x;   // polynomial argument, same format as s
};

inline RegionChoice select_region(int64_t s13, int64_t s24, int regions) {
  const int64_t a13 = s13 < 0 ? -s13 : s13;
  const int64_t a24 = s24 < 0 ? -s24 : s24;
  RegionChoice r;
  if (a13 <= a24) {
    r.region = s24 >= 0 ? 0 : 2;
    r.x = s13;
  } else {
    r.region = s13 >= 0 ? 1 : 3;
    r.x = s24;
  }
  if (regions == 8) r.region = 2 * r.region + (r.x >= 0 ? 1 : 0);
  return r;
}

// True when the region's argument x is the sine curve s13 (regions 0 and 2 of four), so the other
// curve is s24; false when x = s24 and the other curve is s13.
inline bool x_is_sine(int region, int regions) {
  return ((regions == 8 ? region >> 1 : region) & 1) == 0;
}

// The same rule on real numbers, for the float model and the calibration.
inline int select_region_real(double s13, double s24, int regions, double* x) {
  int region;
  if (std::fabs(s13) <= std::fabs(s24)) {
    region = s24 >= 0 ? 0 : 2;
    *x = s13;
  } else {
    region = s13 >= 0 ? 1 : 3;
    *x = s24;
  }
  if (regions == 8) region = 2 * region + (*x >= 0 ? 1 : 0);
  return region;
}

}  // namespace acore
