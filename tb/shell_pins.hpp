// SPDX-License-Identifier: MIT
// Pin-level access to one Verilated build of the APB shell (rtl/acore_apb.v) around either top.
// The builds (tb/CMakeLists.txt: Vacore_apb_pipe, SERIAL=0; Vacore_apb_serial, SERIAL=1) differ in
// their port widths; ShellPins hides that so the driver (tb/shell_driver.cpp) is written once.
#pragma once
#include <verilated.h>
#include <verilated_fst_c.h>

#include <cstdint>
#include <memory>
#include <type_traits>

#include "engine/fixed_model.hpp"
#include "rtl_pins.hpp"

namespace acore {

class ShellPins {
 public:
  virtual ~ShellPins() = default;
  virtual void set_clk(bool v) = 0;
  virtual void set_rst(bool v) = 0;
  virtual void set_apb(bool psel, bool penable, bool pwrite, uint32_t paddr, uint32_t pwdata,
                       uint32_t pstrb) = 0;
  virtual void set_in(bool valid, const ChannelCodes& c, uint32_t in_mask) = 0;
  virtual void set_out_ready(bool v) = 0;
  virtual void eval() = 0;
  virtual void trace(VerilatedFstC* tfp) = 0;
  virtual void final() = 0;
  virtual uint32_t prdata() const = 0;
  virtual bool pready() const = 0;
  virtual bool pslverr() const = 0;
  virtual bool irq() const = 0;
  virtual bool in_ready() const = 0;
  virtual bool out_valid() const = 0;
  virtual bool out_tag() const = 0;
  virtual FixedSample output() const = 0;
};

template <class V>
class VerilatedShellPins final : public ShellPins {
 public:
  VerilatedShellPins(VerilatedContext* ctx, const char* name)
      : top_(std::make_unique<V>(ctx, name)) {}
  void set_clk(bool v) override { top_->clk_i = v; }
  void set_rst(bool v) override { top_->rst_i = v; }
  void set_apb(bool psel, bool penable, bool pwrite, uint32_t paddr, uint32_t pwdata,
               uint32_t pstrb) override {
    top_->psel_i = psel;
    top_->penable_i = penable;
    top_->pwrite_i = pwrite;
    top_->paddr_i = static_cast<std::decay_t<decltype(top_->paddr_i)>>(paddr);
    top_->pwdata_i = pwdata;
    top_->pstrb_i = static_cast<std::decay_t<decltype(top_->pstrb_i)>>(pstrb);
  }
  void set_in(bool valid, const ChannelCodes& c, uint32_t mask) override {
    drive_stream_in(*top_, valid, c, mask);
  }
  void set_out_ready(bool v) override { top_->out_ready_i = v; }
  void eval() override { top_->eval(); }
  void trace(VerilatedFstC* tfp) override { top_->trace(tfp, 99); }
  void final() override { top_->final(); }
  uint32_t prdata() const override { return top_->prdata_o; }
  bool pready() const override { return top_->pready_o; }
  bool pslverr() const override { return top_->pslverr_o; }
  bool irq() const override { return top_->irq_o; }
  bool in_ready() const override { return top_->in_ready_o; }
  bool out_valid() const override { return top_->out_valid_o; }
  bool out_tag() const override { return top_->out_tag_o; }
  FixedSample output() const override { return read_stream_out(*top_); }

 private:
  std::unique_ptr<V> top_;
};

}  // namespace acore
