// SPDX-License-Identifier: MIT
// GoogleTest form of cosim::compare (tb/cosim/cosim_stimuli.hpp): counts the mismatches, fails the
// test on the first one with its description, and prints the tally.
#pragma once
#include <gtest/gtest.h>

#include "cosim/cosim_stimuli.hpp"

namespace acore::cosim {

inline size_t mismatches(const std::vector<FixedSample>& rtl, const FixedModel& model,
                         const std::vector<ChannelCodes>& in, const char* what) {
  const Comparison c = compare(rtl, model, in);
  if (c.mismatches) ADD_FAILURE() << what << ": " << c.first;
  std::printf("%s: %zu samples, %zu mismatches\n", what, in.size(), c.mismatches);
  return c.mismatches;
}

}  // namespace acore::cosim
