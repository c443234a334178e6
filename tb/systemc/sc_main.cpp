// SPDX-License-Identifier: MIT
// SystemC co-sim: the Verilated `--sc` top (Vacore_top_sc) against the bit-accurate model wrapped
// as an SC_MODULE (RefModel), on a clocked bench with random input gaps and output backpressure,
// register loading through the write port and reprogramming between frames. Frames: the paper
// scenario (10^5 samples by default) and random register images with random inputs.
// usage: sc_cosim [SAMPLES] [+trace]   exit 0 = no mismatch
#include <systemc.h>
#include <verilated.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <random>

#include "Vacore_top_sc.h"
#include "calibration/calibration.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "support/paper_signals.hpp"

namespace {

using acore::ChannelCodes;
using acore::FixedSample;

// The bit-accurate model as a SystemC module: it watches the input handshake and queues the
// expected output of every accepted sample.
SC_MODULE(RefModel) {
  sc_in<bool> clk, rst, in_valid, in_ready;
  sc_in<uint32_t> c1, c2, c3, c4;
  std::unique_ptr<acore::FixedModel> model;
  std::deque<FixedSample> expected;

  void on_clock() {
    if (rst.read()) {
      expected.clear();
      return;
    }
    if (!(in_valid.read() && in_ready.read()) || !model) return;
    auto code = [](uint32_t v) { return static_cast<int32_t>(static_cast<int16_t>(v & 0xffff)); };
    expected.push_back(
        model->step({code(c1.read()), code(c2.read()), code(c3.read()), code(c4.read())}));
  }
  SC_CTOR(RefModel) {
    SC_METHOD(on_clock);
    sensitive << clk.pos();
    dont_initialize();
  }
};

struct Frame {
  acore::RegImage img;
  std::vector<ChannelCodes> in;
};

// Driver (register writes, stream with gaps) and checker (compares every accepted output).
SC_MODULE(Bench) {
  sc_in<bool> clk;
  sc_out<bool> rst, reg_we, in_valid, out_ready;
  sc_out<uint32_t> reg_addr, reg_wdata, mag_lo, mag_hi, c1, c2, c3, c4;
  sc_in<bool> in_ready, out_valid, ovf, los, dos;
  sc_in<uint32_t> angle, region, mag;
  RefModel* ref = nullptr;
  std::vector<Frame> frames;
  size_t compared = 0, mismatches = 0, invalid_nonzero = 0;
  bool done = false;
  std::mt19937_64 rng{42};

  void check() {
    if (rst.read()) return;
    if (!out_valid.read()) {
      if (angle.read() || region.read() || ovf.read() || los.read() || dos.read() || mag.read())
        ++invalid_nonzero;
      return;
    }
    if (!out_ready.read()) return;
    if (ref->expected.empty()) {
      ++mismatches;
      return;
    }
    const FixedSample m = ref->expected.front();
    ref->expected.pop_front();
    FixedSample r;
    r.angle = angle.read();
    r.region = static_cast<int>(region.read());
    r.ovf = ovf.read();
    r.los = los.read();
    r.dos = dos.read();
    r.magnitude = mag.read();
    if (!(r == m)) {
      if (mismatches == 0)
        std::printf(
            "first mismatch at output %zu: rtl angle=%u region=%d flags=%d%d%d magnitude=%lld, "
            "model angle=%u region=%d flags=%d%d%d magnitude=%lld\n",
            compared, r.angle, r.region, r.ovf, r.los, r.dos, static_cast<long long>(r.magnitude),
            m.angle, m.region, m.ovf, m.los, m.dos, static_cast<long long>(m.magnitude));
      ++mismatches;
    }
    ++compared;
  }

  void drive() {
    std::uniform_real_distribution<double> u(0, 1);
    in_valid.write(false);
    out_ready.write(true);
    reg_we.write(false);
    rst.write(true);
    wait(3);
    rst.write(false);
    for (size_t f = 0; f < frames.size(); ++f) {
      const Frame& fr = frames[f];
      // Drain, then reprogram the register file and the status window.
      while (!ref->expected.empty()) wait();
      const acore::StatusWindow w = acore::StatusWindow::defaults(fr.img.cfg);
      mag_lo.write(static_cast<uint32_t>(w.mag_lo));
      mag_hi.write(static_cast<uint32_t>(w.mag_hi));
      for (size_t a = 0; a < fr.img.words.size(); ++a) {
        reg_addr.write(static_cast<uint32_t>(a));
        reg_wdata.write(static_cast<uint32_t>(fr.img.words[a]));
        reg_we.write(true);
        wait();
      }
      reg_we.write(false);
      wait();
      ref->model = std::make_unique<acore::FixedModel>(fr.img, w);
      const double gap = f % 2 ? 0.3 : 0.0, bp = f % 2 ? 0.3 : 0.05;
      size_t next = 0;
      while (next < fr.in.size()) {
        const bool v = u(rng) >= gap;
        in_valid.write(v);
        if (v) {
          c1.write(static_cast<uint32_t>(fr.in[next][0]) & 0xffff);
          c2.write(static_cast<uint32_t>(fr.in[next][1]) & 0xffff);
          c3.write(static_cast<uint32_t>(fr.in[next][2]) & 0xffff);
          c4.write(static_cast<uint32_t>(fr.in[next][3]) & 0xffff);
        }
        out_ready.write(u(rng) >= bp);
        wait();
        if (v && in_ready.read()) ++next;
      }
      in_valid.write(false);
      out_ready.write(true);
    }
    while (!ref->expected.empty()) wait();
    wait(5);
    done = true;
    sc_stop();
  }

  SC_CTOR(Bench) {
    SC_METHOD(check);
    sensitive << clk.pos();
    dont_initialize();
    SC_CTHREAD(drive, clk.pos());
  }
};

}  // namespace

