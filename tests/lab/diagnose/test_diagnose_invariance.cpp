// SPDX-License-Identifier: MIT
// The diagnosis does not depend on how a recording is written (diagnose/diagnose.hpp): the verdict,
// the named effects and the explained share stay the same when every channel of sim, real and
// holdout is rescaled into other units (mT, V, ADC codes), when the real recordings are printed
// with 5 or 6 significant digits or with fixed decimals, and an ADC whose range is not a power of
// two is found as quantization with its step in whatever units the file uses. The expectation is
// the diagnosis of the same recordings as the project's simulator writes them (full precision,
// its own units) and, for the ADC, the step the test itself applied.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "diagnose/diagnose_bench.hpp"

namespace acore {
namespace {

constexpr size_t kSamples = 3000;

double explained(const Diagnosis& d) {
  if (d.verdict != "explained") return 0;
  return d.combination.empty() ? d.ranking.front().explained : d.combination_explained;
}

// Every channel times k (a change of units; an ADC's codes are volts times codes per volt).
Recording rescaled(Recording r, double k) {
  for (int c = 0; c < r.channels; ++c)
    for (auto& v : r.ch[c]) v *= k;
  return r;
}

// Every channel as a file printed with `format` ("{:.5g}", "{:.6f}") reads it back.
Recording printed(Recording r, const std::string& format) {
  for (int c = 0; c < r.channels; ++c)
    for (auto& v : r.ch[c]) v = std::stod(fmt::format(fmt::runtime(format), v));
  return r;
}

// An ADC of `bits` over +-range (codes times step, in the recording's units), clipping at its ends.
Recording adc(Recording r, int bits, double range) {
  const double step = 2 * range / std::ldexp(1.0, bits), top = std::ldexp(1.0, bits - 1);
  for (int c = 0; c < r.channels; ++c)
    for (auto& v : r.ch[c]) v = step * std::clamp(std::nearbyint(v / step), -top, top - 1);
  return r;
}

struct Written {
  std::string how;
  Recording sim, real, holdout;
};

void expect_same(const Diagnosis& base, const Written& w, const std::string& what) {
  const Diagnosis d = diagnose(w.sim, w.real, &w.holdout);
  EXPECT_EQ(d.verdict, base.verdict) << what << ", " << w.how;
  EXPECT_EQ(d.named(), base.named()) << what << ", " << w.how;
  EXPECT_NEAR(explained(d), explained(base), 0.02) << what << ", " << w.how;
}

class Invariance : public ::testing::TestWithParam<std::string> {};

// A case of each kind of effect (and none), on four and two channels: rescaled into mT, V and
// codes (scale factors of no special form), and printed as instruments print.
TEST_P(Invariance, VerdictAndShareDoNotDependOnUnitsOrPrinting) {
  const std::string truth = GetParam();
  for (int ch : {4, 2}) {
    const BenchCase c = draw_bench_case(11, ch == 4 ? 1 : 2, truth, ch);
    const BenchRecordings rec = make_bench_recordings(c, kSamples);
    const Diagnosis base = diagnose(rec.sim, rec.real, &rec.holdout);
    const std::string what = fmt::format("{} on {} channels", truth, ch);
    for (const auto& [unit, k] : std::vector<std::pair<std::string, double>>{
             {"mT", 61.3}, {"V", 0.0173}, {"codes", 1517.9}})
      expect_same(base,
                  {unit, rescaled(rec.sim, k), rescaled(rec.real, k), rescaled(rec.holdout, k)},
                  what);
    for (const std::string f : {"{:.5g}", "{:.6g}"})
      expect_same(base, {f, rec.sim, printed(rec.real, f), printed(rec.holdout, f)}, what);
  }
}

INSTANTIATE_TEST_SUITE_P(Effects, Invariance,
                         ::testing::Values("none", "offset", "phase_error", "harmonic",
                                           "zero_offset", "excess_noise"));

// An ADC over a range that is no power of two in any of the units, its values written in
// millitesla with 6 decimals, in volts with 5 significant digits, or as codes: quantization, with
// the step the ADC had, in the file's units.
TEST(InvarianceAdc, LatticeFoundWhateverTheRangeUnitsAndPrinting) {
  for (int ch : {4, 2}) {
    const BenchCase c = draw_bench_case(12, ch == 4 ? 1 : 2, "none", ch);
    const BenchRecordings rec = make_bench_recordings(c, kSamples);
    for (int bits : {8, 9}) {
      const double range = 1.23 * c.peak, step = 2 * range / std::ldexp(1.0, bits);
      const Recording real = adc(rec.real, bits, range), hold = adc(rec.holdout, bits, range);
      struct Way {
        std::string how;
        double k;
        std::string format;
      };
      for (const Way& w :
           {Way{"mT, 6 decimals", 61.3, "{:.6f}"}, Way{"V, 5 digits", 0.0173, "{:.5g}"},
            Way{"V, 6 digits", 0.0173, "{:.6g}"}, Way{"codes", 1 / step, "{:.0f}"}}) {
        const Recording h = printed(rescaled(hold, w.k), w.format);
        const Diagnosis d =
            diagnose(rescaled(rec.sim, w.k), printed(rescaled(real, w.k), w.format), &h);
        const std::string what =
            fmt::format("{} bits over +-{:.4g}, {} channels, {}", bits, range, ch, w.how);
        ASSERT_EQ(d.verdict, "explained") << what;
        ASSERT_EQ(d.named().front(), "quantization") << what;
        const auto& q = d.combination.empty() ? d.ranking.front().cand : d.combination.front().cand;
        EXPECT_NEAR(q.param("step") / (step * w.k), 1.0, 1e-3) << what;
      }
    }
  }
}

}  // namespace
}  // namespace acore
