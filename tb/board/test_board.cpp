// SPDX-License-Identifier: MIT
// The board top (rtl/acore_board.v, registry line board_serial: the serial core; the board is
// simulated in that configuration only, the folded ones are linted and placed) end to end: the
// interface and observer registers (the board's own register block, stages/board_regs.hpp) through
// APB beside the shell's (values read back, out-of-range N, pole pairs and bandwidth codes refused
// with PSLVERR and no effect), then streams of channel codes through the estimator and the
// tracking observer (rtl/acore_track.v):
//   - every estimator output equals FixedModel, and every observer output (tracked and
//     compensated angle, velocity, turn count, loss of tracking) equals the observer's model
//     (model/ip/stages/tracker.cpp) run on the model's angles with the board's register values
//     and COMP_LATENCY = the estimator's LATENCY over its CYCLES (read from CONFIG2), bit for bit;
//   - the ABZ decoder's count equals the model's target of the compensated angle before every
//     sample, UVW follows the compensated angle, and the SPI port's ANGLECOM, ANGLEUNC and
//     DIAAGC.LF, and the APB's TRK_VELOCITY and TRK_POSITION, read the model's values;
//   - MAG and DIAAGC.AGC over SPI and MAG_AGC over APB read the model's (as5047::mag_field,
//     as5047::agc_field of the last sample's magnitude), and at the full, half and quarter field
//     they follow the closed form of the field's length: MAG halves, AGC rises by 32.
#include <gtest/gtest.h>
#include <verilated.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <set>
#include <vector>

// The line the bench is built for: board_serial, or a long-sim board line built by
// tb/CMakeLists.txt with its Verilated class, header and MULT (the estimator's product rule).
#ifndef ACORE_BOARD_CLASS
#define ACORE_BOARD_CLASS Vboard_serial
#define ACORE_BOARD_HEADER "Vboard_serial.h"
#define ACORE_BOARD_MULT 0
#endif
#include ACORE_BOARD_HEADER
#include "core/fixed_point.hpp"
#include "cosim/cosim_stimuli.hpp"
#include "shell/shell_regs.hpp"
#include "stages/board_regs.hpp"
#include "stages/interfaces.hpp"
#include "stages/tracker.hpp"

