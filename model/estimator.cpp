// SPDX-License-Identifier: MIT
#include "estimator.hpp"

#include <cmath>

#include "errors.hpp"
#include "float_model.hpp"

namespace acore {

Engine parse_engine(const std::string& name) {
  if (name == "float") return Engine::Float;
  if (name == "fixed") return Engine::Fixed;
  if (name == "rtl") return Engine::Rtl;
  if (name == "rtl-serial") return Engine::RtlSerial;
  throw InputError("--engine: '" + name + "' is not one of float, fixed, rtl, rtl-serial");
}

const char* engine_name(Engine e) {
  switch (e) {
    case Engine::Float: return "float";
    case Engine::Fixed: return "fixed";
    case Engine::Rtl: return "rtl";
    case Engine::RtlSerial: return "rtl-serial";
  }
  return "?";
}

std::vector<ChannelCodes> to_codes(const Recording& rec, double in_scale, int in_w) {
  std::vector<ChannelCodes> codes(rec.size());
  for (size_t i = 0; i < rec.size(); ++i)
    for (int c = 0; c < 4; ++c)
      codes[i][c] = c < rec.channels ? static_cast<int32_t>(FixedModel::to_code(rec.ch[c][i], in_scale, in_w)) : 0;
  return codes;
}

AngleSeries run_float(const Recording& rec, const FloatCoefficients& fc) {
  AngleSeries out;
  const size_t n = rec.size();
  out.angle.resize(n);
  out.uncorrected.resize(n);
  out.region.resize(n);
  out.flags.assign(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const FloatSample s = float_estimate(rec.d13(i), rec.d24(i), fc);
    out.angle[i] = s.angle;
    out.uncorrected[i] = s.uncorrected;
    out.region[i] = s.region;
  }
  return out;
}

AngleSeries series_from_fixed(const std::vector<FixedSample>& rows, const DatapathConfig& cfg) {
  AngleSeries out;
  const double to_rad = 2 * M_PI / std::ldexp(1.0, cfg.angle_w);
  for (const FixedSample& r : rows) {
    out.angle.push_back(r.angle * to_rad);
    out.uncorrected.push_back(r.uncorrected_angle * to_rad);
    out.region.push_back(r.region);
    out.flags.push_back((r.ovf ? 1u : 0u) | (r.los ? 2u : 0u) | (r.dos ? 4u : 0u));
  }
  return out;
}

AngleSeries run_fixed(const Recording& rec, const RegImage& img) {
  const FixedModel model(img);
  std::vector<FixedSample> rows;
  rows.reserve(rec.size());
  for (const ChannelCodes& c : to_codes(rec, img.in_scale, img.cfg.in_w)) rows.push_back(model.step(c));
  return series_from_fixed(rows, img.cfg);
}

}  // namespace acore
