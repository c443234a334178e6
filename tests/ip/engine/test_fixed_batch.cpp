// SPDX-License-Identifier: MIT
// The vectorized batch path (fixed_batch.cpp) against the per-sample model (fixed_model.cpp): a
// second implementation of the same contract, compared bit for bit, including saturation paths.
#include <gtest/gtest.h>

#include <random>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "support/paper_signals.hpp"

namespace acore {
namespace {

void expect_same(const FixedModel& m, const std::vector<ChannelCodes>& codes) {
  std::vector<FixedOutput> batch(codes.size());
  m.run_batch(codes.data(), codes.size(), batch.data());
  for (size_t i = 0; i < codes.size(); ++i) {
    const FixedOutput s = to_output(m.step(codes[i]));
    ASSERT_TRUE(s == batch[i]) << "sample " << i << ": step angle " << s.angle << " region "
                               << int(s.region) << " flags " << int(s.flags) << " / batch angle "
                               << batch[i].angle << " region " << int(batch[i].region) << " flags "
                               << int(batch[i].flags);
  }
}

// Every word random, the two offsets within +-2000 (so the scaled curves are not all saturated).
RegImage random_image(const DatapathConfig& cfg, std::mt19937_64& rng) {
  RegImage img;
  img.cfg = cfg;
  img.words.assign(cfg.words(), 0);
  std::uniform_int_distribution<uint64_t> word(0, (uint64_t{1} << cfg.reg_w) - 1);
  for (auto& w : img.words) w = word(rng);
  img.set_signed(cfg.addr_offset(0), static_cast<int64_t>(word(rng) % 4000) - 2000);
  img.set_signed(cfg.addr_offset(1), static_cast<int64_t>(word(rng) % 4000) - 2000);
  return img;
}

// n inputs, each channel uniform over the IN_W-bit range.
std::vector<ChannelCodes> random_codes(size_t n, int in_w, std::mt19937_64& rng) {
  std::uniform_int_distribution<int32_t> code(-(1 << (in_w - 1)), (1 << (in_w - 1)) - 1);
  std::vector<ChannelCodes> codes(n);
  for (auto& c : codes) c = {code(rng), code(rng), code(rng), code(rng)};
  return codes;
}

TEST(FixedBatch, MatchesStepOnThePaperScenario) {
  const Recording rec = test::paper_recording(20000);
  const RegImage img =
      quantize(calibrate(rec, CalOptions{}), DatapathConfig{}, choose_in_scale(rec, 16));
  const FixedModel m(img);
  ASSERT_TRUE(m.batch_fits_int32());
  expect_same(m, to_codes(rec, img.in_scale, 16));
}

TEST(FixedBatch, MatchesStepOnRandomImagesAndInputsIncludingSaturation) {
  std::mt19937_64 rng(7);
  for (int degree : {1, 3, 5, 7})
    for (int regions : {4, 8}) {
      DatapathConfig cfg;
      cfg.degree = degree;
      cfg.regions = regions;
      const RegImage img = random_image(cfg, rng);
      std::vector<ChannelCodes> codes = random_codes(3000, cfg.in_w, rng);
      codes.push_back({32767, 32767, -32768, -32768});
      codes.push_back({0, 0, 0, 0});
      const FixedModel m(img);
      expect_same(m, codes);
    }
}

// The widths the vectorized loops read at run time (the truncated partial products in 16- or 32-bit
// lanes by S_F, the scaler's split at R_SHIFT - SCALE_G, the CORDIC's guard bits and iterations,
// the accumulator), on random images and inputs over the whole IN_W range.
TEST(FixedBatch, MatchesStepAtOtherWidths) {
  std::mt19937_64 rng(11);
  for (const char* p :
       {"S_F=17 S_W=20", "S_F=12 S_W=15", "S_F=8 S_W=14 COEF_F=12 ACC_I=7", "R_SHIFT=13 SCALE_G=0",
        "R_SHIFT=16 SCALE_G=2", "IN_W=12 R_SHIFT=3 SCALE_G=3 REG_W=14 COEF_F=12 Z_W=16",
        "CORDIC_G=5 K=12 Z_W=18 ANGLE_W=14", "IN_W=12 REG_W=14 COEF_F=12 Z_W=16",
        "ACC_G=7 ACC_I=7 COEF_F=12 DEGREE=5 REGIONS=8"}) {
    const DatapathConfig cfg = DatapathConfig{}.with_rtl_params(p);
    const RegImage img = random_image(cfg, rng);
    const int32_t lo = -(1 << (cfg.in_w - 1)), hi = (1 << (cfg.in_w - 1)) - 1;
    std::vector<ChannelCodes> codes = random_codes(5000, cfg.in_w, rng);
    codes.push_back({hi, hi, lo, lo});
    codes.push_back({lo, lo, hi, hi});
    codes.push_back({0, 0, 0, 0});
    const FixedModel m(img);
    ASSERT_TRUE(m.batch_fits_int32()) << p;  // else run_batch is step() and nothing is compared
    SCOPED_TRACE(p);
    expect_same(m, codes);
  }
}

// The other correction modes: none runs the vectorized loops without the Horner chunk; poly2d and
// XCENTER fall back to step() (so the comparison guards the dispatch, not a second implementation).
TEST(FixedBatch, MatchesStepInTheOtherCorrectionModes) {
  std::mt19937_64 rng(8);
  struct Mode {
    int correction, degree, regions, xcenter;
  };
  for (const Mode md :
       {Mode{kNone, 3, 4, 0}, Mode{kNone, 3, 8, 0}, Mode{kPoly2d, 3, 4, 0}, Mode{kPoly, 7, 8, 1}}) {
    DatapathConfig cfg;
    cfg.correction = md.correction;
    cfg.degree = md.degree;
    cfg.regions = md.regions;
    cfg.xcenter = md.xcenter;
    const RegImage img = random_image(cfg, rng);  // drawn before the inputs, in this order
    expect_same(FixedModel(img), random_codes(2000, cfg.in_w, rng));
  }
}

// The ZERO word's subtraction, after the vectorized chain, the Fourier stage and in the fallback:
// random images (the zero word's upper bits too) and random inputs.
TEST(FixedBatch, MatchesStepWithTheZeroWord) {
  std::mt19937_64 rng(9);
  for (const char* p :
       {"ZERO=1", "CORRECTION=2 FOURIER_K=4 ZERO=1", "CORRECTION=1 ZERO=1", "ANGLE_W=12 ZERO=1"}) {
    const DatapathConfig cfg = DatapathConfig{}.with_rtl_params(p);
    const RegImage img = random_image(cfg, rng);  // drawn before the inputs, in this order
    expect_same(FixedModel(img), random_codes(2000, cfg.in_w, rng));
  }
}

// A correction mode no row of the table has is an InputError naming it before any sample, so the
// vector path never runs it as "no correction".
TEST(FixedBatch, AModeOutsideTheTableIsAnInputErrorNamingIt) {
  std::mt19937_64 rng(3);
  RegImage img = random_image(DatapathConfig{}, rng);
  img.cfg.correction = 3;
  const std::vector<ChannelCodes> codes = random_codes(300, 16, rng);
  std::vector<FixedOutput> out(codes.size());
  try {
    const FixedModel m(img);
    m.run_batch(codes.data(), codes.size(), out.data());
    ADD_FAILURE() << "the batch engine ran correction=3";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("correction=3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace acore
