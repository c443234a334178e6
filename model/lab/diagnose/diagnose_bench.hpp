// SPDX-License-Identifier: MIT
// Blind self-benchmark of the gap diagnosis (`anglecore diagnose-bench`, docs/diagnosis.md).
//
// Each case draws a random "designer's model" of a sensor (simulator.hpp scenario: amplitudes,
// offsets, harmonic errors orders 1..5, noise), and three recordings of it with simulate():
//   sim      the model alone, constant speed, no temperature column
//   real     the model plus ONE effect (make_effect), a speed ramp through a reversal, a
//            temperature ramp, another noise seed
//   holdout  the same effect and parameters, another ramp, temperature ramp and seed
// The truth is one of the 14 effects of the vocabulary (effect_names()), "none" (real differs by
// fresh noise only) or "outside" (an effect outside the vocabulary, applied to the simulated
// real/holdout recordings here: a slip of the angle, a channel that freezes, amplitude modulation
// of the sine pair at a frequency unrelated to the angle, mains pick-up on one channel). The
// diagnosis runs blind.
//
// Ranges (A = amplitude 1, P = the largest |channel| of the clean model, sigma = the model's
// independent noise, v = the real recording's top speed in rev/s, p = 1):
//   offset         1..5 % of A on a random subset of channels, either sign
//   gain_mismatch  gain - 1 = 1..5 % on a random subset of channels, either sign
//   phase_error    0.5..5 deg, either sign, on the sine pair, the cosine pair or (four
//                  channels) one channel, drawn uniformly
//   harmonic       1..5 % of A, order 2..5 (two channels) or 3, 5, 7 (four: even orders cancel in
//                  c1 - c3 and cause no angle error), any phase
//   eccentricity   eps 0.2..2 deg, any phi0; magnitude modulation m = 0..1.5 eps (eps in rad),
//                  phi_m within 90 deg of phi0
//   channel_skew   the channels in a random slot order, slots tau apart, 360 v tau = 0.2..3 deg
//   common_delay   tau with 360 * v * tau = 0.2..3 deg (the angle lag at v)
//   drift          on a random subset of channels, offset and/or gain coefficients whose
//                  change over 40 degC is 1..5 % of A
//   quantization   6..10 bits over a full scale of 1.05..1.5 P
//   saturation     level 80..95 % of P
//   excess_noise   2..5 sigma
//   hysteresis     0.1..1 deg, either sign
//   zero_offset    0.2..3 deg, either sign
//   amplitude      scale - 1 = 5..30 %, either sign
// Four-channel draws are redrawn until they change what the estimator sees (c1 - c3, c2 - c4) by at
// least 1 % of A: an offset or gain common to both channels of a pair is invisible to the angle.
//
// "Strong enough to matter" (the parameters whose recovery is scored): every parameter drawn by the
// rules above, never a parameter left at its no-op default. Each is compared as a relative error
// |fitted - true| / |true| of the quantity that carries the effect:
//   offset, drift, tau, h, sigma, zero  the parameter itself
//   gain_mismatch     gain - 1 (the mismatch, not the gain)
//   amplitude         scale - 1
//   phase_error       the vector of per-channel phase shifts (phase_error_shifts)
//   channel_skew      the vector of per-channel sampling times (channel_skew_offsets)
//   harmonic          the complex amplitude a e^{i psi} (the order must match exactly)
//   eccentricity      the vector (eps e^{i phi0}, m e^{i phi_m})
//   quantization      the ADC step 2 full_scale / 2^bits (bits and full scale are not
//                     separately observable)
//   saturation        the clipped depth 1 - level / P
#pragma once
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/recording.hpp"
#include "diagnose/diagnose.hpp"
#include "sim/effects.hpp"
#include "sim/simulator.hpp"

