// SPDX-License-Identifier: MIT
// Fuzz target for the scenario JSON (`simulate --config`, model/lab/sim/simulator.hpp), its effects
// included (names, parameters and value rules read from the effect table, model/lab/sim/
// effect_table.hpp): any input is either rejected (not JSON, or an InputError naming the field) or
// read into a scenario whose JSON reads back as the same scenario, and which simulates 64 samples
// (or refuses them with an InputError); nothing else may happen. Seeds:
// tests/fuzz/corpus/fuzz_scenario/.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.hpp"
#include "fuzz_target.hpp"
#include "sim/simulator.hpp"

namespace {

bool accepts(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return false;
  acore::Scenario s;
  try {
    s = acore::Scenario::from_json(j, "fuzz");
  } catch (const acore::InputError&) {
    return false;
  }
  // What the scenario writes (simulate --dump-config) is what it reads.
  const nlohmann::json once = s.to_json();
  if (acore::Scenario::from_json(once, "fuzz").to_json() != once) std::abort();
  try {
    (void)acore::simulate(s, 64, 1);
  } catch (const acore::InputError&) {
  }
  return true;
}

}  // namespace

ACORE_FUZZ_TARGET("fuzz_scenario",
                  "0123456789-.e{}[]:,\" effectoffset_c1gain_mismatchphase_errordelta_radharmonic"
                  "orderamplitudeeccentricityepsilon_radzero_offsetzero_radchannel_skewtau_scommon_"
                  "delaydriftquantizationbitsfull_scalesaturationlevelexcess_noisesigmahysteresis"
                  "h_radscalechannelssensortrajectorykindturnstemperatureenabled",
                  accepts)
