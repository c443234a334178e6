// SPDX-License-Identifier: MIT
#include "shell/shell_driver.hpp"

#include <deque>

#include "core/errors.hpp"

namespace acore {

namespace {

// Where the wrapped top sits in the shell's hierarchy (its public LATENCY and CYCLES), and its
// active coefficient words (public through model/rtlsim/shell_public.vlt): mem_q of the serial
// core's RAM or of the pipelined top's register file; the folded top (FOLD > 1) keeps its words in
// several memory copies (acore_fold_regs.v), and the upset goes into the one its host port reads
// back (rb_mem_q), the copy the scrubber checks.
std::string top_scope(const RtlBuild& b) {
  return b.serial ? "acore_apb.g_serial.u_top" : "acore_apb.g_pipe.u_top";
}
std::string words_scope(const RtlBuild& b) {
  if (b.serial) return "acore_apb.g_serial.u_top.u_ram";
  if (b.cfg.fold > 1) return "acore_apb.g_pipe.u_top.g_fold.u_dp.u_regs";
  return "acore_apb.g_pipe.u_top.g_pipe.u_regs";
}
const char* words_var(const RtlBuild& b) {
  return !b.serial && b.cfg.fold > 1 ? "rb_mem_q" : "mem_q";
}

}  // namespace

struct ShellDriver::Impl {
  const RtlBuild* build = nullptr;
  DatapathConfig cfg;
  std::unique_ptr<rtl::ShellModel> pins;
  uint64_t cycles = 0;
  bool rst = false;  // rst_i as driven: no handshake counts while it is high
  std::function<void()> hook;
  // APB master.
  enum Phase { kIdle, kSetup, kAccess };
  Phase phase = kIdle;
  std::deque<std::shared_ptr<ApbTransfer>> queue;
  ApbStats stats;
  // Stream.
  std::vector<ChannelCodes> in;
  size_t next = 0;
  double gaps = 0, backpressure = 0;
  std::mt19937_64 rng{1};
  std::vector<uint64_t> accept_cycles;
  std::vector<ShellOutput> outputs;
  // CTRL's persistent bits as last written (reset value: SCRUB).
  uint32_t ctrl = shell::kCtrlScrub;