namespace acore {
namespace {

namespace sh = acore::shell;
namespace bd = acore::board;

// The board's observer build (rtl/acore_board.v: TRK_FRAC_W = 25, the turn count and LEAD as wide
// as TRK_POSITION.TURNS and TRK_LEAD, at the default 16-bit angle); COMP_LATENCY is set from
// CONFIG2.
TrackConfig board_track_config(int comp_latency) {
  TrackConfig c;
  c.angle_w = 16;
  c.frac_w = 25;
  c.turn_w = bd::kTrkPositionTurnsBits;
  c.comp_latency = comp_latency;
  c.lead_w = bd::kTrkLeadLeadBits;
  c.lead_f = bd::kTrkLeadLeadFrac;
  return c;
}

// The estimator's configuration: the defaults with the line's MULT.
DatapathConfig board_datapath() {
  DatapathConfig c;
  c.mult = ACORE_BOARD_MULT;
  return c;
}

int64_t sext(uint64_t x, int w) { return fx::sext(static_cast<int64_t>(x), w); }

struct Board {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<ACORE_BOARD_CLASS> top;
  uint64_t t = 0;
  int last = 0;
  int64_t pos = 0;  // x4 decoder
  uint32_t angle = 0;
  bool have_angle = false;
  // Every output of the estimator and of the observer, as seen on the board's ports.
  std::vector<FixedOutput> est;
  std::vector<TrackOutput> trk;
  // Called after each clock at which the observer delivered, before its angle reaches ABZ.
  std::function<void(Board&)> on_trk;
  Board() {
    ctx = std::make_unique<VerilatedContext>();
    ctx->randReset(2);
    top = std::make_unique<ACORE_BOARD_CLASS>(ctx.get());
    // The inputs start random too (randReset(2)): idle bus, no sample, SPI idle.
    top->psel_i = 0;
    top->penable_i = 0;
    top->pwrite_i = 0;
    top->in_valid_i = 0;
    top->sclk_i = 0;
    top->mosi_i = 0;
    top->csn_i = 1;
    top->rst_i = 1;
    tick();
    tick();
    top->rst_i = 0;
    tick();
  }
  void tick() {
    top->clk_i = 0;
    top->eval();
    top->clk_i = 1;
    top->eval();
    ++t;
    if (top->out_valid_o) {
      angle = top->angle_o;
      have_angle = true;
      est.push_back(FixedOutput{top->angle_o, 0,
                                static_cast<uint8_t>((top->los_o ? 2 : 0) | (top->dos_o ? 4 : 0))});
    }
    if (top->trk_valid_o) {
      TrackOutput o;
      o.angle = top->trk_angle_o;
      o.angle_comp = top->trk_angle_comp_o;
      o.velocity = sext(top->trk_velocity_o, 41);
      o.turns = sext(top->trk_turns_o, 16);
      o.lot = top->trk_lot_o;
      trk.push_back(o);
    }
    static const int gray[2][2] = {{0, 3}, {1, 2}};
    const int g = gray[top->a_o][top->b_o];
    const int d = (g - last + 4) % 4;
    pos += d == 1 ? 1 : d == 3 ? -1 : 0;
    EXPECT_NE(d, 2) << "lost count";
    last = g;
    if (top->trk_valid_o && on_trk) on_trk(*this);
  }
  // One APB transfer; returns PSLVERR, *rdata the read data.
  bool apb(bool write, uint32_t addr, uint32_t wdata, uint32_t* rdata = nullptr) {
    top->psel_i = 1;
    top->penable_i = 0;
    top->pwrite_i = write;
    top->paddr_i = addr;
    top->pwdata_i = wdata;
    top->pstrb_i = 0xF;
    tick();
    top->penable_i = 1;
    top->eval();
    const bool err = top->pslverr_o;
    if (rdata) *rdata = top->prdata_o;
    tick();
    top->psel_i = 0;
    top->penable_i = 0;
    return err;
  }
  uint16_t spi_frame(uint16_t mosi) {
    top->csn_i = 0;
    tick();
    tick();
    uint16_t miso = 0;
    for (int i = 0; i < 16; ++i) {
      top->sclk_i = 1;
      top->mosi_i = (mosi >> (15 - i)) & 1;
      tick();
      tick();
      miso = static_cast<uint16_t>((miso << 1) | top->miso_o);
      top->sclk_i = 0;
      tick();
      tick();
    }
    top->csn_i = 1;
    for (int i = 0; i < 8; ++i) tick();
    return miso;
  }
};

// Writes the identity image (no correction, the real arctangent table) through the shadow window
// and commits it.
void load_identity(Board& b) {
  const RegImage img = cosim::identity_image(board_datapath());
  for (size_t a = 0; a < img.words.size(); ++a)
    ASSERT_FALSE(
        b.apb(true, sh::kCoef + 4 * static_cast<uint32_t>(a), static_cast<uint32_t>(img.words[a])));
  ASSERT_FALSE(b.apb(true, sh::kCtrl, sh::kCtrlScrub | sh::kCtrlCommit));
  uint32_t st = sh::kStatusBusy;
  for (int i = 0; i < 100000 && (st & sh::kStatusBusy); ++i) b.apb(false, sh::kStatus, 0, &st);
  ASSERT_FALSE(st & sh::kStatusBusy);
}

// A channel code of a unit component (two's complement, 8000 codes of the image's 8192 a unit):
// the RTL's 16-bit word and the model's signed value.
int32_t unit_code(double x) { return static_cast<int32_t>(std::lround(8000 * x)); }

TEST(Board, InterfaceRegistersThroughApb) {
  Board b;
  uint32_t v = 0;
  // The ranges of the description (the model's: stages/interfaces.hpp refuses the same values).
  const uint32_t n_max = static_cast<uint32_t>(bd::kAbzNNMax),
                 pp_max = static_cast<uint32_t>(bd::kUvwPpPolePairsMax);
  EXPECT_FALSE(b.apb(false, bd::kAbzN, 0, &v));
  EXPECT_EQ(v, 1024u);
  EXPECT_FALSE(b.apb(true, bd::kAbzN, 1000, nullptr));
  EXPECT_TRUE(b.apb(true, bd::kAbzN, 0, nullptr));
  EXPECT_TRUE(b.apb(true, bd::kAbzN, n_max + 1, nullptr));
  EXPECT_FALSE(b.apb(false, bd::kAbzN, 0, &v));
  EXPECT_EQ(v, 1000u) << "a refused write has no effect";
  EXPECT_FALSE(b.apb(true, bd::kAbzN, n_max, nullptr));
  EXPECT_FALSE(b.apb(false, bd::kAbzN, 0, &v));
  EXPECT_EQ(v, n_max);
  EXPECT_TRUE(b.apb(true, bd::kUvwPp, pp_max + 1, nullptr));
  EXPECT_TRUE(b.apb(true, bd::kUvwPp, 0, nullptr));
  EXPECT_FALSE(b.apb(true, bd::kUvwPp, pp_max, nullptr));
  EXPECT_FALSE(b.apb(false, bd::kUvwPp, 0, &v));
  EXPECT_EQ(v, pp_max);
  for (uint32_t addr : {bd::kAbzIndex, bd::kAbzSpacing, bd::kUvwOffset, bd::kTrkLot, bd::kIfZero}) {
    EXPECT_FALSE(b.apb(true, addr, 0x1234, nullptr));
    EXPECT_FALSE(b.apb(false, addr, 0, &v));
    EXPECT_EQ(v, 0x1234u) << addr;
  }
  // The observer's registers: reset values, the bandwidth code's range (the model's: kMin ..
  // k_max() of the board's FRAC_W), LEAD's 8 bits, the read-only velocity and position.
  const TrackConfig tc = board_track_config(0);
  EXPECT_FALSE(b.apb(false, bd::kTrkBw, 0, &v));
  EXPECT_EQ(v, bd::kTrkBwReset);
  EXPECT_EQ(static_cast<int>(v), TrackRegs{}.bw) << "the model's default code";
  EXPECT_FALSE(b.apb(false, bd::kTrkLead, 0, &v));
  EXPECT_EQ(v, 0u);
  for (uint32_t bw = 0; bw <= 20; ++bw) {
    const bool ok = static_cast<int>(bw) >= TrackConfig::kMin && static_cast<int>(bw) <= tc.k_max();
    EXPECT_EQ(b.apb(true, bd::kTrkBw, bw, nullptr), !ok) << bw;
    EXPECT_FALSE(b.apb(false, bd::kTrkBw, 0, &v));
    if (ok) EXPECT_EQ(v, bw);
  }
  EXPECT_EQ(v, static_cast<uint32_t>(tc.k_max())) << "a refused write has no effect";
  EXPECT_TRUE(b.apb(true, bd::kTrkBw, 0x10004, nullptr)) << "upper bits are not ignored";
  EXPECT_FALSE(b.apb(true, bd::kTrkLead, 0xFF, nullptr));
  EXPECT_FALSE(b.apb(false, bd::kTrkLead, 0, &v));
  EXPECT_EQ(v, 0xFFu);
  EXPECT_TRUE(b.apb(true, bd::kTrkVelocity, 1, nullptr)) << "read only";
  EXPECT_TRUE(b.apb(true, bd::kTrkPosition, 1, nullptr)) << "read only";
  EXPECT_FALSE(b.apb(false, bd::kTrkVelocity, 0, &v));
  EXPECT_EQ(v, 0u) << "no sample yet";
}

// The bus split: every word address of the 4 KiB space is answered by exactly one map, the shell's
// (its registers and its shadow window) or the board's, with the shell's rules; an unaligned
// address at a board register is an error as at a shell register.
TEST(Board, EveryAddressIsAnsweredByOneMap) {
  Board b;
  const std::vector<uint32_t> shell = {
      sh::kId,          sh::kConfig0,   sh::kConfig1, sh::kConfig2,  sh::kConfig3,
      sh::kCtrl,        sh::kStatus,    sh::kIrq,     sh::kMagLo,    sh::kMagHi,
      sh::kCrcExpected, sh::kCrcShadow, sh::kCrcRef,  sh::kCrcScrub, sh::kScrubPasses};
  const std::vector<uint32_t> board = {
      bd::kAbzN,   bd::kAbzIndex, bd::kAbzSpacing, bd::kUvwPp,       bd::kUvwOffset,
      bd::kTrkBw,  bd::kTrkLead,  bd::kTrkLot,     bd::kTrkVelocity, bd::kTrkPosition,
      bd::kAbzHys, bd::kIfZero,   bd::kIfCtrl,     bd::kMagAgc};
  uint32_t cfg1 = 0;
  ASSERT_FALSE(b.apb(false, sh::kConfig1, 0, &cfg1));
  const uint32_t words = (cfg1 & sh::kConfig1WordsMask) >> sh::kConfig1WordsShift;
  size_t wrong = 0, nonzero_on_error = 0, answered = 0;
  for (uint32_t addr = 0; addr < sh::kAddrSpace; addr += 4) {
    const bool mapped = std::count(shell.begin(), shell.end(), addr) ||
                        std::count(board.begin(), board.end(), addr) ||
                        (addr >= sh::kCoef && addr < sh::kCoef + 4 * words);
    uint32_t v = 0;
    const bool err = b.apb(false, addr, 0, &v);
    wrong += err == mapped;
    nonzero_on_error += err && v != 0;
    answered += !err;
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(nonzero_on_error, 0u);
  EXPECT_EQ(answered, shell.size() + board.size() + words);
  for (uint32_t off = 1; off < 4; ++off) {
    EXPECT_TRUE(b.apb(false, bd::kAbzN + off, 0, nullptr)) << off;
    EXPECT_TRUE(b.apb(true, bd::kAbzN + off, 7, nullptr)) << off;
  }
  uint32_t v = 0;
  EXPECT_FALSE(b.apb(false, bd::kAbzN, 0, &v));
  EXPECT_EQ(v, bd::kAbzNReset) << "an unaligned write has no effect";
  // The shell's registers still work behind the split, back to back with the board's.
  EXPECT_FALSE(b.apb(true, sh::kCrcExpected, 0x12345678, nullptr));
  EXPECT_FALSE(b.apb(true, bd::kAbzSpacing, 0x4321, nullptr));
  EXPECT_FALSE(b.apb(false, sh::kCrcExpected, 0, &v));
  EXPECT_EQ(v, 0x12345678u);
  EXPECT_FALSE(b.apb(false, bd::kAbzSpacing, 0, &v));
  EXPECT_EQ(v, 0x4321u);
}

// MAG and AGC after streams of a rotating vector at the full, half and quarter field (2 x 8000,
// 8000, 4000 codes of differential amplitude: 1.95, 0.98, 0.49 of the identity image's calibrated
// unit): over SPI (MAG, DIAAGC.AGC) and APB (MAG_AGC) the model's values of the last sample, and
// against the closed form of the vector length L (scaled units) times the CORDIC gain g:
// m = L g 2^S_F, MAG = m / 2^(S_W-13) within 1 %, AGC = 128 + 32 (S_F + 0.625 - log2 m) within
// its 4-code bound; each halving halves MAG and adds 32 to AGC (the AS5047P's sense).
TEST(Board, MagAndAgcFollowTheField) {
  Board b;
  uint32_t v = 0;
  EXPECT_FALSE(b.apb(false, bd::kMagAgc, 0, &v));
  EXPECT_EQ(v, 0xFFu) << "before any sample: MAG 0, AGC 255 (no field)";
  EXPECT_TRUE(b.apb(true, bd::kMagAgc, 1, nullptr)) << "read only";
  load_identity(b);
  if (::testing::Test::HasFatalFailure()) return;
  const DatapathConfig cfg = board_datapath();
  const int mag_w = cfg.s_w + 2;  // rtl/acore_derived.vh's acore_mag_w
  const FixedModel model(cosim::identity_image(cfg), StatusWindow{0, INT64_MAX});
  double gain = 1.0;
  for (int i = 0; i < cfg.iterations; ++i) gain *= std::sqrt(1.0 + std::ldexp(1.0, -2 * i));
  int prev_mag = -1, prev_agc = -1;
  double th = 0.3;
  for (double amp : {1.0, 0.5, 0.25}) {
    int64_t m = 0;
    for (int i = 0; i < 40; ++i) {
      th += 0.013;
      const ChannelCodes c{unit_code(amp * std::cos(th)), unit_code(amp * std::sin(th)),
                           unit_code(-amp * std::cos(th)), unit_code(-amp * std::sin(th))};
      m = model.step(c).magnitude;
      const auto word = [](int32_t x) { return static_cast<uint32_t>(x) & 0xFFFF; };
      b.top->c1_i = word(c[0]);
      b.top->c2_i = word(c[1]);
      b.top->c3_i = word(c[2]);
      b.top->c4_i = word(c[3]);
      b.top->in_valid_i = 1;
      b.top->eval();
      while (!b.top->in_ready_o) b.tick();
      b.tick();
      b.top->in_valid_i = 0;
    }
    for (int i = 0; i < 600; ++i) b.tick();
    b.spi_frame(as5047::with_even_parity(0x4000 | as5047::kMag));
    const uint16_t mag = b.spi_frame(as5047::with_even_parity(0x4000 | as5047::kDiaagc)) & 0x3FFF;
    const uint16_t dia = b.spi_frame(as5047::kNop);
    const int agc = dia & as5047::kDiaagcAgcMask;
    EXPECT_TRUE(as5047::parity_even(dia));
    EXPECT_EQ(mag, as5047::mag_field(m, mag_w)) << "MAG at amplitude " << amp;
    EXPECT_EQ(agc, as5047::agc_field(m, cfg.s_f)) << "AGC at amplitude " << amp;
    EXPECT_FALSE(b.apb(false, bd::kMagAgc, 0, &v));
    EXPECT_EQ((v & bd::kMagAgcMagMask) >> bd::kMagAgcMagShift, mag);
    EXPECT_EQ((v & bd::kMagAgcAgcMask) >> bd::kMagAgcAgcShift, static_cast<uint32_t>(agc));
    // The closed form: L = 2 amp 8000 / 8192 scaled units.
    const double m_exact = 2 * amp * 8000 / 8192 * gain * std::ldexp(1.0, cfg.s_f);
    const double mag_exact = m_exact / std::ldexp(1.0, mag_w - 15);
    EXPECT_NEAR(mag, mag_exact, 0.01 * mag_exact) << amp;
    const double agc_exact = 128 + 32 * (cfg.s_f + 0.625 - std::log2(m_exact));
    EXPECT_GE(agc, agc_exact - 1) << amp;
    EXPECT_LE(agc, agc_exact + 32 * 0.0861 + 2) << amp;
    if (prev_mag >= 0) {
      EXPECT_NEAR(mag, prev_mag / 2.0, 2.0) << "half the field: half MAG";
      EXPECT_NEAR(agc - prev_agc, 32, 2) << "half the field: AGC + 32";
    }
    std::printf("board_serial MAG/AGC at %.2f of the stream's field: m %lld, MAG %u, AGC %d\n", amp,
                static_cast<long long>(m), mag, agc);
    prev_mag = mag;
    prev_agc = agc;
  }
}

// One co-sim run: the registers written, `n` samples of a rotating vector streamed at full rate
// (speed w0 turns a sample for the first half, w1 after: a speed step), every output compared.
struct RunResult {
  size_t samples = 0, est_mismatches = 0, trk_mismatches = 0, abz_checks = 0, lot_samples = 0;
};

// write_regs false: the registers keep their reset values (bw, lead, lot_thr unused).
RunResult run_stream(int bw, uint32_t lead, uint32_t lot_thr, bool write_regs, int n, double w0,
                     double w1) {
  RunResult res;
  Board b;
  load_identity(b);
  if (::testing::Test::HasFatalFailure()) return res;
  uint32_t cfg2 = 0;
  EXPECT_FALSE(b.apb(false, sh::kConfig2, 0, &cfg2));
  const int latency =
      static_cast<int>((cfg2 & sh::kConfig2LatencyMask) >> sh::kConfig2LatencyShift);
  const int cycles = static_cast<int>((cfg2 & sh::kConfig2CyclesMask) >> sh::kConfig2CyclesShift);
  EXPECT_GT(cycles, 1);
  // ABZ converts an angle to its target in 3 ceil(N_W / 2) + 5 clocks (rtl/acore_abz.v; the board
  // makes N_W the ABZ_N field's width) and then emits one count a clock at most: the check below
  // (the previous target reached before the next observer output) holds while a sample's counts fit
  // in the clocks left of a sample. The serial core's clocks leave room for the speeds asked; a
  // folded board's 32 do not, so the run scales its speeds down to fit, and the loss-of-tracking
  // threshold with them (the loop's error scales with the speed step: the step still raises it),
  // and streams as many more samples (the angle turns as far).
  const int abz_latency = 3 * ((bd::kAbzNNBits + 1) / 2) + 5;
  const double counts =
      4.0 * bd::kAbzNReset * std::max(std::fabs(w0), std::fabs(w1));  // N at reset
  const double scale = std::min(1.0, (cycles - abz_latency - 2) / counts);
  EXPECT_GT(scale, 0.0) << "the board's " << cycles << " clocks a sample leave ABZ no count";
  if (scale < 1) {
    w0 *= scale;
    w1 *= scale;
    lot_thr = static_cast<uint32_t>(std::lround(lot_thr * scale));
    n = static_cast<int>(std::lround(n / scale));
  }
  if (write_regs) {
    EXPECT_FALSE(b.apb(true, bd::kTrkBw, static_cast<uint32_t>(bw)));
    EXPECT_FALSE(b.apb(true, bd::kTrkLead, lead));
    EXPECT_FALSE(b.apb(true, bd::kTrkLot, lot_thr));
  }
  const TrackConfig tc = board_track_config(latency / cycles);
  // The model runs with the register values the board reads back (written, or the reset values).
  uint32_t rb_bw = 0, rb_lead = 0, rb_lot = 0;
  EXPECT_FALSE(b.apb(false, bd::kTrkBw, 0, &rb_bw));
  EXPECT_FALSE(b.apb(false, bd::kTrkLead, 0, &rb_lead));
  EXPECT_FALSE(b.apb(false, bd::kTrkLot, 0, &rb_lot));
  if (write_regs) {
    EXPECT_EQ(rb_bw, static_cast<uint32_t>(bw));
    EXPECT_EQ(rb_lead, lead);
    EXPECT_EQ(rb_lot, lot_thr);
  }
  TrackRegs tr;
  tr.bw = static_cast<int>(rb_bw);
  tr.lead = rb_lead;
  tr.lot_thr = rb_lot;

  // The stimulus and the model's expectation: estimator, then observer.
  std::vector<ChannelCodes> in;
  double th = 0.1;
  for (int i = 0; i < n; ++i) {
    th += 2 * M_PI * (i < n / 2 ? w0 : w1);
    in.push_back({unit_code(std::cos(th)), unit_code(std::sin(th)), unit_code(-std::cos(th)),
                  unit_code(-std::sin(th))});
  }
  const FixedModel model(cosim::identity_image(board_datapath()), StatusWindow{0, INT64_MAX});
  std::vector<FixedOutput> est_model;
  std::vector<uint32_t> angles;
  std::vector<int64_t> mags;
  for (const auto& c : in) {
    const FixedSample fs = model.step(c);
    mags.push_back(fs.magnitude);
    FixedOutput o = to_output(fs);
    o.region = 0;  // the board shows the angle, los and dos (not the region, nor ovf)
    o.flags &= 6;
    est_model.push_back(o);
    angles.push_back(est_model.back().angle);
  }
  const std::vector<TrackOutput> trk_model = track_codes(angles, tc, tr);

  // ABZ (N = 1024 at reset: the count walks from 0 to each target): before the observer's next
  // output reaches it, the decoder has caught up with the previous one's target.
  const int64_t abz_n = 1024;
  int64_t target = 0;
  b.on_trk = [&](Board& bb) {
    const int64_t wrapped = ((bb.pos % (4 * abz_n)) + 4 * abz_n) % (4 * abz_n);
    EXPECT_EQ(wrapped, target) << "ABZ before output " << bb.trk.size() - 1;
    ++res.abz_checks;
    target = abz_target(bb.trk.back().angle_comp, 16, abz_n, bd::kAbzHysReset, target);
  };
  const auto check_reads = [&](size_t k) {  // after k samples, the stream paused
    for (int i = 0; i < 600; ++i) b.tick();
    EXPECT_EQ(b.trk.size(), k);
    if (k == 0 || b.trk.size() != k) return;
    const TrackOutput& m = trk_model[k - 1];
    b.spi_frame(as5047::with_even_parity(0x4000 | as5047::kAnglecom));
    const uint16_t com = b.spi_frame(as5047::with_even_parity(0x4000 | as5047::kAngleunc));
    const uint16_t unc = b.spi_frame(as5047::with_even_parity(0x4000 | as5047::kDiaagc));
    const uint16_t dia = b.spi_frame(as5047::kNop);
    EXPECT_EQ(com & 0x3FFFu, m.angle_comp >> 2) << "ANGLECOM after " << k;
    EXPECT_EQ(unc & 0x3FFFu, est_model[k - 1].angle >> 2) << "ANGLEUNC after " << k;
    EXPECT_EQ((dia >> 8) & 1, m.lot ? 0 : 1) << "DIAAGC.LF after " << k;
    EXPECT_EQ(dia & as5047::kDiaagcAgcMask, as5047::agc_field(mags[k - 1], board_datapath().s_f))
        << "DIAAGC.AGC after " << k;
    b.spi_frame(as5047::with_even_parity(0x4000 | as5047::kMag));
    EXPECT_EQ(b.spi_frame(as5047::kNop) & 0x3FFF,
              as5047::mag_field(mags[k - 1], board_datapath().s_w + 2))
        << "MAG after " << k;
    uint32_t vel = 0, posn = 0;
    EXPECT_FALSE(b.apb(false, bd::kTrkVelocity, 0, &vel));
    EXPECT_FALSE(b.apb(false, bd::kTrkPosition, 0, &posn));
    EXPECT_EQ(vel, static_cast<uint32_t>(static_cast<uint64_t>(m.velocity) >> 9)) << k;
    EXPECT_EQ(posn, (static_cast<uint32_t>(m.turns & 0xFFFF) << 16) | m.angle) << k;
    const UvwState s = uvw_state(m.angle_comp, 0, 16, 1);
    EXPECT_EQ(b.top->u_o, s.u);
    EXPECT_EQ(b.top->v_o, s.v);
    EXPECT_EQ(b.top->w_o, s.w);
  };
  for (int i = 0; i < n; ++i) {
    if (i == n / 2 || i == n / 4) check_reads(static_cast<size_t>(i));
    const auto word = [](int32_t c) { return static_cast<uint32_t>(c) & 0xFFFF; };
    b.top->c1_i = word(in[i][0]);
    b.top->c2_i = word(in[i][1]);
    b.top->c3_i = word(in[i][2]);
    b.top->c4_i = word(in[i][3]);
    b.top->in_valid_i = 1;
    b.top->eval();
    while (!b.top->in_ready_o) b.tick();
    b.tick();
    b.top->in_valid_i = 0;
    // After the first sample the count walks from 0 (reset) to its target, up to 2N edges at one a
    // clock: a pause, then every later target is caught up within a sample.
    if (i == 0)
      for (int j = 0; j < 3 * abz_n; ++j) b.tick();
  }
  check_reads(static_cast<size_t>(n));
  for (int i = 0; i < 600; ++i) b.tick();

  res.samples = in.size();
  if (b.est.size() != est_model.size()) ++res.est_mismatches;
  if (b.trk.size() != trk_model.size()) ++res.trk_mismatches;
  for (size_t i = 0; i < std::min(b.est.size(), est_model.size()); ++i)
    if (!(b.est[i] == est_model[i])) {
      if (res.est_mismatches < 5)
        ADD_FAILURE() << "estimator sample " << i << ": rtl " << b.est[i].angle << " model "
                      << est_model[i].angle;
      ++res.est_mismatches;
    }
  for (size_t i = 0; i < std::min(b.trk.size(), trk_model.size()); ++i) {
    const TrackOutput &r = b.trk[i], &m = trk_model[i];
    res.lot_samples += m.lot;
    if (r.angle != m.angle || r.angle_comp != m.angle_comp || r.velocity != m.velocity ||
        r.turns != m.turns || r.lot != m.lot) {
      if (res.trk_mismatches < 5)
        ADD_FAILURE() << "observer sample " << i << ": rtl angle " << r.angle << " comp "
                      << r.angle_comp << " v " << r.velocity << " turns " << r.turns << " lot "
                      << r.lot << "; model " << m.angle << " " << m.angle_comp << " " << m.velocity
                      << " " << m.turns << " " << m.lot;
      ++res.trk_mismatches;
    }
  }
  // The decoder's count after the last catch-up.
  const int64_t wrapped = ((b.pos % (4 * abz_n)) + 4 * abz_n) % (4 * abz_n);
  EXPECT_EQ(wrapped, target) << "ABZ after the stream";
  // The stream turned: the turn count moved with the angle.
  EXPECT_GE(std::llabs(trk_model.back().turns), 1);
  std::printf(
      "board co-sim: bw %d lead %u/16 lot %u COMP_LATENCY %d (LATENCY %d, CYCLES %d): "
      "%zu samples, %zu estimator and %zu observer mismatches, %zu ABZ checks, %zu LOT "
      "samples, last turns %lld\n",
      tr.bw, tr.lead, tr.lot_thr, tc.comp_latency, latency, cycles, res.samples, res.est_mismatches,
      res.trk_mismatches, res.abz_checks, res.lot_samples,
      static_cast<long long>(trk_model.back().turns));
  return res;
}

// Constant speed then a speed step (x3.5), with a narrow loop, a lead and a low LOT threshold
// (the step raises LOT and it clears), and at the registers' reset values.
TEST(Board, ObserverOnTheEstimatorEqualsTheModels) {
  const RunResult a = run_stream(4, 0x25, 600, true, 3000, 0.003, 0.0105);
  EXPECT_GE(a.samples, 3000u);
  EXPECT_EQ(a.est_mismatches, 0u);
  EXPECT_EQ(a.trk_mismatches, 0u);
  EXPECT_GT(a.lot_samples, 0u) << "the speed step raised loss of tracking";
  EXPECT_GE(a.abz_checks, 3000u);
  const RunResult r = run_stream(0, 0, 0, false, 2000, -0.004, 0.002);
  EXPECT_GE(r.samples, 2000u);
  EXPECT_EQ(r.est_mismatches, 0u);
  EXPECT_EQ(r.trk_mismatches, 0u);
}

// Large steps between samples, each followed by a long pause: ABZ catches up, UVW and SPI read the
// observer's compensated angle, ANGLEUNC the estimator's.
TEST(Board, InterfacesFollowTheCompensatedAngle) {
  Board b;
  const int64_t n = 1000;
  const int pp = 7;
  const uint32_t offset = 0x2345;
  load_identity(b);
  if (HasFatalFailure()) return;
  ASSERT_FALSE(b.apb(true, bd::kAbzN, n, nullptr));
  ASSERT_FALSE(b.apb(true, bd::kAbzIndex, 17, nullptr));
  ASSERT_FALSE(b.apb(true, bd::kAbzSpacing, 2, nullptr));
  ASSERT_FALSE(b.apb(true, bd::kUvwPp, pp, nullptr));
  ASSERT_FALSE(b.apb(true, bd::kUvwOffset, offset, nullptr));
  std::mt19937_64 rng(31);
  int64_t target = 0;
  int samples = 0;
  std::set<uint32_t> angles;
  for (int k = 0; k < 40; ++k) {
    // Channel codes of a rotating vector (two's complement, 8000 codes of the image's 8192 a unit).
    const double th = 0.37 * k;
    const auto code = [](double x) {
      return static_cast<uint32_t>(std::lround(8000 * x)) & 0xFFFF;
    };
    b.top->c1_i = code(std::cos(th));
    b.top->c2_i = code(std::sin(th));
    b.top->c3_i = code(-std::cos(th));
    b.top->c4_i = code(-std::sin(th));
    b.top->in_valid_i = 1;
    while (!b.top->in_ready_o) b.tick();
    b.tick();
    b.top->in_valid_i = 0;
    const bool had = b.have_angle;
    b.have_angle = false;
    for (int i = 0; i < 400 && !b.have_angle; ++i) b.tick();
    ASSERT_TRUE(b.have_angle) << k << " " << had;
    ++samples;
    angles.insert(b.angle);
    for (int i = 0; i < 3 * 4 * n + 100; ++i) b.tick();
    ASSERT_EQ(b.trk.size(), static_cast<size_t>(samples));
    const uint32_t com = b.trk.back().angle_comp;
    target = abz_target(com, 16, n, bd::kAbzHysReset, target);
    // N was written before the first angle (the count stays 0 until one arrives): the drive
    // homes its decoder once, as after power-up (here to the model's count; an SPI read gives it).
    if (k == 0) b.pos = target;
    const int64_t wrapped = ((b.pos % (4 * n)) + 4 * n) % (4 * n);
    ASSERT_EQ(wrapped, target) << "sample " << k << " angle " << com;
    const UvwState s = uvw_state(com, offset, 16, pp);
    EXPECT_EQ(b.top->u_o, s.u);
    EXPECT_EQ(b.top->v_o, s.v);
    EXPECT_EQ(b.top->w_o, s.w);
    // ODrive's read: 0xFFFF twice, the second answer is ANGLECOM = the angle's upper 14 bits.
    b.spi_frame(0xFFFF);
    const uint16_t raw = b.spi_frame(as5047::with_even_parity(0x7FFE));  // then ANGLEUNC
    EXPECT_TRUE(as5047::parity_even(raw));
    EXPECT_FALSE((raw >> 14) & 1);
    EXPECT_EQ(raw & 0x3FFFu, com >> 2);
    const uint16_t unc = b.spi_frame(as5047::with_even_parity(0x7FFC));  // then DIAAGC
    EXPECT_EQ(unc & 0x3FFFu, b.angle >> 2) << "ANGLEUNC: the estimator's angle";
    const uint16_t diag = b.spi_frame(0x0000);
    EXPECT_EQ((diag >> 8) & 1, b.trk.back().lot ? 0 : 1) << "LF: not loss of tracking";
  }
  EXPECT_EQ(samples, 40);
  EXPECT_GT(angles.size(), 30u) << "the estimator's angle moved";
}

// The AS5047P configuration a drive's driver does at start-up, through the board's SPI pins with
// the framings of SimpleFOC's AS5047 driver (its constants: reads 0xC017/0x4016/0xC018/0x4019, the
// answer collected with 0xFFFF; writes 0x8016/0x0017/0x0018/0x8019, then the data word with its
// parity) and ODrive's read (0xFFFF every transfer, each answer's parity and EF checked), written
// from the datasheet: the zero written to ZPOS moves ANGLECOM by exactly that amount, DIR reverses
// it, ABIRES with ABIBIN sets the pulses a turn the ABZ decoder counts; every setting is the
// board's register (APB reads what SPI wrote) and the data frame answers the old content.
TEST(Board, SpiConfigurationRoundTripWithDriverFramings) {
  Board b;
  load_identity(b);
  if (HasFatalFailure()) return;
  const auto parity_ok = [](uint16_t w) { return as5047::parity_even(w); };
  // ODrive: one transfer, the answer (to the previous command) checked.
  int refused = 0;
  const auto odrive = [&](uint16_t cmd) {
    const uint16_t a = b.spi_frame(cmd);
    refused += !parity_ok(a) || ((a >> 14) & 1);
    return static_cast<uint16_t>(a & 0x3FFF);
  };
  // SimpleFOC: spi_transfer16 then nop() (0xFFFF) for a read; command then data for a write.
  const auto calc_parity = [](uint16_t d) { return as5047::with_even_parity(d & 0x7FFF); };
  const auto sf_read = [&](uint16_t cmd) {
    b.spi_frame(cmd);
    return static_cast<uint16_t>(b.spi_frame(0xFFFF) & 0x3FFF);
  };
  const auto sf_write = [&](uint16_t cmd, uint16_t data) {
    b.spi_frame(cmd);
    return static_cast<uint16_t>(b.spi_frame(calc_parity(data)) & 0x3FFF);  // the old content
  };
  // Samples of a vector at angle th (turns), the stream then paused: the observer's compensated
  // angle of the last sample, from the board's own outputs.
  const auto samples = [&](double th, int count) {
    for (int k = 0; k < count; ++k) {
      b.top->c1_i = static_cast<uint32_t>(unit_code(std::cos(2 * M_PI * th))) & 0xFFFF;
      b.top->c2_i = static_cast<uint32_t>(unit_code(std::sin(2 * M_PI * th))) & 0xFFFF;
      b.top->c3_i = static_cast<uint32_t>(unit_code(-std::cos(2 * M_PI * th))) & 0xFFFF;
      b.top->c4_i = static_cast<uint32_t>(unit_code(-std::sin(2 * M_PI * th))) & 0xFFFF;
      b.top->in_valid_i = 1;
      while (!b.top->in_ready_o) b.tick();
      b.tick();
      b.top->in_valid_i = 0;
      for (int i = 0; i < 400; ++i) b.tick();
    }
    for (int i = 0; i < 5000; ++i) b.tick();  // ABZ caught up
    return b.trk.back().angle_comp;
  };
  // The observer at its fastest bandwidth: it settles within a few samples.
  ASSERT_FALSE(b.apb(true, bd::kTrkBw, static_cast<uint32_t>(TrackConfig::kMin), nullptr));
  const uint32_t com = samples(0.3, 40);
  odrive(0xFFFF);
  EXPECT_EQ(odrive(0xFFFF), com >> 2) << "ANGLECOM before any setting";
  // setZero(z): read ZPOSL (for its error-enable bits), write ZPOSM, write ZPOSL.
  const uint16_t z = 0x1A2B;
  EXPECT_EQ(sf_read(0xC017), 0u);
  EXPECT_EQ(sf_write(0x8016, (z >> 6) & 0xFF), 0u) << "the data frame answers the old ZPOSM";
  EXPECT_EQ(sf_write(0x0017, z & 0x3F), 0u);
  uint32_t v = 0;
  EXPECT_FALSE(b.apb(false, bd::kIfZero, 0, &v));
  EXPECT_EQ(v, z) << "ZPOS is the board's IF_ZERO";
  // getZero() reads it back; then ANGLECOM has moved by exactly z (ODrive's read).
  b.spi_frame(0x4016);
  const uint16_t zposm = static_cast<uint16_t>(b.spi_frame(0xC017) & 0xFF);
  const uint16_t zposl = static_cast<uint16_t>(b.spi_frame(0xFFFF) & 0x3F);
  EXPECT_EQ((zposm << 6) | zposl, z);
  odrive(0xFFFF);
  const uint16_t zeroed = odrive(0xFFFF);
  EXPECT_EQ(zeroed, ((com >> 2) - z) & 0x3FFF) << "ANGLECOM = angle - ZPOS";
  // DIR (SETTINGS1 bit 2, read-modify-write as the driver's writeSettings1): the angle counts the
  // other way: -(angle - ZPOS), within the LSB the 16-bit angle has below the 14 bits.
  uint16_t s1 = sf_read(0xC018);
  EXPECT_EQ(s1 & 1, 1) << "SETTINGS1 bit 0 reads 1";
  s1 = static_cast<uint16_t>(s1 | 0x04);
  sf_write(0x0018, s1);
  odrive(0xFFFF);
  const uint16_t reversed = odrive(0xFFFF);
  EXPECT_EQ(reversed, ((z << 2) - com) >> 2 & 0x3FFF);
  const int diff = (reversed + zeroed) & 0x3FFF;
  EXPECT_TRUE(diff == 0 || diff == 0x3FFF) << "DIR negates: " << reversed << " vs " << zeroed;
  EXPECT_FALSE(b.apb(false, bd::kIfCtrl, 0, &v));
  EXPECT_EQ(v & bd::kIfCtrlDir, bd::kIfCtrlDir);
  // Back to DIR 0, zero 0, then setABIResolution(AS5047_ABI_2048): ABIBIN 1, ABIRES 1: 512 pulses.
  sf_write(0x0018, static_cast<uint16_t>(s1 & ~0x04));
  sf_write(0x8016, 0);
  sf_write(0x0017, 0);
  s1 = sf_read(0xC018);
  sf_write(0x0018, static_cast<uint16_t>((s1 | 0x20) & ~0x08));
  uint16_t s2 = sf_read(0x4019);
  s2 = static_cast<uint16_t>((s2 & ~0xE0) | (1 << 5));
  sf_write(0x8019, s2);
  EXPECT_EQ(sf_read(0x4019), s2) << "SETTINGS2 reads back";
  EXPECT_FALSE(b.apb(false, bd::kAbzN, 0, &v));
  EXPECT_EQ(v, 512u) << "ABIRES is the board's ABZ_N";
  // A quarter turn in small steps: the decoder counts 4 N / 4 = N counts (one count of hysteresis
  // and rounding either way); then AS5047_ABI_4000 (decimal, code 0): 1000 pulses.
  for (int64_t n : {int64_t{512}, int64_t{1000}}) {
    if (n == 1000) {
      s1 = sf_read(0xC018);
      sf_write(0x0018, static_cast<uint16_t>(s1 & ~0x20));
      s2 = sf_read(0x4019);
      sf_write(0x8019, static_cast<uint16_t>(s2 & ~0xE0));
      EXPECT_FALSE(b.apb(false, bd::kAbzN, 0, &v));
      EXPECT_EQ(v, 1000u);
    }
    const uint32_t start = samples(0.3, 20);
    const int64_t pos0 = b.pos;
    for (int k = 1; k < 25; ++k) samples(0.3 + 0.01 * k, 1);
    const uint32_t end = samples(0.55, 20);
    // (The angles stay within 0.4 .. 0.75 turn: no wrap between start and end.)
    const auto counts = [&](int64_t pulses) {
      return ((static_cast<int64_t>(end) * 4 * pulses) >> 16) -
             ((static_cast<int64_t>(start) * 4 * pulses) >> 16);
    };
    const int64_t expected = counts(n);
    EXPECT_NEAR(static_cast<double>(b.pos - pos0), static_cast<double>(expected), 1.0) << n;
    // About a quarter turn, either way round (the estimator's angle convention), and not the
    // count AngleCore's reset N would give.
    EXPECT_GT(std::llabs(expected), 4 * n / 5) << n;
    EXPECT_LT(std::llabs(expected), 6 * n / 5) << n;
    EXPECT_GT(std::llabs(b.pos - pos0 - counts(1024)), 2) << n;
  }
  EXPECT_EQ(refused, 0) << "ODrive refused no answer";
}

}  // namespace
}  // namespace acore
