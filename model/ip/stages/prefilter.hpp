// SPDX-License-Identifier: MIT
// Stage 1, pre-filter (paper Eq. 3): opposite sensors subtracted, which cancels the common-mode
// "temporal variation". Mirrors rtl/acore_prefilter.v. D_W = IN_W + 1, no rounding, no overflow.
#pragma once
#include <cstdint>

namespace acore {

struct DiffPair {
  int64_t d13;  // c1 - c3, the sine curve
  int64_t d24;  // c2 - c4, the cosine curve
};

// Two-channel sensors feed c1 = sin, c2 = cos and c3 = c4 = 0.
inline DiffPair prefilter(int64_t c1, int64_t c2, int64_t c3, int64_t c4) {
  return {c1 - c3, c2 - c4};
}

}  // namespace acore
