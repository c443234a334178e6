// SPDX-License-Identifier: MIT
// Pin-level access to one Verilated build of rtl/acore_top.v. Every named configuration of
// rtl/configs.txt is Verilated into its own class (Vacore_top_<name>) whose port types depend on
// the widths; RtlPins hides that behind one interface so the harness (rtl_engine.cpp) is written
// once. VerilatedPins<V> implements it for any such class.
#pragma once
#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <memory>
#include <type_traits>

#include "engine/fixed_model.hpp"

namespace acore {

// The sample stream's pins, the same on both tops and on the APB shell around them.
template <class V>
void drive_stream_in(V& top, bool valid, const ChannelCodes& c, uint32_t mask) {
  using C = std::decay_t<decltype(top.c1_i)>;
  top.in_valid_i = valid;
  top.c1_i = static_cast<C>(static_cast<uint32_t>(c[0]) & mask);
  top.c2_i = static_cast<C>(static_cast<uint32_t>(c[1]) & mask);
  top.c3_i = static_cast<C>(static_cast<uint32_t>(c[2]) & mask);
  top.c4_i = static_cast<C>(static_cast<uint32_t>(c[3]) & mask);
}

template <class V>
FixedSample read_stream_out(const V& top) {
  FixedSample s;
  s.angle = top.angle_o;
  s.region = top.region_o;
  s.ovf = top.ovf_o;
  s.los = top.los_o;
  s.dos = top.dos_o;
  return s;
}

class RtlPins {
 public:
  virtual ~RtlPins() = default;
  virtual void set_clk(bool v) = 0;
  virtual void set_rst(bool v) = 0;
  virtual void set_reg(uint32_t addr, uint64_t wdata, bool we) = 0;
  virtual void set_window(uint64_t mag_lo, uint64_t mag_hi) = 0;
  virtual void set_in(bool valid, const ChannelCodes& c, uint32_t in_mask) = 0;
  virtual void set_out_ready(bool v) = 0;
  virtual void eval() = 0;
  virtual void trace(VerilatedFstC* tfp) = 0;
  virtual void final() = 0;
  virtual bool in_ready() const = 0;
  virtual bool out_valid() const = 0;
  virtual uint64_t reg_rdata() const = 0;
  virtual FixedSample output() const = 0;
};

template <class V>
class VerilatedPins final : public RtlPins {
 public:
  VerilatedPins(VerilatedContext* ctx, const char* name) : top_(std::make_unique<V>(ctx, name)) {}
  void set_clk(bool v) override { top_->clk_i = v; }
  void set_rst(bool v) override { top_->rst_i = v; }
  void set_reg(uint32_t addr, uint64_t wdata, bool we) override {
    top_->reg_addr_i = static_cast<std::decay_t<decltype(top_->reg_addr_i)>>(addr);
    top_->reg_wdata_i = static_cast<std::decay_t<decltype(top_->reg_wdata_i)>>(wdata);
    top_->reg_we_i = we;
  }
  void set_window(uint64_t lo, uint64_t hi) override {
    top_->mag_lo_i = static_cast<std::decay_t<decltype(top_->mag_lo_i)>>(lo);
    top_->mag_hi_i = static_cast<std::decay_t<decltype(top_->mag_hi_i)>>(hi);
  }
  void set_in(bool valid, const ChannelCodes& c, uint32_t mask) override {
    drive_stream_in(*top_, valid, c, mask);
  }
  void set_out_ready(bool v) override { top_->out_ready_i = v; }
  void eval() override { top_->eval(); }
  void trace(VerilatedFstC* tfp) override { top_->trace(tfp, 99); }
  void final() override { top_->final(); }
  bool in_ready() const override { return top_->in_ready_o; }
  bool out_valid() const override { return top_->out_valid_o; }
  uint64_t reg_rdata() const override { return top_->reg_rdata_o; }
  FixedSample output() const override { return read_stream_out(*top_); }

 private:
  std::unique_ptr<V> top_;
};

}  // namespace acore
