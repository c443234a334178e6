// SPDX-License-Identifier: MIT
// The board top (rtl/acore_board.v, registry line board_serial: the serial core) end to end: the
// interface registers through APB (values read back, out-of-range N and pole pairs refused with
// PSLVERR and no effect, the addresses outside the map of a plain shell now mapped), then a stream
// of channel codes through the estimator; after it, the ABZ decoder's count, the UVW signals and
// an ODrive-style SPI read all agree with the board's own last output angle (the model's
// expectation of each interface, model/ip/stages/interfaces.hpp). Until the tracker is wired in,
// ANGLECOM reads the same as ANGLEUNC and DIAAGC.LF is 1 (no loss of tracking).
#include <gtest/gtest.h>
#include <verilated.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <set>

#include "Vboard_serial.h"
#include "cosim_stimuli.hpp"
#include "shell_regs.hpp"
#include "stages/interfaces.hpp"

namespace acore {
namespace {

namespace sh = acore::shell;

struct Board {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<Vboard_serial> top;
  uint64_t t = 0;
  int last = 0;
  int64_t pos = 0;  // x4 decoder
  uint32_t angle = 0;
  bool have_angle = false;
  Board() {
    ctx = std::make_unique<VerilatedContext>();
    ctx->randReset(2);
    top = std::make_unique<Vboard_serial>(ctx.get());
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
    }
    static const int gray[2][2] = {{0, 3}, {1, 2}};
    const int g = gray[top->a_o][top->b_o];
    const int d = (g - last + 4) % 4;
    pos += d == 1 ? 1 : d == 3 ? -1 : 0;
    EXPECT_NE(d, 2) << "lost count";
    last = g;
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

TEST(Board, InterfaceRegistersThroughApb) {
  Board b;
  uint32_t v = 0;
  EXPECT_FALSE(b.apb(false, sh::kAbzN, 0, &v));
  EXPECT_EQ(v, 1024u);
  EXPECT_FALSE(b.apb(true, sh::kAbzN, 1000, nullptr));
  EXPECT_TRUE(b.apb(true, sh::kAbzN, 0, nullptr));
  EXPECT_TRUE(b.apb(true, sh::kAbzN, 4097, nullptr));
  EXPECT_FALSE(b.apb(false, sh::kAbzN, 0, &v));
  EXPECT_EQ(v, 1000u) << "a refused write has no effect";
  EXPECT_FALSE(b.apb(true, sh::kAbzN, 4096, nullptr));
  EXPECT_FALSE(b.apb(false, sh::kAbzN, 0, &v));
  EXPECT_EQ(v, 4096u);
  EXPECT_TRUE(b.apb(true, sh::kUvwPp, 17, nullptr));
  EXPECT_TRUE(b.apb(true, sh::kUvwPp, 0, nullptr));
  EXPECT_FALSE(b.apb(true, sh::kUvwPp, 16, nullptr));
  EXPECT_FALSE(b.apb(false, sh::kUvwPp, 0, &v));
  EXPECT_EQ(v, 16u);
  for (uint32_t addr : {sh::kAbzIndex, sh::kAbzSpacing, sh::kUvwOffset}) {
    EXPECT_FALSE(b.apb(true, addr, 0x1234, nullptr));
    EXPECT_FALSE(b.apb(false, addr, 0, &v));
    EXPECT_EQ(v, 0x1234u) << addr;
  }
}

TEST(Board, InterfacesFollowTheEstimatorsAngle) {
  Board b;
  const int64_t n = 1000;
  const int pp = 7;
  const uint32_t offset = 0x2345;
  // The identity image (no correction, the real arctangent table) through the shadow window.
  const RegImage img = cosim::identity_image(DatapathConfig{});
  for (size_t a = 0; a < img.words.size(); ++a)
    ASSERT_FALSE(
        b.apb(true, sh::kCoef + 4 * static_cast<uint32_t>(a), static_cast<uint32_t>(img.words[a])));
  ASSERT_FALSE(b.apb(true, sh::kCtrl, sh::kCtrlScrub | sh::kCtrlCommit));
  uint32_t st = sh::kStatusBusy;
  for (int i = 0; i < 100000 && (st & sh::kStatusBusy); ++i) b.apb(false, sh::kStatus, 0, &st);
  ASSERT_FALSE(st & sh::kStatusBusy);
  ASSERT_FALSE(b.apb(true, sh::kAbzN, n, nullptr));
  ASSERT_FALSE(b.apb(true, sh::kAbzIndex, 17, nullptr));
  ASSERT_FALSE(b.apb(true, sh::kAbzSpacing, 2, nullptr));
  ASSERT_FALSE(b.apb(true, sh::kUvwPp, pp, nullptr));
  ASSERT_FALSE(b.apb(true, sh::kUvwOffset, offset, nullptr));
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
    target = abz_target(b.angle, 16, n, target);
    for (int i = 0; i < 3 * 4 * n + 100; ++i) b.tick();
    // The N write re-homed the count at the first angle, without edges: the drive homes its
    // decoder once, as after power-up (here to the model's count; an SPI read would give it).
    if (k == 0) b.pos = target;
    const int64_t wrapped = ((b.pos % (4 * n)) + 4 * n) % (4 * n);
    ASSERT_EQ(wrapped, target) << "sample " << k << " angle " << b.angle;
    const UvwState s = uvw_state(b.angle, offset, 16, pp);
    EXPECT_EQ(b.top->u_o, s.u);
    EXPECT_EQ(b.top->v_o, s.v);
    EXPECT_EQ(b.top->w_o, s.w);
    // ODrive's read: 0xFFFF twice, the second answer is ANGLECOM = the angle's upper 14 bits.
    b.spi_frame(0xFFFF);
    const uint16_t raw = b.spi_frame(as5047::with_even_parity(0x7FFE));  // then ANGLEUNC
    EXPECT_TRUE(as5047::parity_even(raw));
    EXPECT_FALSE((raw >> 14) & 1);
    EXPECT_EQ(raw & 0x3FFFu, b.angle >> 2);
    const uint16_t unc = b.spi_frame(as5047::with_even_parity(0x7FFC));  // then DIAAGC
    EXPECT_EQ(unc & 0x3FFFu, b.angle >> 2) << "ANGLECOM = ANGLEUNC until the tracker is wired";
    const uint16_t diag = b.spi_frame(0x0000);
    EXPECT_TRUE((diag >> 8) & 1) << "LF: no loss of tracking until the tracker is wired";
  }
  EXPECT_EQ(samples, 40);
  EXPECT_GT(angles.size(), 30u) << "the estimator's angle moved";
}

}  // namespace
}  // namespace acore
