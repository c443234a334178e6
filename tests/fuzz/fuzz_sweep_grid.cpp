// SPDX-License-Identifier: MIT
// Fuzz target for the design-space sweep grid (`sweep --grid`, docs/contracts.md): any input is
// either rejected (not JSON, or InputError naming the sub-grid and field) or expands into
// distinct, valid configurations; nothing else may happen (a grid whose Cartesian product is too
// large must be refused before it is built, not exhaust memory). Seeds:
// tests/fuzz/corpus/fuzz_sweep_grid/.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

#include "core/datapath_config.hpp"
#include "core/errors.hpp"
#include "fuzz_target.hpp"
#include "sweep/design_space.hpp"

namespace {

bool accepts(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return false;
  std::vector<std::string> points;
  try {
    points = acore::expand_grid(j);
  } catch (const acore::InputError&) {
    return false;
  }
  const std::set<std::string> distinct(points.begin(), points.end());
  if (distinct.size() != points.size()) std::abort();
  for (const std::string& p : points) acore::DatapathConfig{}.with_rtl_params(p).validate();
  return true;
}

}  // namespace

ACORE_FUZZ_TARGET("fuzz_sweep_grid",
                  "0123456789-[]{}:,\" DEGREEREGIONSXCENTERCORRECTIONFOURIER_KFOLDIN_WREG_WCOEF_FK",
                  accepts)
