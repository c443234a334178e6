// SPDX-License-Identifier: MIT
// Fuzz target for the diagnosis inputs (`diagnose --sim --real [--holdout]`): the input holds two
// or three recordings separated by a line "%%"; each either fails to parse (InputError), or the
// set is refused by diagnose() with an InputError (channel sets differ, no theta_ref, too short,
// less than a turn), or the diagnosis runs to the end with a verdict from the contract's list and
// finite shares; nothing else may happen. Seeds: tests/fuzz/corpus/fuzz_diagnose/.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/recording.hpp"
#include "diagnose/diagnose.hpp"
#include "fuzz_target.hpp"

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts(1);
  size_t at = 0;
  while (at <= text.size()) {
    const size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    if (line == "%%" || line == "%%\r")
      parts.emplace_back();
    else
      parts.back() += line + "\n";
    at = end + 1;
  }
  return parts;
}

bool accepts(const std::string& text) {
  const std::vector<std::string> parts = split(text);
  if (parts.size() < 2 || parts.size() > 3) return false;
  acore::Diagnosis d;
  try {
    const acore::Recording sim = acore::parse_recording(parts[0], "sim");
    const acore::Recording real = acore::parse_recording(parts[1], "real");
    std::unique_ptr<acore::Recording> hold;
    if (parts.size() == 3)
      hold = std::make_unique<acore::Recording>(acore::parse_recording(parts[2], "holdout"));
    acore::DiagnoseOptions opt;
    opt.fourier_order = 4;  // a short fuzz input has few samples per turn
    d = acore::diagnose(sim, real, hold.get(), opt);
  } catch (const acore::InputError&) {
    return false;
  }
  const nlohmann::json j = d.to_json();
  const std::string verdict = j.value("verdict", "");
  if (verdict != "explained" && verdict != "unexplained" && verdict != "no_gap") std::abort();
  (void)j.dump();
  return true;
}

}  // namespace

ACORE_FUZZ_TARGET("fuzz_diagnose", "0123456789.-+eE,#=% \nt,theta_ref,c1,c2,c3,c4,sin,cos,temp",
                  accepts)
