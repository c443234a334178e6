// SPDX-License-Identifier: MIT
#include "rtl_engine.hpp"

#include <verilated.h>
#include <verilated_fst_c.h>

#include "core/errors.hpp"
#include "rtl_builds.hpp"

namespace acore {

namespace {
std::string available_builds() {
  std::string s;
  for (const RtlBuild& b : rtl_builds()) s += "\n  " + b.name + ": " + b.config().describe();
  return s;
}
}  // namespace

const RtlBuild& rtl_build_for(const DatapathConfig& cfg) {
  for (const RtlBuild& b : rtl_builds())
    if (b.config().describe() == cfg.describe()) return b;
  throw InputError("no Verilated build of the RTL has the configuration " + cfg.describe() +
                   "; add it to rtl/configs.txt and rebuild. Available:" + available_builds());
}

const RtlBuild& rtl_build_named(const std::string& name) {
  for (const RtlBuild& b : rtl_builds())
    if (b.name == name) return b;
  throw InputError("no Verilated build of the RTL is named '" + name +
                   "'. Available:" + available_builds());
}

struct RtlHarness::Impl {
  std::unique_ptr<VerilatedContext> ctx;
  std::unique_ptr<RtlPins> top;
  std::unique_ptr<VerilatedFstC> tfp;
  uint64_t cycles = 0;
  DatapathConfig cfg;
  int latency = 0;
  int cycles_per_sample = 1;
  void eval() {
    top->eval();
    if (tfp) tfp->dump(ctx->time());
  }
};

int RtlHarness::latency() const { return impl_->latency; }
int RtlHarness::cycles_per_sample() const { return impl_->cycles_per_sample; }
const DatapathConfig& RtlHarness::config() const { return impl_->cfg; }

RtlHarness::RtlHarness(const std::string& trace, int rand_reset, uint64_t seed,
                       const DatapathConfig& cfg)
    : impl_(new Impl) {
  const RtlBuild& build = rtl_build_for(cfg);
  impl_->cfg = cfg;
  impl_->latency = build.latency;
  impl_->cycles_per_sample = build.cycles;
  impl_->ctx = std::make_unique<VerilatedContext>();
  impl_->ctx->randReset(rand_reset);
  impl_->ctx->randSeed(static_cast<int>(seed & 0x7fffffff));
  if (!trace.empty()) impl_->ctx->traceEverOn(true);
  impl_->top = build.make(impl_->ctx.get(), "acore_top");
  if (!trace.empty()) {
    impl_->tfp = std::make_unique<VerilatedFstC>();
    impl_->top->trace(impl_->tfp.get());
    impl_->tfp->open(trace.c_str());
  }
  RtlPins& t = *impl_->top;
  t.set_clk(false);
  t.set_rst(false);
  t.set_reg(0, 0, false);
  t.set_in(false, {0, 0, 0, 0}, 0);
  t.set_out_ready(true);
  set_window(StatusWindow::defaults(impl_->cfg));
  impl_->eval();
}

RtlHarness::~RtlHarness() {
  impl_->top->final();
  if (impl_->tfp) impl_->tfp->close();
}

void RtlHarness::tick() {
  Impl& m = *impl_;
  m.top->set_clk(true);
  m.ctx->timeInc(1);
  m.eval();
  m.top->set_clk(false);
  m.ctx->timeInc(1);
  m.eval();
  ++m.cycles;
}

uint64_t RtlHarness::cycles() const { return impl_->cycles; }

void RtlHarness::set_reset(bool rst) {
  impl_->top->set_rst(rst);
  impl_->eval();
}

void RtlHarness::reset(int cycles) {
  drive(false, {0, 0, 0, 0}, true);
  set_reset(true);
  for (int i = 0; i < cycles; ++i) tick();
  set_reset(false);
}

void RtlHarness::drive_host(int addr, bool we, uint64_t wdata) {
  impl_->top->set_reg(static_cast<uint32_t>(addr), wdata, we);
  impl_->eval();
}

void RtlHarness::write_reg(int addr, uint64_t value) {
  drive_host(addr, true, value);
  tick();
  drive_host(addr, false, 0);
}

void RtlHarness::load(const RegImage& img) {
  for (size_t a = 0; a < img.words.size(); ++a) write_reg(static_cast<int>(a), img.words[a]);
  for (size_t a = 0; a < img.words.size(); ++a)
    if (read_reg(static_cast<int>(a)) != img.words[a])
      throw CheckFailed("RTL register " + std::to_string(a) + " read back differs from the image");
}

uint64_t RtlHarness::read_reg(int addr) {
  drive_host(addr, false, 0);
  // The read-back is pipelined over two clocks (rtl/acore_coef_regfile.v).
  tick();
  tick();
  return impl_->top->reg_rdata();
}

uint64_t RtlHarness::reg_rdata() const { return impl_->top->reg_rdata(); }

void RtlHarness::set_window(const StatusWindow& w) {
  const int64_t max = (int64_t{1} << (impl_->cfg.s_w + 2)) - 1;
  if (w.mag_lo < 0 || w.mag_hi < 0 || w.mag_lo > max || w.mag_hi > max)
    throw InputError("status window outside the RTL's unsigned MAG_W-bit ports");
  impl_->top->set_window(static_cast<uint64_t>(w.mag_lo), static_cast<uint64_t>(w.mag_hi));
}

void RtlHarness::drive(bool in_valid, const ChannelCodes& c, bool out_ready) {
  RtlPins& t = *impl_->top;
  const uint32_t mask = static_cast<uint32_t>((uint64_t{1} << impl_->cfg.in_w) - 1);
  t.set_in(in_valid, c, mask);
  t.set_out_ready(out_ready);
  t.eval();  // settle in_ready_o, which depends on out_ready_i
}

bool RtlHarness::in_ready() const { return impl_->top->in_ready(); }
bool RtlHarness::out_valid() const { return impl_->top->out_valid(); }

FixedSample RtlHarness::output() const { return impl_->top->output(); }

bool RtlHarness::outputs_zero() const {
  const FixedSample s = impl_->top->output();
  return s.angle == 0 && s.region == 0 && !s.ovf && !s.los && !s.dos;
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
  DatapathConfig cfg = img.cfg;
  if (opt.fold != 0) {
    cfg.fold = opt.fold;
    cfg.validate();
  }
  RtlHarness h(opt.trace, 2, opt.seed, cfg);
  h.set_window(opt.window ? *opt.window : StatusWindow::defaults(img.cfg));
  h.reset();
  h.load(img);
  std::mt19937_64 rng(opt.seed);
  return h.stream(in, opt.gaps, opt.backpressure, rng);
}

}  // namespace acore