namespace acore {

// One drawn case: what the diagnosis must find.
struct BenchCase {
  size_t index = 0;
  std::string truth;    // an effect name, "none" or "outside"
  std::string outside;  // for "outside": glitch, dropout, modulation or pickup
  ParamList outside_params;
  int channels = 4;
  Scenario model;  // the designer's model (no effects): sim, and the base of real/holdout
  Effect effect;   // the drawn effect (empty name for none/outside)
  Trajectory real_traj, hold_traj;
  double real_temp[2] = {25, 25}, hold_temp[2] = {25, 25};  // start, end degC
  double peak = 1;    // P: the largest |channel| of the clean model
  uint64_t seed = 0;  // noise seeds derive from it
};

struct BenchRecordings {
  Recording sim, real, holdout;
};

// The case `index` of a run with `seed`: truth and channel count given, everything else drawn from
// a generator seeded by (seed, index) alone, so results do not depend on --jobs.
BenchCase draw_bench_case(uint64_t seed, size_t index, const std::string& truth, int channels,
                          const std::string& outside = "");
// The three recordings of a case, `samples` each.
BenchRecordings make_bench_recordings(const BenchCase& c, size_t samples);

struct BenchParam {
  std::string name;  // e.g. "offset_c1", "gain_c2 - 1", "step", "a e^{i psi}"
  double truth = 0, fitted = 0, rel_error = 0;
};

struct BenchCaseResult {
  BenchCase drawn;       // the effect bench's draw (the physics bench fills index, truth, channels)
  std::string label;     // the row of the confusion matrix: the truth, or a physics scenario
  std::string expected;  // the right top-1: an effect, no_gap or unexplained
  bool effect_case = false;  // the recordings carry an effect: its holdout shrink is scored
  ParamList drawn_params;    // what was drawn, for the JSON report
  std::string verdict;       // explained, unexplained, no_gap
  std::string top1;          // the named effect when explained, else the verdict
  bool correct = false;
  bool confident_wrong = false;  // an effect named (or no_gap) on a none/outside recording
  std::vector<std::string> ambiguous_with;  // the diagnosis's own doubt (Diagnosis::ambiguous_with)
  double real_before = 0, real_after = 0, hold_before = 0, hold_after = 0;
  double shrink = 0;  // 1 - hold_after / hold_before
  double best_explained =
      0;  // the largest share of gap^2 any acceptable effect or combination explained
  double slow_share = 0;   // (slow / gap)^2 of the real recording before any effect (gap.hpp)
  bool slow_veto = false;  // an explanation explained enough but left a slow change in time
                           // (Diagnosis::note)
  std::vector<BenchParam> params;  // when the right effect is named (top-1)
  double seconds = 0;              // wall time of the diagnosis
};

struct BenchOptions {
  int per_effect = 10;  // recordings per effect, and as many with none and outside the vocabulary
  uint64_t seed = 1;
  size_t samples = 20000;  // per recording
  int jobs = 1;
  std::vector<size_t> only;  // run only these case indices (empty: all)
  std::function<void(size_t done, size_t total, const BenchCaseResult&)>
      progress;  // called serialized
};

// The benchmark's acceptance targets (docs/diagnosis.md): top-1 and top-3 shares, median shrink.
struct BenchTargets {
  double top1_min = 0.90;       // share of all cases (effects, none, outside) with the right top-1
  double shrink_min = 0.70;     // median holdout shrink over the effect cases
  double param_rel_max = 0.20;  // every scored parameter of a correctly named effect
  int confident_wrong_max = 0;  // on none/outside
};

struct BenchSummary {
  std::vector<BenchCaseResult> cases;
  std::vector<std::string> rows;               // truth labels: effects, none, outside
  std::vector<std::string> columns;            // verdict labels: effects, no_gap, unexplained
  std::vector<std::vector<int>> confusion;     // [row][column]
  double top1_accuracy = 0, top1_effects = 0;  // all cases; effect cases only
  double median_shrink = 0, min_shrink = 0;    // over the effect cases
  int confident_wrong = 0;
  int ambiguous = 0;    // named effects the diagnosis itself flagged as ambiguous
  int slow_vetoed = 0;  // cases whose explanation the slow-change rule refused (Diagnosis::note)
  double outside_best_explained =
      0;  // the most any effect or pair explained on an outside recording
  int params_scored = 0, params_within = 0;  // scored parameters, those within param_rel_max
  double param_median = 0, param_max = 0;
  double seconds = 0;
  BenchTargets targets;
  bool met() const;
  std::vector<std::string> missed() const;  // the targets missed, in words
  nlohmann::json to_json() const;
  std::string text() const;  // confusion matrix, per-effect table, totals
};

// The expected top-1 label of a truth: the effect itself, no_gap for none, unexplained for outside.
std::string expected_top1(const std::string& truth);

// ---- Shared by this bench and the physics bench (physics_bench.hpp) ----

// splitmix64: a well-mixed seed (cases are drawn from mix(mix(seed) ^ index)).
uint64_t bench_mix(uint64_t x);

// The random draws of a case.
class BenchDraw {
 public:
  explicit BenchDraw(uint64_t seed) : rng_(seed) {}
  double u(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int i(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }
  double sign() { return u(0, 1) < 0.5 ? -1.0 : 1.0; }
  bool coin() { return u(0, 1) < 0.5; }
  std::vector<bool> subset(int n);  // a random nonempty subset of n channels

 private:
  std::mt19937_64 rng_;
};

// A speed ramp through a reversal: from +-(3..12) to -+(3..12) rev/s, any start angle.
Trajectory draw_bench_ramp(BenchDraw& d);
// A temperature ramp over 30..60 degC starting at 0..30 degC, heating or cooling: start, end.
void draw_bench_temperature(BenchDraw& d, double out[2]);

// Judges a diagnosis against the right top-1 `expected`: verdict, top-1, correct, confident wrong
// (an effect named where no_gap or unexplained is right, or no_gap where unexplained is), gaps,
// holdout shrink, the best share any acceptable effect or pair explained. `d` needs a holdout.
BenchCaseResult judge_diagnosis(const Diagnosis& d, const std::string& expected, double seconds);

// The cases of `only` (indices into `cases`, in that order), or every case when `only` is empty;
// an index past the end is an InputError naming the option.
InputError only_out_of_range(size_t index, size_t cases);
template <class Case>
std::vector<Case> select_cases(const std::vector<Case>& cases, const std::vector<size_t>& only) {
  if (only.empty()) return cases;
  std::vector<Case> some;
  for (size_t i : only) {
    if (i >= cases.size()) throw only_out_of_range(i, cases.size());
    some.push_back(cases[i]);
  }
  return some;
}

// Runs `run(i)` for i = 0..n-1 on `jobs` threads (results in index order; the first exception is
// rethrown after the workers stop); `progress` is called serialized after each case.
std::vector<BenchCaseResult> run_bench_cases(
    size_t n, int jobs, const std::function<BenchCaseResult(size_t)>& run,
    const std::function<void(size_t done, size_t total, const BenchCaseResult&)>& progress);

// The summary of judged cases: confusion matrix (rows: the labels in `rows` order; columns: the
// vocabulary, any other expected label, no_gap, unexplained), accuracy, shrink, parameters.
BenchSummary summarize_bench(std::vector<BenchCaseResult> cases, std::vector<std::string> rows,
                             const BenchTargets& targets, double seconds);

// Scores one diagnosed case against its truth (params compared as documented above).
BenchCaseResult run_bench_case(const BenchCase& c, size_t samples);

// The (effects + 2) * per_effect cases of a run: per_effect of each effect, then none, then outside
// (cycling through its kinds); channel counts alternate 4, 2, 4, ...
std::vector<BenchCase> draw_bench_cases(const BenchOptions& opt);

// Draws and diagnoses (effects + 2) * per_effect cases on `jobs` threads, then summarizes.
BenchSummary run_diagnose_bench(const BenchOptions& opt,
                                const BenchTargets& targets = BenchTargets{});

}  // namespace acore
