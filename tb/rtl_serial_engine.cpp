// SPDX-License-Identifier: MIT
// Compiled once per named configuration of the serial core (tb/CMakeLists.txt): ACORE_SERIAL_V is
// the Verilated class, ACORE_SERIAL_HDR / ACORE_SERIAL_PUB_HDR its headers, ACORE_SERIAL_PUB the
// class holding the public CYCLES, ACORE_SERIAL_<PARAM> the -G overrides of the build,
// ACORE_SERIAL_NS the build's namespace (rtl_serial_engine.hpp).
#include "rtl_serial_engine.hpp"

#include <verilated.h>
#include <verilated_fst_c.h>

#include <type_traits>

#include ACORE_SERIAL_HDR
#include ACORE_SERIAL_PUB_HDR
#include "core/errors.hpp"

namespace acore {
inline namespace ACORE_SERIAL_NS {

using SerialTop = ACORE_SERIAL_V;

struct RtlSerialHarness::Impl {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<SerialTop> top;
  std::unique_ptr<VerilatedFstC> tfp;
  uint64_t cycles = 0;
  DatapathConfig cfg = rtl_serial_config();
  void eval() {
    top->eval();
    if (tfp) tfp->dump(ctx->time());
  }
};

DatapathConfig rtl_serial_config() {
  DatapathConfig c;
  // The -G overrides of this build (tb/CMakeLists.txt defines ACORE_SERIAL_<PARAM> for each).
#define ACORE_SERIAL_SET(PARAM, field) c.field = PARAM;
#ifdef ACORE_SERIAL_IN_W
  ACORE_SERIAL_SET(ACORE_SERIAL_IN_W, in_w)
#endif
#ifdef ACORE_SERIAL_REG_W
  ACORE_SERIAL_SET(ACORE_SERIAL_REG_W, reg_w)
#endif
#ifdef ACORE_SERIAL_S_W
  ACORE_SERIAL_SET(ACORE_SERIAL_S_W, s_w)
#endif
#ifdef ACORE_SERIAL_S_F
  ACORE_SERIAL_SET(ACORE_SERIAL_S_F, s_f)
#endif
#ifdef ACORE_SERIAL_R_SHIFT
  ACORE_SERIAL_SET(ACORE_SERIAL_R_SHIFT, r_shift)
#endif
#ifdef ACORE_SERIAL_SCALE_G
  ACORE_SERIAL_SET(ACORE_SERIAL_SCALE_G, scale_guard)
#endif
#ifdef ACORE_SERIAL_DEGREE
  ACORE_SERIAL_SET(ACORE_SERIAL_DEGREE, degree)
#endif
#ifdef ACORE_SERIAL_REGIONS
  ACORE_SERIAL_SET(ACORE_SERIAL_REGIONS, regions)
#endif
#ifdef ACORE_SERIAL_COEF_F
  ACORE_SERIAL_SET(ACORE_SERIAL_COEF_F, coef_f)
#endif
#ifdef ACORE_SERIAL_ACC_G
  ACORE_SERIAL_SET(ACORE_SERIAL_ACC_G, acc_guard)
#endif
#ifdef ACORE_SERIAL_ACC_I
  ACORE_SERIAL_SET(ACORE_SERIAL_ACC_I, acc_int)
#endif
#ifdef ACORE_SERIAL_K
  ACORE_SERIAL_SET(ACORE_SERIAL_K, iterations)
#endif
#ifdef ACORE_SERIAL_CORDIC_G
  ACORE_SERIAL_SET(ACORE_SERIAL_CORDIC_G, cordic_guard)
#endif
#ifdef ACORE_SERIAL_Z_W
  ACORE_SERIAL_SET(ACORE_SERIAL_Z_W, z_w)
#endif
#ifdef ACORE_SERIAL_ANGLE_W
  ACORE_SERIAL_SET(ACORE_SERIAL_ANGLE_W, angle_w)
#endif
#ifdef ACORE_SERIAL_ZERO
  ACORE_SERIAL_SET(ACORE_SERIAL_ZERO, zero_word)
#endif
#undef ACORE_SERIAL_SET
  return c;
}

int RtlSerialHarness::cycles_per_sample() { return static_cast<int>(ACORE_SERIAL_PUB::CYCLES); }
int RtlSerialHarness::latency() { return static_cast<int>(ACORE_SERIAL_PUB::LATENCY); }

RtlSerialHarness::RtlSerialHarness(const std::string& trace, int rand_reset, uint64_t seed)
    : impl_(new Impl) {
  impl_->ctx = std::make_unique<VerilatedContext>();
  impl_->ctx->randReset(rand_reset);
  impl_->ctx->randSeed(static_cast<int>(seed & 0x7fffffff));
  if (!trace.empty()) impl_->ctx->traceEverOn(true);
  impl_->top = std::make_unique<SerialTop>(impl_->ctx.get(), "acore_serial_top");
  if (!trace.empty()) {
    impl_->tfp = std::make_unique<VerilatedFstC>();
    impl_->top->trace(impl_->tfp.get(), 99);
    impl_->tfp->open(trace.c_str());
  }
  SerialTop& t = *impl_->top;
  t.clk_i = 0;
  t.rst_i = 0;
  t.reg_we_i = 0;
  t.in_valid_i = 0;
  t.out_ready_i = 1;
  set_window(StatusWindow::defaults(impl_->cfg));
  impl_->eval();
}

RtlSerialHarness::~RtlSerialHarness() {
  impl_->top->final();
  if (impl_->tfp) impl_->tfp->close();
}

void RtlSerialHarness::tick() {
  Impl& m = *impl_;
  m.top->clk_i = 1;
  m.ctx->timeInc(1);
  m.eval();
  m.top->clk_i = 0;
  m.ctx->timeInc(1);
  m.eval();
  ++m.cycles;
}

uint64_t RtlSerialHarness::cycles() const { return impl_->cycles; }

void RtlSerialHarness::set_reset(bool rst) {
  impl_->top->rst_i = rst;
  impl_->eval();
}

void RtlSerialHarness::reset(int cycles) {
  drive(false, {0, 0, 0, 0}, true);
  set_reset(true);
  for (int i = 0; i < cycles; ++i) tick();
  set_reset(false);
}

void RtlSerialHarness::drive_host(int addr, bool we, uint64_t wdata) {
  SerialTop& t = *impl_->top;
  t.reg_addr_i = static_cast<std::remove_reference_t<decltype(t.reg_addr_i)>>(addr);
  t.reg_wdata_i = static_cast<IData>(wdata);
  t.reg_we_i = we;
  impl_->eval();
}

void RtlSerialHarness::write_reg(int addr, uint64_t value) {
  drive_host(addr, true, value);
  tick();
  drive_host(addr, false, 0);
}

void RtlSerialHarness::load(const RegImage& img) {
  for (size_t a = 0; a < img.words.size(); ++a) write_reg(static_cast<int>(a), img.words[a]);
  for (size_t a = 0; a < img.words.size(); ++a)
    if (read_reg(static_cast<int>(a)) != img.words[a])
      throw CheckFailed("serial RTL register " + std::to_string(a) +
                        " read back differs from the image");
}

uint64_t RtlSerialHarness::read_reg(int addr) {
  drive_host(addr, false, 0);
  // Two clocks, as the pipelined top: the RAM's output register, then the read-back register.
  tick();
  tick();
  return impl_->top->reg_rdata_o;
}

uint64_t RtlSerialHarness::reg_rdata() const { return impl_->top->reg_rdata_o; }

void RtlSerialHarness::set_window(const StatusWindow& w) {
  const int64_t max = (int64_t{1} << (impl_->cfg.s_w + 2)) - 1;
  if (w.mag_lo < 0 || w.mag_hi < 0 || w.mag_lo > max || w.mag_hi > max)
    throw InputError("status window outside the RTL's unsigned MAG_W-bit ports");
  impl_->top->mag_lo_i = static_cast<IData>(w.mag_lo);
  impl_->top->mag_hi_i = static_cast<IData>(w.mag_hi);
}

void RtlSerialHarness::drive(bool in_valid, const ChannelCodes& c, bool out_ready) {
  SerialTop& t = *impl_->top;
  const uint32_t mask = (uint32_t{1} << impl_->cfg.in_w) - 1;
  t.in_valid_i = in_valid;
  t.c1_i = static_cast<SData>(static_cast<uint32_t>(c[0]) & mask);
  t.c2_i = static_cast<SData>(static_cast<uint32_t>(c[1]) & mask);
  t.c3_i = static_cast<SData>(static_cast<uint32_t>(c[2]) & mask);
  t.c4_i = static_cast<SData>(static_cast<uint32_t>(c[3]) & mask);
  t.out_ready_i = out_ready;
  t.eval();
}

bool RtlSerialHarness::in_ready() const { return impl_->top->in_ready_o; }
bool RtlSerialHarness::out_valid() const { return impl_->top->out_valid_o; }

FixedSample RtlSerialHarness::output() const {
  const SerialTop& t = *impl_->top;
  FixedSample s;
  s.angle = t.angle_o;
  s.region = t.region_o;
  s.ovf = t.ovf_o;
  s.los = t.los_o;
  s.dos = t.dos_o;
  return s;
}

bool RtlSerialHarness::outputs_zero() const {
  const SerialTop& t = *impl_->top;
  return t.angle_o == 0 && t.region_o == 0 && !t.ovf_o && !t.los_o && !t.dos_o;
}

std::vector<FixedSample> RtlSerialHarness::stream(const std::vector<ChannelCodes>& in, double gaps,
                                                  double backpressure, std::mt19937_64& rng) {
  std::vector<FixedSample> out;
  out.reserve(in.size());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bool random = gaps > 0 || backpressure > 0;
  size_t next = 0;
  const uint64_t limit =
      impl_->cycles + 1000 + 100 * (in.size() + 1) * static_cast<uint64_t>(cycles_per_sample());
  while (out.size() < in.size()) {
    const bool valid = next < in.size() && (!random || gaps <= 0 || u(rng) >= gaps);
    const bool ready = !random || backpressure <= 0 || u(rng) >= backpressure;
    drive(valid, valid ? in[next] : ChannelCodes{0, 0, 0, 0}, ready);
    if (valid && in_ready()) ++next;
    if (ready && out_valid()) out.push_back(output());
    tick();
    if (impl_->cycles > limit) throw CheckFailed("serial RTL stream does not finish");
  }
  return out;
}

std::vector<FixedSample> run_rtl_serial(const RegImage& img, const std::vector<ChannelCodes>& in,
                                        const RtlRunOptions& opt) {
  if (img.cfg.describe() != rtl_serial_config().describe())
    throw InputError("the serial RTL engine is built for the configuration (" +
                     rtl_serial_config().describe() + "), the register image has " +
                     img.cfg.describe());
  RtlSerialHarness h(opt.trace, 2, opt.seed);
  h.set_window(opt.window ? *opt.window : StatusWindow::defaults(img.cfg));
  h.reset();
  h.load(img);
  std::mt19937_64 rng(opt.seed);
  return h.stream(in, opt.gaps, opt.backpressure, rng);
}

}  // namespace ACORE_SERIAL_NS
}  // namespace acore