int sc_main(int argc, char** argv) {
  Verilated::commandArgs(argc, argv);
  Verilated::randReset(2);
  size_t samples = 100000;
  bool trace = false;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "+trace")
      trace = true;
    else if (argv[i][0] != '+')
      samples = std::stoul(argv[i]);
  }
  // Frames: the paper scenario, then random images with random inputs (saturation paths).
  std::vector<Frame> frames;
  {
    const acore::Recording cal = acore::test::paper_recording(4000, true);
    const acore::FloatCoefficients fc = acore::calibrate(cal, acore::CalOptions{});
    Frame f;
    f.img = acore::quantize(fc, acore::DatapathConfig{}, acore::choose_in_scale(cal, 16));
    f.in = acore::to_codes(acore::test::paper_recording(samples, true), f.img.in_scale, 16);
    frames.push_back(f);
    std::mt19937_64 rng(7);
    for (int k = 0; k < 4; ++k) {
      Frame r;
      r.img = f.img;
      const uint64_t mask = (uint64_t{1} << r.img.cfg.reg_w) - 1;
      for (int a = 0; a < r.img.cfg.addr_atan(0); ++a) r.img.words[a] = rng() & mask;
      r.in.resize(samples / 10);
      for (auto& c : r.in)
        for (int j = 0; j < 4; ++j)
          c[j] = static_cast<int32_t>(static_cast<int16_t>(rng() & 0xffff));
      frames.push_back(r);
    }
  }
  size_t total = 0;
  for (const auto& f : frames) total += f.in.size();

  sc_clock clk("clk", 10, SC_NS);
  sc_signal<bool> rst, reg_we, in_valid, in_ready, out_valid, out_ready, ovf, los, dos;
  sc_signal<uint32_t> reg_addr, reg_wdata, reg_rdata, mag_lo, mag_hi, c1, c2, c3, c4, angle, region,
      mag;

  Vacore_top_sc dut("dut");
  dut.clk_i(clk);
  dut.rst_i(rst);
  dut.reg_addr_i(reg_addr);
  dut.reg_wdata_i(reg_wdata);
  dut.reg_we_i(reg_we);
  dut.reg_rdata_o(reg_rdata);
  dut.mag_lo_i(mag_lo);
  dut.mag_hi_i(mag_hi);
  dut.in_valid_i(in_valid);
  dut.in_ready_o(in_ready);
  dut.c1_i(c1);
  dut.c2_i(c2);
  dut.c3_i(c3);
  dut.c4_i(c4);
  dut.out_valid_o(out_valid);
  dut.out_ready_i(out_ready);
  dut.angle_o(angle);
  dut.region_o(region);
  dut.ovf_o(ovf);
  dut.los_o(los);
  dut.dos_o(dos);
  dut.mag_o(mag);

  RefModel ref("ref");
  ref.clk(clk);
  ref.rst(rst);
  ref.in_valid(in_valid);
  ref.in_ready(in_ready);
  ref.c1(c1);
  ref.c2(c2);
  ref.c3(c3);
  ref.c4(c4);

  Bench bench("bench");
  bench.ref = &ref;
  bench.frames = std::move(frames);
  bench.clk(clk);
  bench.rst(rst);
  bench.reg_we(reg_we);
  bench.in_valid(in_valid);
  bench.out_ready(out_ready);
  bench.reg_addr(reg_addr);
  bench.reg_wdata(reg_wdata);
  bench.mag_lo(mag_lo);
  bench.mag_hi(mag_hi);
  bench.c1(c1);
  bench.c2(c2);
  bench.c3(c3);
  bench.c4(c4);
  bench.in_ready(in_ready);
  bench.out_valid(out_valid);
  bench.ovf(ovf);
  bench.los(los);
  bench.dos(dos);
  bench.angle(angle);
  bench.region(region);
  bench.mag(mag);

  sc_trace_file* tf = nullptr;
  if (trace) {
    tf = sc_create_vcd_trace_file("sc_cosim");
    sc_trace(tf, clk, "clk");
    sc_trace(tf, in_valid, "in_valid");
    sc_trace(tf, in_ready, "in_ready");
    sc_trace(tf, out_valid, "out_valid");
    sc_trace(tf, out_ready, "out_ready");
    sc_trace(tf, angle, "angle");
  }
  sc_start();
  dut.final();
  if (tf) sc_close_vcd_trace_file(tf);
  std::printf(
      "SystemC co-sim: %zu samples sent, %zu compared, %zu mismatches, %zu non-zero outputs while "
      "invalid\n",
      total, bench.compared, bench.mismatches, bench.invalid_nonzero);
  const bool ok =
      bench.done && bench.mismatches == 0 && bench.compared == total && bench.invalid_nonzero == 0;
  return ok ? 0 : 1;
}
