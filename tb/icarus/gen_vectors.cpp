// SPDX-License-Identifier: MIT
// Test vectors for the Icarus bench (tb/icarus/acore_tb_icarus.v) from the bit-accurate model.
// usage: acore_gen_vectors DIR FRAME [N]   writes DIR/regs.hex, DIR/in.hex, DIR/exp.hex,
// DIR/meta.txt
//   (regs.hex: the register image as every image is written, write_regimage(), with its header;
//   $readmemh skips the `//` lines. meta.txt: samples, mag_lo, mag_hi, the image's CRC-32 in hex
//   for the shell bench)
//   FRAME 0: the paper scenario's calibrated image; paper samples (a turn), then random and extreme
//            codes
//   FRAME 1: a random register image with random inputs (saturation paths)
//   N: samples in all (default: frame 0 7501 = 5000 paper samples, 2500 random codes and the zero
//      vector; frame 1 2501); with N, half of frame 0's are paper samples. tb/icarus/vectors/ holds
//      `acore_gen_vectors tb/icarus/vectors 0 400` (FuseSoC's sim target; tb/fusesoc/fusesoc.sh
//      checks it is current).
#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "calibration/calibration.hpp"
#include "core/errors.hpp"
#include "engine/estimator.hpp"
#include "engine/fixed_model.hpp"
#include "regmap/regimage.hpp"
#include "support/paper_signals.hpp"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: %s DIR FRAME [N]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const int frame = std::stoi(argv[2]);
  const int total = argc == 4 ? std::stoi(argv[3]) : frame == 0 ? 7501 : 2501;
  if (total < 4) {
    std::fprintf(stderr, "%s: N=%d must be >= 4\n", argv[0], total);
    return 2;
  }
  const int n_paper = argc == 4 ? total / 2 : 5000;
  const acore::Recording cal = acore::test::paper_recording(4000, true);
  acore::RegImage img = acore::quantize(acore::calibrate(cal, acore::CalOptions{}),
                                        acore::DatapathConfig{}, acore::choose_in_scale(cal, 16));
  std::mt19937_64 rng(1234 + frame);
  std::vector<acore::ChannelCodes> in;
  if (frame == 0) {
    in = acore::to_codes(acore::test::paper_recording(n_paper, true), img.in_scale, 16);
  } else {
    const uint64_t mask = (uint64_t{1} << img.cfg.reg_w) - 1;
    for (int a = 0; a < img.cfg.addr_atan(0); ++a) img.words[a] = rng() & mask;
  }
  while (static_cast<int>(in.size()) < total - 1) {
    acore::ChannelCodes c;
    for (int j = 0; j < 4; ++j) {
      const uint64_t r = rng();
      c[j] = (r & 7) == 0 ? ((r >> 3) & 1 ? 32767 : -32768) : static_cast<int16_t>(r >> 8);
    }
    in.push_back(c);
  }
  in.push_back({0, 0, 0, 0});
  const acore::StatusWindow w = acore::StatusWindow::defaults(img.cfg);
  const acore::FixedModel model(img, w);
  // Provenance without DIR, so that the committed vectors are what any checkout makes.
  img.provenance.push_back(fmt::format(
      "generator=acore_gen_vectors (tb/icarus/gen_vectors.cpp) frame {} ({}), {} samples", frame,
      frame == 0 ? "the paper scenario's calibrated image" : "random words before the atan table",
      total));
  try {
    acore::write_regimage(img, dir + "/regs.hex");
  } catch (const acore::InputError& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
  std::ofstream vin(dir + "/in.hex"), vexp(dir + "/exp.hex"), meta(dir + "/meta.txt");
  char line[64];
  for (const auto& c : in) {
    std::snprintf(line, sizeof line, "%04x%04x%04x%04x\n", c[0] & 0xffff, c[1] & 0xffff,
                  c[2] & 0xffff, c[3] & 0xffff);
    vin << line;
    const acore::FixedSample s = model.step(c);
    const unsigned v = (s.dos << 20) | (s.los << 19) | (s.ovf << 18) |
                       (static_cast<unsigned>(s.region) << 16) | s.angle;
    std::snprintf(line, sizeof line, "%06x\n", v);
    vexp << line;
  }
  meta << in.size() << " " << w.mag_lo << " " << w.mag_hi << " " << std::hex
       << acore::image_crc32(img) << "\n";
  return vin && vexp && meta ? 0 : 1;
}
