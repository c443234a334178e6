// SPDX-License-Identifier: MIT
// The plugin side of rtl_plugin.hpp: the interfaces implemented once, as templates over any
// Verilated class V (their port types depend on the build's widths). Each plugin's generated
// source (model/rtlsim/CMakeLists.txt) includes this header and its Verilated class, and
// instantiates ACORE_RTL_PLUGIN once. Only plugins include this file (and verilated.h).
#pragma once
#include <verilated.h>
#include <verilated_fst_c.h>
#include <verilated_syms.h>

#include <memory>
#include <string>
#include <type_traits>

#include "rtlsim/rtl_plugin.hpp"

namespace acore::rtl {

// Context, model and trace of one Verilated build; Base is TopModel or ShellModel.
template <class V, class Base>
class Verilated : public Base {
 public:
  explicit Verilated(const SimOptions& opt) : ctx_(std::make_unique<VerilatedContext>()) {
    ctx_->randReset(opt.rand_reset);
    ctx_->randSeed(static_cast<int>(opt.seed & 0x7fffffff));
    if (opt.trace) ctx_->traceEverOn(true);
    top_ = std::make_unique<V>(ctx_.get(), "TOP");
    if (opt.trace) {
      tfp_ = std::make_unique<VerilatedFstC>();
      top_->trace(tfp_.get(), 99);
      tfp_->open(opt.trace);
    }
    top_->clk_i = 0;
    top_->rst_i = 0;
    top_->in_valid_i = 0;
    top_->out_ready_i = 1;
  }
  ~Verilated() override {
    top_->final();
    if (tfp_) tfp_->close();
  }
  void eval(bool dump) override {
    top_->eval();
    if (dump && tfp_) tfp_->dump(ctx_->time());
  }
  void tick() override {
    top_->clk_i = 1;
    ctx_->timeInc(1);
    eval(true);
    top_->clk_i = 0;
    ctx_->timeInc(1);
    eval(true);
  }
  void set_rst(bool v) override { top_->rst_i = v; }
  void set_in(bool valid, const ChannelCodes& c, uint32_t mask) override {
    using C = std::decay_t<decltype(top_->c1_i)>;
    top_->in_valid_i = valid;
    top_->c1_i = static_cast<C>(static_cast<uint32_t>(c[0]) & mask);
    top_->c2_i = static_cast<C>(static_cast<uint32_t>(c[1]) & mask);
    top_->c3_i = static_cast<C>(static_cast<uint32_t>(c[2]) & mask);
    top_->c4_i = static_cast<C>(static_cast<uint32_t>(c[3]) & mask);
  }
  void set_out_ready(bool v) override { top_->out_ready_i = v; }
  bool in_ready() const override { return top_->in_ready_o; }
  bool out_valid() const override { return top_->out_valid_o; }
  FixedSample output() const override {
    FixedSample s;
    s.angle = top_->angle_o;
    s.region = top_->region_o;
    s.ovf = top_->ovf_o;
    s.los = top_->los_o;
    s.dos = top_->dos_o;
    s.magnitude = static_cast<int64_t>(top_->mag_o);
    return s;
  }
  void* public_var(const char* scope, const char* name) override {
    const VerilatedScope* s = ctx_->scopeFind((std::string("TOP.") + scope).c_str());
    if (!s) s = ctx_->scopeFind(scope);
    VerilatedVar* v = s ? s->varFind(name) : nullptr;
    return v ? v->datap() : nullptr;
  }

 protected:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  std::unique_ptr<VerilatedFstC> tfp_;
};

template <class V>
class VerilatedTop final : public Verilated<V, TopModel> {
 public:
  explicit VerilatedTop(const SimOptions& opt) : Verilated<V, TopModel>(opt) {
    this->top_->reg_we_i = 0;
  }
  void set_reg(uint32_t addr, uint64_t wdata, bool we) override {
    this->top_->reg_addr_i = static_cast<std::decay_t<decltype(this->top_->reg_addr_i)>>(addr);
    this->top_->reg_wdata_i = static_cast<std::decay_t<decltype(this->top_->reg_wdata_i)>>(wdata);
    this->top_->reg_we_i = we;
  }
  uint64_t reg_rdata() const override { return this->top_->reg_rdata_o; }
  void set_window(uint64_t lo, uint64_t hi) override {
    this->top_->mag_lo_i = static_cast<std::decay_t<decltype(this->top_->mag_lo_i)>>(lo);
    this->top_->mag_hi_i = static_cast<std::decay_t<decltype(this->top_->mag_hi_i)>>(hi);
  }
};

template <class V>
class VerilatedShell final : public Verilated<V, ShellModel> {
 public:
  explicit VerilatedShell(const SimOptions& opt) : Verilated<V, ShellModel>(opt) {
    set_apb(false, false, false, 0, 0, 0);
  }
  void set_apb(bool psel, bool penable, bool pwrite, uint32_t paddr, uint32_t pwdata,
               uint32_t pstrb) override {
    auto& t = *this->top_;
    t.psel_i = psel;
    t.penable_i = penable;
    t.pwrite_i = pwrite;
    t.paddr_i = static_cast<std::decay_t<decltype(t.paddr_i)>>(paddr);
    t.pwdata_i = pwdata;
    t.pstrb_i = static_cast<std::decay_t<decltype(t.pstrb_i)>>(pstrb);
  }
  uint32_t prdata() const override { return this->top_->prdata_o; }
  bool pready() const override { return this->top_->pready_o; }
  bool pslverr() const override { return this->top_->pslverr_o; }
  bool irq() const override { return this->top_->irq_o; }
  bool out_tag() const override { return this->top_->out_tag_o; }
};

template <class V>
TopModel* make_top(const SimOptions& opt) {
  return new VerilatedTop<V>(opt);
}
template <class V>
ShellModel* make_shell(const SimOptions& opt) {
  return new VerilatedShell<V>(opt);
}

}  // namespace acore::rtl

// The plugin's one export. KIND is top or shell; LATENCY and CYCLES are expressions (the built
// top's public localparams, 0 for the shell).
#define ACORE_RTL_PLUGIN(V, NAME, MODULE, PARAMS, LATENCY, CYCLES, MAKE_TOP, MAKE_SHELL)  \
  extern "C" __attribute__((visibility("default"))) const acore::rtl::PluginInfo*         \
  acore_rtl_plugin() {                                                                    \
    static const acore::rtl::PluginInfo info{                                             \
        acore::rtl::kAbi,         NAME,     MODULE,    PARAMS, static_cast<int>(LATENCY), \
        static_cast<int>(CYCLES), MAKE_TOP, MAKE_SHELL};                                  \
    return &info;                                                                         \
  }
