// SPDX-License-Identifier: MIT
#include "engine/estimator.hpp"

#include <algorithm>
#include <cmath>

#include "core/angle.hpp"
#include "core/errors.hpp"
#include "engine/float_model.hpp"

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
    case Engine::Float:
      return "float";
    case Engine::Fixed:
      return "fixed";
    case Engine::Rtl:
      return "rtl";
    case Engine::RtlSerial:
      return "rtl-serial";
  }
  return "?";
}

std::vector<ChannelCodes> to_codes(const Recording& rec, double in_scale, int in_w) {
  std::vector<ChannelCodes> codes(rec.size());
  for (size_t i = 0; i < rec.size(); ++i)
    for (int c = 0; c < 4; ++c)
      codes[i][c] = c < rec.channels
                        ? static_cast<int32_t>(FixedModel::to_code(rec.ch[c][i], in_scale, in_w))
                        : 0;
  return codes;
}

namespace {
// a - offset in [0, 2 pi); a itself when there is no offset (so such angles stay bit for bit).
double minus_offset(double a, double offset) {
  if (offset == 0.0) return a;
  const double r = std::fmod(a - offset, 2 * M_PI);
  return r < 0 ? r + 2 * M_PI : r;
}
}  // namespace

AngleSeries run_float(const Recording& rec, const FloatCoefficients& fc) {
  AngleSeries out;
  const size_t n = rec.size();
  out.angle.resize(n);
  out.uncorrected.resize(n);
  out.region.resize(n);
  out.flags.assign(n, 0);
  out.zero_offset = fc.zero_offset;
  out.zero_word = fc.zero_word != 0;
  const double sw = fc.software_zero_offset();
  for (size_t i = 0; i < n; ++i) {
    const FloatSample s = float_estimate(rec.d13(i), rec.d24(i), fc);
    out.angle[i] = minus_offset(s.angle, sw);
    out.uncorrected[i] = minus_offset(s.uncorrected, sw);
    out.region[i] = s.region;
  }
  return out;
}

AngleSeries series_from_fixed(const std::vector<FixedSample>& rows, const RegImage& img) {
  const DatapathConfig& cfg = img.cfg;
  AngleSeries out;
  out.zero_offset = img.applied_zero_offset();
  out.zero_word = cfg.zero_word != 0;
  const double sw = img.software_zero_offset();
  const double to_rad = 2 * M_PI / std::ldexp(1.0, cfg.angle_w);
  for (const FixedSample& r : rows) {
    out.angle.push_back(minus_offset(r.angle * to_rad, sw));
    out.uncorrected.push_back(minus_offset(r.uncorrected_angle * to_rad, sw));
    out.region.push_back(r.region);
    out.flags.push_back((r.ovf ? 1u : 0u) | (r.los ? 2u : 0u) | (r.dos ? 4u : 0u));
  }
  return out;
}

std::vector<FixedSample> run_fixed_rows(const RegImage& img,
                                        const std::vector<ChannelCodes>& codes) {
  const FixedModel model(img);
  std::vector<FixedSample> rows;
  rows.reserve(codes.size());
  for (const ChannelCodes& c : codes) rows.push_back(model.step(c));
  return rows;
}

AngleSeries run_fixed(const Recording& rec, const RegImage& img) {
  return series_from_fixed(run_fixed_rows(img, to_codes(rec, img.in_scale, img.cfg.in_w)), img);
}

void run_fixed_batch(const RegImage& img, const ChannelColumns& in, int periodicity,
                     const BatchAngles& out) {
  const FixedModel model(img);
  const int in_w = img.cfg.in_w;
  const double sw = img.software_zero_offset();
  const double to_rad = 2 * M_PI / std::ldexp(1.0, img.cfg.angle_w);
  constexpr size_t kChunk = 4096;  // codes and outputs stay in cache between the two passes
  std::vector<ChannelCodes> codes(std::min(kChunk, in.n));
  std::vector<FixedOutput> rows(codes.size());
  for (size_t start = 0; start < in.n; start += kChunk) {
    const size_t m = std::min(kChunk, in.n - start);
    for (size_t i = 0; i < m; ++i)
      for (int c = 0; c < 4; ++c)
        codes[i][c] =
            c < in.channels
                ? static_cast<int32_t>(FixedModel::to_code(in.ch[c][start + i], img.in_scale, in_w))
                : 0;
    model.run_batch(codes.data(), m, rows.data());
    for (size_t i = 0; i < m; ++i) {
      const size_t k = start + i;
      out.angle[k] = minus_offset(rows[i].angle * to_rad, sw);
      if (out.flags) out.flags[k] = rows[i].flags;
      if (out.region) out.region[k] = rows[i].region;
      if (out.error_deg && in.theta_ref)
        out.error_deg[k] = wrap_deg((out.angle[k] - periodicity * in.theta_ref[k]) * 180.0 / M_PI);
    }
  }
}

std::vector<double> judged_error_deg(const RegImage& img, const std::vector<double>& angle_rad,
                                     const std::vector<double>& theta_ref, int periodicity) {
  return judged_error_deg(img, angle_error_deg(angle_rad, theta_ref, periodicity));
}

std::vector<double> judged_error_deg(const RegImage& img, std::vector<double> error_deg) {
  if (img.zero_reference_unknown()) return about_mean_deg(error_deg);
  return error_deg;  // moved, not copied (the Python package's fast path hands over its errors)
}

nlohmann::json estimate_json(Engine engine, size_t samples, int fold, const RegImage& img,
                             double zero_offset, bool zero_word, const ErrorStats* error,
                             const ErrorStats* uncorrected, size_t flagged) {
  nlohmann::json j = {{"engine", engine_name(engine)}, {"samples", samples}};
  if (engine == Engine::Rtl) j["fold"] = fold;
  j["zero_offset"] = {{"rad", zero_offset},
                      {"deg", zero_offset * 180 / M_PI},
                      {"code", angle_code(zero_offset, img.cfg.angle_w)},
                      {"applied_by", zero_word ? "zero_word" : "software"}};
  if (error) {
    j["error_deg"] = stats_json(*error);
    // A self-calibrated image (zero_reference=none) is judged about the errors' mean.
    j["about_mean"] = img.zero_reference_unknown();
  }
  if (uncorrected) j["uncorrected_error_deg"] = stats_json(*uncorrected);
  j["flagged_samples"] = flagged;
  return j;
}

}  // namespace acore