  void eval() { pins->eval(true); }
  uint32_t* var(const std::string& scope, const char* name) const {
    void* p = pins->public_var(scope.c_str(), name);
    if (!p) throw CheckFailed("shell driver: no public " + scope + "." + name);
    return static_cast<uint32_t*>(p);
  }
};

ShellDriver::ShellDriver(const RtlBuild& build, const std::string& trace, int rand_reset,
                         uint64_t seed)
    : impl_(new Impl) {
  Impl& m = *impl_;
  if (build.top != RtlTop::kShell)
    throw InputError("ShellDriver drives the register shell; '" + build.name + "' is a top");
  m.build = &build;
  m.cfg = build.cfg;
  rtl::SimOptions opt;
  opt.trace = trace.empty() ? nullptr : trace.c_str();
  opt.rand_reset = rand_reset;
  opt.seed = seed;
  m.pins.reset(build.plugin().make_shell(opt));
  m.pins->set_rst(false);
  m.pins->set_apb(false, false, false, 0, 0, 0);
  m.pins->set_in(false, {0, 0, 0, 0}, 0);
  m.pins->set_out_ready(true);
  m.eval();
}

ShellDriver::~ShellDriver() = default;

void ShellDriver::tick() {
  Impl& m = *impl_;
  rtl::ShellModel& p = *m.pins;
  // APB: this clock's phase and pins.
  if (m.phase == Impl::kIdle && !m.queue.empty()) m.phase = Impl::kSetup;
  const ApbTransfer* t = m.phase == Impl::kIdle ? nullptr : m.queue.front().get();
  if (t)
    p.set_apb(true, m.phase == Impl::kAccess, t->write, t->addr, t->write ? t->wdata : 0,
              t->write ? t->strb : 0);
  else
    p.set_apb(false, false, false, 0, 0, 0);
  // Stream: this clock's valid and ready.
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bool valid = m.next < m.in.size() && !(m.gaps > 0 && u(m.rng) < m.gaps);
  const bool ready = !(m.backpressure > 0 && u(m.rng) < m.backpressure);
  const uint32_t mask = static_cast<uint32_t>((uint64_t{1} << m.cfg.in_w) - 1);
  p.set_in(valid, valid ? m.in[m.next] : ChannelCodes{0, 0, 0, 0}, mask);
  p.set_out_ready(ready);
  m.eval();
  // Observe this clock.
  const bool access = m.phase == Impl::kAccess;
  // (Outside reset: PRDATA and PSLVERR are flops with a synchronous reset, their power-up state
  // shows until the reset's first edge.)
  if (!m.rst && !access && p.pslverr()) ++m.stats.stray_slverr;
  if (!m.rst && !(access && !t->write) && p.prdata() != 0) ++m.stats.stray_prdata;
  if (access && !p.pready()) ++m.stats.wait_states;
  bool completed = false;
  if (access && p.pready()) {
    auto& done = *m.queue.front();
    done.rdata = p.prdata();
    done.slverr = p.pslverr();
    done.cycle = m.cycles;
    done.done = true;
    m.queue.pop_front();
    ++m.stats.transfers;
    completed = true;
  }
  if (!m.rst && valid && p.in_ready()) {
    m.accept_cycles.push_back(m.cycles);
    ++m.next;
  }
  if (!m.rst && ready && p.out_valid()) m.outputs.push_back({p.output(), p.out_tag(), m.cycles});
  if (m.hook) m.hook();
  // The edge.
  p.tick();
  ++m.cycles;
  if (m.phase == Impl::kSetup)
    m.phase = Impl::kAccess;
  else if (completed)
    m.phase = m.queue.empty() ? Impl::kIdle : Impl::kSetup;
}

void ShellDriver::ticks(int n) {
  for (int i = 0; i < n; ++i) tick();
}

uint64_t ShellDriver::cycles() const { return impl_->cycles; }
void ShellDriver::on_clock(std::function<void()> f) { impl_->hook = std::move(f); }

void ShellDriver::set_reset(bool rst) {
  impl_->rst = rst;
  impl_->pins->set_rst(rst);
  impl_->eval();
}

void ShellDriver::reset(int cycles) {
  set_reset(true);
  ticks(cycles);
  set_reset(false);
  impl_->ctrl = shell::kCtrlScrub;
}

std::shared_ptr<const ApbTransfer> ShellDriver::post(bool write, uint32_t addr, uint32_t wdata,
                                                     uint32_t strb) {
  auto t = std::make_shared<ApbTransfer>();
  t->write = write;
  t->addr = addr;
  t->wdata = wdata;
  t->strb = strb;
  impl_->queue.push_back(t);
  return t;
}

bool ShellDriver::apb_idle() const { return impl_->queue.empty(); }

uint32_t ShellDriver::read(uint32_t addr, bool* slverr) {
  const auto t = post(false, addr);
  for (int n = 0; !t->done; ++n) {
    if (n > 1000000) throw CheckFailed("APB read does not complete");
    tick();
  }
  if (slverr) *slverr = t->slverr;
  return t->rdata;
}

bool ShellDriver::write(uint32_t addr, uint32_t data, uint32_t strb) {
  const auto t = post(true, addr, data, strb);
  for (int n = 0; !t->done; ++n) {
    if (n > 1000000) throw CheckFailed("APB write does not complete");
    tick();
  }
  return t->slverr;
}

const ShellDriver::ApbStats& ShellDriver::apb_stats() const { return impl_->stats; }

void ShellDriver::write_shadow(const RegImage& img) {
  for (size_t a = 0; a < img.words.size(); ++a)
    if (write(shell::kCoef + 4 * static_cast<uint32_t>(a), static_cast<uint32_t>(img.words[a])))
      throw CheckFailed("APB shell: shadow word " + std::to_string(a) + " write refused (PSLVERR)");
}

void ShellDriver::set_ctrl(uint32_t bits) {
  impl_->ctrl = bits & ~(shell::kCtrlCommit | shell::kCtrlClear);
  if (write(shell::kCtrl, impl_->ctrl)) throw CheckFailed("APB shell: CTRL write refused");
}

uint32_t ShellDriver::ctrl() const { return impl_->ctrl; }

uint32_t ShellDriver::commit(bool check, uint32_t crc_expected) {
  if (check && write(shell::kCrcExpected, crc_expected))
    throw CheckFailed("APB shell: CRC_EXPECTED write refused");
  impl_->ctrl = check ? impl_->ctrl | shell::kCtrlCrcCheck : impl_->ctrl & ~shell::kCtrlCrcCheck;
  if (write(shell::kCtrl, impl_->ctrl | shell::kCtrlCommit))
    throw CheckFailed("APB shell: commit refused (busy)");
  for (int n = 0;; ++n) {
    const uint32_t st = read(shell::kStatus);
    if (!(st & shell::kStatusBusy)) return st;
    if (n > 1000000) throw CheckFailed("APB shell: commit does not finish");
  }
}

uint32_t ShellDriver::load_and_commit(const RegImage& img) {
  write_shadow(img);
  return commit(true, image_crc32(img));
}

void ShellDriver::set_window(const StatusWindow& w) {
  if (write(shell::kMagLo, static_cast<uint32_t>(w.mag_lo)) ||
      write(shell::kMagHi, static_cast<uint32_t>(w.mag_hi)))
    throw CheckFailed("APB shell: MAG_LO/MAG_HI write refused");
}

void ShellDriver::stream(const std::vector<ChannelCodes>& in, double gaps, double backpressure,
                         uint64_t seed) {
  Impl& m = *impl_;
  m.in.insert(m.in.end(), in.begin(), in.end());
  m.gaps = gaps;
  m.backpressure = backpressure;
  m.rng.seed(seed);
}

size_t ShellDriver::queued() const { return impl_->in.size(); }
size_t ShellDriver::accepted() const { return impl_->next; }
const std::vector<uint64_t>& ShellDriver::accept_cycles() const { return impl_->accept_cycles; }
const std::vector<ShellOutput>& ShellDriver::outputs() const { return impl_->outputs; }

void ShellDriver::drain(size_t outputs, uint64_t max_cycles) {
  const size_t want = outputs == kAllQueued ? impl_->in.size() : outputs;
  const uint64_t end = impl_->cycles + max_cycles;
  while (impl_->outputs.size() < want || !apb_idle()) {
    if (impl_->cycles > end) throw CheckFailed("APB shell: the stream does not drain");
    tick();
  }
}

rtl::ShellModel& ShellDriver::pins() { return *impl_->pins; }
const RtlBuild& ShellDriver::build() const { return *impl_->build; }
const DatapathConfig& ShellDriver::config() const { return impl_->cfg; }

uint32_t ShellDriver::top_param(const char* name) const {
  return *impl_->var(top_scope(*impl_->build), name);
}

void ShellDriver::flip_active_bit(int addr, int bit) {
  uint32_t* words = impl_->var(words_scope(*impl_->build), words_var(*impl_->build));
  if (impl_->cfg.reg_w > 32 || addr < 0 || addr >= impl_->cfg.words() || bit < 0 ||
      bit >= impl_->cfg.reg_w)
    throw CheckFailed("shell driver: no active word bit " + std::to_string(addr) + "." +
                      std::to_string(bit));
  words[addr] ^= uint32_t{1} << bit;
}

uint64_t ShellDriver::active_word(int addr) const {
  return impl_->var(words_scope(*impl_->build), words_var(*impl_->build))[addr];
}

}  // namespace acore
