// SPDX-License-Identifier: MIT
// Fuzz target for the harmonics signal spec (docs/contracts.md, `harmonics` input): any input is
// either rejected (not JSON, or InputError naming the field) or a spec whose analysis runs to the
// end with finite results that obey the paper's bound (Eq. 29); nothing else may happen. Seeds:
// tests/fuzz/corpus/fuzz_harmonics_spec/.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"
#include "fuzz_target.hpp"
#include "harmonics/harmonics.hpp"

namespace {

bool accepts(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return false;
  acore::HarmonicAnalysis a;
  try {
    a = acore::analyze(acore::parse_signal_spec(j));
  } catch (const acore::InputError&) {
    return false;
  }
  if (a.phi.empty() || a.exact.size() != a.phi.size() || !std::isfinite(a.max_error) ||
      !std::isfinite(a.bound_geometric))
    std::abort();
  // Eq. 29 bounds the exact error (a little slack for the grid's rounding).
  if (a.max_error > a.bound_geometric * (1 + 1e-9) + 1e-12) std::abort();
  (void)a.to_json().dump();
  return true;
}

}  // namespace

ACORE_FUZZ_TARGET("fuzz_harmonics_spec", "0123456789.-+eE{}[]:,\" pA0B0ApBpdelta_ptermsnthetapsi",
                  accepts)
