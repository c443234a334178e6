// SPDX-License-Identifier: MIT
// The driver of the APB register shell (rtl/acore_apb.v), written once for both tops it wraps:
// a clock harness, an APB4 master (a queue of transfers, back to back, sampled at the access
// phase), a valid/ready stream driver with random input gaps and output backpressure that records
// when each sample was taken and every output with its generation tag, and the host operations a
// firmware driver performs (load the shadow, commit under a CRC check, poll STATUS). Everything
// advances in tick(), so the host talks to the shell while samples flow.
//
//   ShellDriver d(rtl_build_named("apb_serial"));
//   d.reset();
//   d.write_shadow(img);                                    // 0x400 + 4a <- word a
//   uint32_t st = d.commit(true, image_crc32(img));         // CRC_EXPECTED, CTRL.COMMIT, poll BUSY
//   if (st & shell::kStatusCrcShadow) ...                       // refused: the active image is
//   unchanged d.stream(codes, 0.0, 0.3, seed); d.drain();             // outputs() carry their tags
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "rtlsim/rtl_builds.hpp"
#include "shell/shell_regs.hpp"

namespace acore {

// The shell's builds are the registry's acore_apb lines with the `sim` flow (rtl_builds.hpp):
// build.serial tells which top it wraps, build.cfg that top's configuration.

// One APB transfer; done, rdata, slverr and cycle are filled in when its access phase completes.
struct ApbTransfer {
  bool write = false;
  uint32_t addr = 0, wdata = 0, strb = 0xF;
  bool done = false;
  uint32_t rdata = 0;
  bool slverr = false;
  uint64_t cycle = 0;  // the clock (tick number) whose edge completed it
};

// One output sample and the generation bit (out_tag_o) it carried.
struct ShellOutput {
  FixedSample sample;
  bool tag = false;
  uint64_t cycle = 0;
};

class ShellDriver {
 public:
  // trace: FST file ("" = none); rand_reset: Verilated::randReset mode (2 = random initial state).
  explicit ShellDriver(const RtlBuild& build, const std::string& trace = "", int rand_reset = 2,
                       uint64_t seed = 1);
  ~ShellDriver();
  ShellDriver(const ShellDriver&) = delete;
  ShellDriver& operator=(const ShellDriver&) = delete;

  // ---- clock ----
  // One clock: drive the APB and stream pins, settle, sample (transfer completions, handshakes,
  // the on_clock hook), then the rising and falling edges.
  void tick();
  void ticks(int n);
  // rst_i high for `cycles` clocks, then low (the stream and APB keep their queues).
  void reset(int cycles = 4);
  void set_reset(bool rst);
  uint64_t cycles() const;
  // Called every clock after the inputs settled, before the edge (pins() shows this clock).
  void on_clock(std::function<void()> f);

  // ---- APB master ----
  std::shared_ptr<const ApbTransfer> post(bool write, uint32_t addr, uint32_t wdata = 0,
                                          uint32_t strb = 0xF);
  bool apb_idle() const;
  // Blocking forms: tick until the transfer completes (streams keep flowing).
  uint32_t read(uint32_t addr, bool* slverr = nullptr);
  bool write(uint32_t addr, uint32_t data, uint32_t strb = 0xF);  // returns PSLVERR
  // Protocol observations: access-phase clocks with PREADY low (wait states), clocks with PSLVERR
  // high outside an access phase, clocks with PRDATA nonzero outside a read's access phase.
  struct ApbStats {
    uint64_t transfers = 0, wait_states = 0, stray_slverr = 0, stray_prdata = 0;
  };
  const ApbStats& apb_stats() const;

  // ---- host operations ----
  // Every word of the image into the shadow window (throws CheckFailed on PSLVERR).
  void write_shadow(const RegImage& img);
  // CTRL's persistent bits (CRC_CHECK, SCRUB, IRQ_EN; the driver keeps a copy) and STATUS.
  void set_ctrl(uint32_t bits);
  uint32_t ctrl() const;
  // CRC_EXPECTED (when check), CTRL.COMMIT with CRC_CHECK = check, then STATUS until BUSY is low;
  // returns that STATUS (throws CheckFailed when the commit write is refused).
  uint32_t commit(bool check, uint32_t crc_expected);
  // write_shadow, then a checked commit with the image's CRC (model image_crc32).
  uint32_t load_and_commit(const RegImage& img);
  void set_window(const StatusWindow& w);

  // ---- streams ----
  // Queues samples; each clock in_valid is high unless a gap (probability `gaps`) and out_ready is
  // low with probability `backpressure` (from `seed`).
  void stream(const std::vector<ChannelCodes>& in, double gaps, double backpressure, uint64_t seed);
  size_t queued() const;  // samples queued since construction
  size_t accepted() const;
  // Clock (tick number) in which each accepted sample was taken, in order.
  const std::vector<uint64_t>& accept_cycles() const;
  const std::vector<ShellOutput>& outputs() const;
  // Ticks until `outputs` outputs have come out in all (default: one per queued sample; fewer when
  // a reset dropped samples in flight) and the APB queue is empty; CheckFailed after max_cycles.
  static constexpr size_t kAllQueued = ~size_t{0};
  void drain(size_t outputs = kAllQueued, uint64_t max_cycles = 50'000'000);
  rtl::ShellModel& pins();

  // ---- the build ----
  const RtlBuild& build() const;
  const DatapathConfig& config() const;
  // A Verilator-public parameter of the wrapped top (LATENCY; CYCLES for the serial core).
  uint32_t top_param(const char* name) const;
  // Backdoor into the top's active coefficient words (model/rtlsim/shell_public.vlt): an upset. The
  // folded top keeps its words in several memory copies (acore_fold_regs.v); the upset goes into
  // the one its host port reads back, the copy the scrubber checks.
  void flip_active_bit(int addr, int bit);
  uint64_t active_word(int addr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acore
