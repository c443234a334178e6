// SPDX-License-Identifier: MIT
#include "rtl_engine.hpp"

#include <verilated.h>
#include <verilated_fst_c.h>

#include "Vacore_top.h"
#include "Vacore_top_acore_top.h"
#include "errors.hpp"

namespace acore {

struct RtlHarness::Impl {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<Vacore_top> top;
  std::unique_ptr<VerilatedFstC> tfp;
  uint64_t cycles = 0;
  DatapathConfig cfg = rtl_config();
  void eval() {
    top->eval();
    if (tfp) tfp->dump(ctx->time());
  }
};

DatapathConfig rtl_config() { return DatapathConfig{}; }

int RtlHarness::latency() { return static_cast<int>(Vacore_top_acore_top::LATENCY); }

RtlHarness::RtlHarness(const std::string& trace, int rand_reset, uint64_t seed) : impl_(new Impl) {
  impl_->ctx = std::make_unique<VerilatedContext>();
  impl_->ctx->randReset(rand_reset);
  impl_->ctx->randSeed(static_cast<int>(seed & 0x7fffffff));
  if (!trace.empty()) impl_->ctx->traceEverOn(true);
  impl_->top = std::make_unique<Vacore_top>(impl_->ctx.get(), "acore_top");
  if (!trace.empty()) {
    impl_->tfp = std::make_unique<VerilatedFstC>();
    impl_->top->trace(impl_->tfp.get(), 99);
    impl_->tfp->open(trace.c_str());
  }
  Vacore_top& t = *impl_->top;
  t.clk_i = 0;
  t.rst_i = 0;
  t.reg_we_i = 0;
  t.in_valid_i = 0;
  t.out_ready_i = 1;
  set_window(StatusWindow::defaults(impl_->cfg));
  impl_->eval();
}

RtlHarness::~RtlHarness() {
  impl_->top->final();
  if (impl_->tfp) impl_->tfp->close();
}

void RtlHarness::tick() {
  Impl& m = *impl_;
  m.top->clk_i = 1;
  m.ctx->timeInc(1);
  m.eval();
  m.top->clk_i = 0;
  m.ctx->timeInc(1);
  m.eval();
  ++m.cycles;
}

uint64_t RtlHarness::cycles() const { return impl_->cycles; }

void RtlHarness::set_reset(bool rst) {
  impl_->top->rst_i = rst;
  impl_->eval();
}

void RtlHarness::reset(int cycles) {
  drive(false, {0, 0, 0, 0}, true);
  set_reset(true);
  for (int i = 0; i < cycles; ++i) tick();
  set_reset(false);
}

void RtlHarness::load(const RegImage& img) {
  Vacore_top& t = *impl_->top;
  for (size_t a = 0; a < img.words.size(); ++a) {
    t.reg_addr_i = static_cast<CData>(a);
    t.reg_wdata_i = static_cast<IData>(img.words[a]);
    t.reg_we_i = 1;
    impl_->eval();
    tick();
  }
  t.reg_we_i = 0;
  for (size_t a = 0; a < img.words.size(); ++a)
    if (read_reg(static_cast<int>(a)) != img.words[a])
      throw CheckFailed("RTL register " + std::to_string(a) + " read back differs from the image");
}

uint64_t RtlHarness::read_reg(int addr) {
  Vacore_top& t = *impl_->top;
  t.reg_we_i = 0;
  t.reg_addr_i = static_cast<CData>(addr);
  impl_->eval();
  tick();
  return t.reg_rdata_o;
}

void RtlHarness::set_window(const StatusWindow& w) {
  const int64_t max = (int64_t{1} << (impl_->cfg.s_w + 2)) - 1;
  if (w.mag_lo < 0 || w.mag_hi < 0 || w.mag_lo > max || w.mag_hi > max)
    throw InputError("status window outside the RTL's unsigned MAG_W-bit ports");
  impl_->top->mag_lo_i = static_cast<IData>(w.mag_lo);
  impl_->top->mag_hi_i = static_cast<IData>(w.mag_hi);
}

void RtlHarness::drive(bool in_valid, const ChannelCodes& c, bool out_ready) {
  Vacore_top& t = *impl_->top;
  const uint32_t mask = (uint32_t{1} << impl_->cfg.in_w) - 1;
  t.in_valid_i = in_valid;
  t.c1_i = static_cast<SData>(static_cast<uint32_t>(c[0]) & mask);
  t.c2_i = static_cast<SData>(static_cast<uint32_t>(c[1]) & mask);
  t.c3_i = static_cast<SData>(static_cast<uint32_t>(c[2]) & mask);
  t.c4_i = static_cast<SData>(static_cast<uint32_t>(c[3]) & mask);
  t.out_ready_i = out_ready;
  t.eval();  // settle in_ready_o, which depends on out_ready_i
}

bool RtlHarness::in_ready() const { return impl_->top->in_ready_o; }
bool RtlHarness::out_valid() const { return impl_->top->out_valid_o; }

FixedSample RtlHarness::output() const {
  const Vacore_top& t = *impl_->top;
  FixedSample s;
  s.angle = t.angle_o;
  s.region = t.region_o;
  s.ovf = t.ovf_o;
  s.los = t.los_o;
  s.dos = t.dos_o;
  return s;
}

bool RtlHarness::outputs_zero() const {
  const Vacore_top& t = *impl_->top;
  return t.angle_o == 0 && t.region_o == 0 && !t.ovf_o && !t.los_o && !t.dos_o;
}

std::vector<FixedSample> RtlHarness::stream(const std::vector<ChannelCodes>& in, double gaps,
                                            double backpressure, std::mt19937_64& rng) {
  std::vector<FixedSample> out;
  out.reserve(in.size());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bool random = gaps > 0 || backpressure > 0;
  size_t next = 0;
  // Enough clocks for every sample plus the pipeline, even with random stalls (bounded).
  while (out.size() < in.size()) {
    const bool valid = next < in.size() && (!random || gaps <= 0 || u(rng) >= gaps);
    const bool ready = !random || backpressure <= 0 || u(rng) >= backpressure;
    drive(valid, valid ? in[next] : ChannelCodes{0, 0, 0, 0}, ready);
    if (valid && in_ready()) ++next;
    if (ready && out_valid()) out.push_back(output());
    tick();
    if (impl_->cycles > (uint64_t{1} << 40)) throw CheckFailed("RTL stream does not finish");
  }
  return out;
}

std::vector<FixedSample> run_rtl(const RegImage& img, const std::vector<ChannelCodes>& in,
                                 const RtlRunOptions& opt) {
  if (img.cfg.describe() != rtl_config().describe())
    throw InputError("the RTL engine is built for the default configuration (" + rtl_config().describe() +
                     "), the register image has " + img.cfg.describe());
  RtlHarness h(opt.trace, 2, opt.seed);
  h.set_window(opt.window ? *opt.window : StatusWindow::defaults(img.cfg));
  h.reset();
  h.load(img);
  std::mt19937_64 rng(opt.seed);
  return h.stream(in, opt.gaps, opt.backpressure, rng);
}

}  // namespace acore
