// SPDX-License-Identifier: MIT
#include "rtlsim/run_engine.hpp"

#include "core/errors.hpp"
#include "regmap/codec.hpp"

namespace acore {

bool is_rtl(Engine e) { return e == Engine::Rtl || e == Engine::RtlSerial; }

void check_engine_options(Engine e, const EngineOptions& opt) {
  if (opt.fold != 1 && e != Engine::Rtl) throw InputError("--fold applies to --engine rtl only");
  if (!is_rtl(e) && (opt.gaps > 0 || opt.backpressure > 0 || !opt.trace.empty() || opt.window))
    throw InputError(std::string("--engine ") + engine_name(e) +
                     ": input gaps, backpressure, a trace and a status window apply to the RTL "
                     "engines only (rtl, rtl-serial)");
}

EngineRun run_engine(Engine e, const Recording& rec, const RegImage& img,
                     const EngineOptions& opt) {
  check_engine_options(e, opt);
  EngineRun r;
  if (e == Engine::Float) {
    r.series = run_float(rec, opt.float_coefficients ? *opt.float_coefficients : dequantize(img));
    return r;
  }
  // c1 = sin, c2 = cos, c3 = c4 = 0 for two-channel recordings (FixedModel::to_code per value).
  const std::vector<ChannelCodes> codes = to_codes(rec, img.in_scale, img.cfg.in_w);
  std::vector<FixedSample> model = run_fixed_rows(img, codes);
  if (e == Engine::Fixed) {
    r.series = series_from_fixed(model, img);
    r.rows = std::move(model);
    return r;
  }
  RtlRunOptions ro;
  ro.top = e == Engine::Rtl ? RtlTop::kPipelined : RtlTop::kSerial;
  ro.fold = opt.fold;
  ro.seed = opt.seed;
  ro.gaps = opt.gaps;
  ro.backpressure = opt.backpressure;
  ro.trace = opt.trace;
  ro.window = opt.window;
  ro.module_dir = opt.module_dir;
  r.rows = run_rtl(img, codes, ro);
  r.series = series_from_fixed(r.rows, img);
  // The RTL has no uncorrected output: the bit-accurate model's (the same front end).
  r.series.uncorrected = series_from_fixed(model, img).uncorrected;
  return r;
}

}  // namespace acore
