// SPDX-License-Identifier: MIT
#include "rtlsim/rtl_engine.hpp"

#include "core/errors.hpp"

namespace acore {

struct RtlHarness::Impl {
  const RtlBuild* build = nullptr;
  const rtl::PluginInfo* info = nullptr;
  std::unique_ptr<rtl::TopModel> top;
  uint64_t cycles = 0;
  uint32_t in_mask = 0;
};

RtlHarness::RtlHarness(const RtlBuild& build, const std::string& trace, int rand_reset,
                       uint64_t seed, const std::string& module_dir)
    : impl_(new Impl) {
  if (build.top == RtlTop::kShell)
    throw InputError("RtlHarness drives a top; '" + build.name + "' is the register shell");
  impl_->build = &build;
  impl_->info = &build.plugin(module_dir);
  rtl::SimOptions opt;
  opt.trace = trace.empty() ? nullptr : trace.c_str();
  opt.rand_reset = rand_reset;
  opt.seed = seed;
  impl_->top.reset(impl_->info->make_top(opt));
  impl_->in_mask = static_cast<uint32_t>((uint64_t{1} << build.cfg.in_w) - 1);
  rtl::TopModel& t = *impl_->top;
  t.set_reg(0, 0, false);
  t.set_in(false, {0, 0, 0, 0}, 0);
  t.set_out_ready(true);
  set_window(StatusWindow::defaults(build.cfg));
  t.eval(true);
}

RtlHarness::~RtlHarness() = default;

int RtlHarness::latency() const { return impl_->info->latency; }
int RtlHarness::cycles_per_sample() const { return impl_->info->cycles; }
const DatapathConfig& RtlHarness::config() const { return impl_->build->cfg; }
const RtlBuild& RtlHarness::build() const { return *impl_->build; }

void RtlHarness::tick() {
  impl_->top->tick();
  ++impl_->cycles;
}

uint64_t RtlHarness::cycles() const { return impl_->cycles; }

void RtlHarness::set_reset(bool rst) {
  impl_->top->set_rst(rst);
  impl_->top->eval(true);
}

void RtlHarness::reset(int cycles) {
  drive(false, {0, 0, 0, 0}, true);
  set_reset(true);
  for (int i = 0; i < cycles; ++i) tick();
  set_reset(false);
}

void RtlHarness::drive_host(int addr, bool we, uint64_t wdata) {
  impl_->top->set_reg(static_cast<uint32_t>(addr), wdata, we);
  impl_->top->eval(true);
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
      throw CheckFailed("RTL register " + std::to_string(a) + " of build " + impl_->build->name +
                        " read back differs from the image");
}

uint64_t RtlHarness::read_reg(int addr) {
  drive_host(addr, false, 0);
  // The read-back is pipelined over two clocks on both tops.
  tick();
  tick();
  return impl_->top->reg_rdata();
}

uint64_t RtlHarness::reg_rdata() const { return impl_->top->reg_rdata(); }

void RtlHarness::set_window(const StatusWindow& w) {
  const int64_t max = (int64_t{1} << (config().s_w + 2)) - 1;
  if (w.mag_lo < 0 || w.mag_hi < 0 || w.mag_lo > max || w.mag_hi > max)
    throw InputError("status window outside the RTL's unsigned MAG_W-bit ports");
  impl_->top->set_window(static_cast<uint64_t>(w.mag_lo), static_cast<uint64_t>(w.mag_hi));
}

void RtlHarness::drive(bool in_valid, const ChannelCodes& c, bool out_ready) {
  rtl::TopModel& t = *impl_->top;
  t.set_in(in_valid, c, impl_->in_mask);
  t.set_out_ready(out_ready);
  t.eval(false);  // settle in_ready_o, which depends on out_ready_i
}

bool RtlHarness::in_ready() const { return impl_->top->in_ready(); }
bool RtlHarness::out_valid() const { return impl_->top->out_valid(); }

FixedSample RtlHarness::output() const { return impl_->top->output(); }

bool RtlHarness::outputs_zero() const {
  const FixedSample s = impl_->top->output();
  return s.angle == 0 && s.region == 0 && !s.ovf && !s.los && !s.dos && s.magnitude == 0;
}

std::vector<FixedSample> RtlHarness::stream(const std::vector<ChannelCodes>& in, double gaps,
                                            double backpressure, std::mt19937_64& rng) {
  std::vector<FixedSample> out;
  out.reserve(in.size());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bool random = gaps > 0 || backpressure > 0;
  size_t next = 0;
  // Enough clocks for every sample plus the pipeline, even with random stalls (bounded).
  const uint64_t limit = impl_->cycles + 1000 +
                         100 * (in.size() + 1) * static_cast<uint64_t>(cycles_per_sample()) +
                         static_cast<uint64_t>(latency());
  while (out.size() < in.size()) {
    const bool valid = next < in.size() && (!random || gaps <= 0 || u(rng) >= gaps);
    const bool ready = !random || backpressure <= 0 || u(rng) >= backpressure;
    drive(valid, valid ? in[next] : ChannelCodes{0, 0, 0, 0}, ready);
    if (valid && in_ready()) ++next;
    if (ready && out_valid()) out.push_back(output());
    tick();
    if (impl_->cycles > limit)
      throw CheckFailed("RTL stream of build " + impl_->build->name + " does not finish");
  }
  return out;
}

std::vector<FixedSample> run_rtl(const RegImage& img, const std::vector<ChannelCodes>& in,
                                 const RtlRunOptions& opt) {
  DatapathConfig cfg = img.cfg;
  if (opt.fold != 0) {
    if (opt.top != RtlTop::kPipelined && opt.fold != 1)
      throw InputError("a fold factor applies to the pipelined top only");
    cfg.fold = opt.fold;
    cfg.validate();
  }
  RtlHarness h(rtl_build_for(opt.top, cfg), opt.trace, 2, opt.seed, opt.module_dir);
  h.set_window(opt.window ? *opt.window : StatusWindow::defaults(img.cfg));
  h.reset();
  h.load(img);
  std::mt19937_64 rng(opt.seed);
  return h.stream(in, opt.gaps, opt.backpressure, rng);
}

}  // namespace acore
