// SPDX-License-Identifier: MIT
// anglecore._core: the C++ model (acore_ip, acore_lab) and the RTL engine (acore_rtlsim) as a
// Python extension. Every function here converts between numpy/Python objects and the model's types
// and calls the model's own function (the one the CLI calls); python/anglecore/__init__.py gives it
// its Python face. Recordings cross as dicts {"channels", "columns": {name: float64 array}, "meta",
// "comments"}: the batch estimate reads the caller's arrays in place, and arrays coming back own
// the C++ vectors they were computed into (no copy either way).
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibration/calibrate_options.hpp"
#include "core/errors.hpp"
#include "core/recording.hpp"
#include "diagnose/diagnose.hpp"
#include "diagnose/physics_bench.hpp"
#include "engine/estimator.hpp"
#include "engine/track_series.hpp"
#include "harmonics/harmonic_attribution.hpp"
#include "harmonics/harmonics.hpp"
#include "regmap/codec.hpp"
#include "regmap/regimage.hpp"
#include "rtlsim/run_engine.hpp"
#include "sim/simulator.hpp"
#include "stages/interfaces.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace acore {
namespace {

using InArray = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
template <typename T>
using OutArray = nb::ndarray<nb::numpy, T, nb::ndim<1>>;

// A vector handed to numpy: the array owns it (moved, not copied).
template <typename T>
nb::object to_numpy(std::vector<T>&& v) {
  auto* owned = new std::vector<T>(std::move(v));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return nb::cast(OutArray<T>(owned->data(), {owned->size()}, owner), nb::rv_policy::reference);
}

// nlohmann::json <-> Python objects (dict, list, str, int, float, bool, None).
nb::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      nb::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[it.key().c_str()] = to_python(it.value());
      return d;
    }
    case nlohmann::json::value_t::array: {
      nb::list l;
      for (const auto& v : j) l.append(to_python(v));
      return l;
    }
    case nlohmann::json::value_t::string:
      return nb::str(j.get_ref<const std::string&>().c_str());
    case nlohmann::json::value_t::boolean:
      return nb::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return nb::int_(j.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return nb::int_(j.get<uint64_t>());
    case nlohmann::json::value_t::number_float:
      return nb::float_(j.get<double>());
    default:
      return nb::none();
  }
}

nlohmann::json to_json(nb::handle h) {
  if (h.is_none()) return nullptr;
  if (nb::isinstance<nb::bool_>(h)) return nb::cast<bool>(h);
  if (nb::isinstance<nb::int_>(h)) return nb::cast<int64_t>(h);
  if (nb::isinstance<nb::float_>(h)) return nb::cast<double>(h);
  if (nb::isinstance<nb::str>(h)) return nb::cast<std::string>(h);
  if (nb::isinstance<nb::dict>(h)) {
    nlohmann::json j = nlohmann::json::object();
    for (auto [k, v] : nb::borrow<nb::dict>(h)) j[nb::cast<std::string>(nb::str(k))] = to_json(v);
    return j;
  }
  if (nb::isinstance<nb::list>(h) || nb::isinstance<nb::tuple>(h)) {
    nlohmann::json j = nlohmann::json::array();
    for (nb::handle v : h) j.push_back(to_json(v));
    return j;
  }
  // numpy scalars and the like: through float() when they have it.
  if (nb::hasattr(h, "__float__")) return nb::cast<double>(h.attr("__float__")());
  throw nb::type_error(
      ("cannot convert a " + std::string(nb::type_name(h.type()).c_str()) + " to JSON").c_str());
}

// --- recordings --------------------------------------------------------------------------------

const char* const kChannelNames4[4] = {"c1", "c2", "c3", "c4"};
const char* const kChannelNames2[2] = {"sin", "cos"};

nb::dict recording_to_python(Recording&& rec) {
  nb::dict cols;
  if (rec.has_t()) cols["t"] = to_numpy(std::move(rec.t));
  if (rec.has_theta()) cols["theta_ref"] = to_numpy(std::move(rec.theta_ref));
  for (int c = 0; c < rec.channels; ++c)
    cols[rec.channels == 4 ? kChannelNames4[c] : kChannelNames2[c]] =
        to_numpy(std::move(rec.ch[c]));
  if (rec.has_temp()) cols["temp"] = to_numpy(std::move(rec.temp));
  nb::dict meta;
  for (const auto& [k, v] : rec.meta) meta[k.c_str()] = v;
  nb::dict d;
  d["channels"] = rec.channels;
  d["columns"] = cols;
  d["meta"] = meta;
  d["comments"] = nb::cast(rec.comments);
  return d;
}

std::vector<double> column(const nb::dict& cols, const char* name) {
  if (!cols.contains(name)) return {};
  const InArray a = nb::cast<InArray>(cols[name]);
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

Recording recording_from_python(const nb::dict& d) {
  Recording rec;
  rec.channels = nb::cast<int>(d["channels"]);
  const nb::dict cols = nb::cast<nb::dict>(d["columns"]);
  for (int c = 0; c < rec.channels; ++c)
    rec.ch[c] = column(cols, rec.channels == 4 ? kChannelNames4[c] : kChannelNames2[c]);
  rec.theta_ref = column(cols, "theta_ref");
  rec.t = column(cols, "t");
  rec.temp = column(cols, "temp");
  for (auto [k, v] : nb::cast<nb::dict>(d["meta"]))
    rec.meta[nb::cast<std::string>(nb::str(k))] = nb::cast<std::string>(nb::str(v));
  rec.comments = nb::cast<std::vector<std::string>>(d["comments"]);
  rec.check_consistent("recording");
  return rec;
}

// --- scenarios ---------------------------------------------------------------------------------

Scenario scenario_from_python(nb::handle s) {
  if (nb::isinstance<nb::str>(s)) {
    const std::string name = nb::cast<std::string>(s);
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0)
      return load_scenario(name);
    return builtin_scenario(name);
  }
  return Scenario::from_json(to_json(s), "scenario");
}

// --- estimate ----------------------------------------------------------------------------------

// The bit-accurate batch over the caller's arrays, in place; the GIL is released while it runs.
// The errors are judged as the command judges them (judged_error_deg).
nb::tuple estimate_fixed_batch(const RegImage& img, int channels, const std::vector<InArray>& ch,
                               std::optional<InArray> theta, int periodicity) {
  ChannelColumns in;
  in.channels = channels;
  if (static_cast<int>(ch.size()) != channels)
    throw InputError("estimate: expected " + std::to_string(channels) + " channel arrays");
  in.n = ch[0].shape(0);
  for (int c = 0; c < channels; ++c) {
    if (ch[c].shape(0) != in.n) throw InputError("estimate: channel arrays differ in length");
    in.ch[c] = ch[c].data();
  }
  if (theta) {
    if (theta->shape(0) != in.n) throw InputError("estimate: theta_ref differs in length");
    in.theta_ref = theta->data();
  }
  std::vector<double> angle(in.n), err(theta ? in.n : 0);
  std::vector<uint8_t> flags(in.n), region(in.n);
  {
    nb::gil_scoped_release release;
    run_fixed_batch(img, in, periodicity,
                    {angle.data(), flags.data(), region.data(), theta ? err.data() : nullptr});
    err = judged_error_deg(img, std::move(err));
  }
  return nb::make_tuple(to_numpy(std::move(angle)), to_numpy(std::move(flags)),
                        to_numpy(std::move(region)), theta ? to_numpy(std::move(err)) : nb::none());
}

// Any engine through run_engine (the command's dispatch): (angle, uncorrected, region, flags,
// magnitude) as the command computes them; magnitude (the CORDIC's, the RTL's mag_o) is None for
// the float engine, which has no rows. fold, trace and rtl_dir are the RTL's (EngineOptions).
nb::tuple estimate_series(const RegImage& img, const nb::dict& rec_py, const std::string& engine,
                          int fold, const std::string& trace, const std::string& rtl_dir) {
  const Engine e = parse_engine(engine);
  EngineOptions opt;
  opt.fold = fold;
  opt.trace = trace;
  opt.module_dir = rtl_dir;
  check_engine_options(e, opt);
  const Recording rec = recording_from_python(rec_py);
  EngineRun run;
  {
    nb::gil_scoped_release release;
    run = run_engine(e, rec, img, opt);
  }
  AngleSeries& s = run.series;
  std::vector<uint8_t> region(s.region.begin(), s.region.end()),
      flags(s.flags.begin(), s.flags.end());
  std::vector<int64_t> magnitude;
  magnitude.reserve(run.rows.size());
  for (const FixedSample& r : run.rows) magnitude.push_back(r.magnitude);
  return nb::make_tuple(to_numpy(std::move(s.angle)), to_numpy(std::move(s.uncorrected)),
                        to_numpy(std::move(region)), to_numpy(std::move(flags)),
                        run.rows.empty() ? nb::none() : to_numpy(std::move(magnitude)));
}

// The board's MAG and DIAAGC.AGC (as5047::mag_field, as5047::agc_field) of magnitudes at the
// image's widths: (mag uint16, agc uint8).
nb::tuple board_mag_agc(const RegImage& img,
                        nb::ndarray<const int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu> m) {
  const int mag_w = img.cfg.s_w + 2, s_f = img.cfg.s_f;
  std::vector<uint16_t> mag(m.shape(0));
  std::vector<uint8_t> agc(m.shape(0));
  for (size_t i = 0; i < m.shape(0); ++i) {
    mag[i] = as5047::mag_field(m(i), mag_w);
    agc[i] = as5047::agc_field(m(i), s_f);
  }
  return nb::make_tuple(to_numpy(std::move(mag)), to_numpy(std::move(agc)));
}

// The error an image is judged by (judged_error_deg: about the mean when its zero is unknown).
nb::object judged_error_py(const RegImage& img, InArray angle, InArray theta, int periodicity) {
  if (angle.shape(0) != theta.shape(0)) throw InputError("estimate: theta_ref differs in length");
  const std::vector<double> a(angle.data(), angle.data() + angle.shape(0)),
      t(theta.data(), theta.data() + theta.shape(0));
  return to_numpy(judged_error_deg(img, a, t, periodicity));
}

nb::object estimate_report(const RegImage& img, const std::string& engine, int fold, size_t samples,
                           std::optional<InArray> err, std::optional<InArray> uncorrected_err,
                           size_t flagged) {
  ErrorStats st, su;
  if (err) st = error_stats(err->data(), err->shape(0));
  if (uncorrected_err) su = error_stats(uncorrected_err->data(), uncorrected_err->shape(0));
  return to_python(estimate_json(parse_engine(engine), samples, fold, img,
                                 img.applied_zero_offset(), img.cfg.zero_word != 0,
                                 err ? &st : nullptr, uncorrected_err ? &su : nullptr, flagged));
}

// The tracking observer over the estimated angles with the command's settings (track_series):
// (velocity_rpm or None without t, turns, angle_comp, lot, the JSON fields the command adds:
// track, velocity_error_rpm). t and theta_ref are the recording's columns (None when absent).
nb::tuple track_py(const RegImage& img, InArray angle, std::optional<InArray> t,
                   std::optional<InArray> theta, int periodicity, double bandwidth_hz, double lead,
                   int64_t lot_threshold) {
  const double fs = t ? sample_rate_of_times(t->data(), t->shape(0)) : 0;
  TrackSettings ts;
  ts.bandwidth_hz = bandwidth_hz;
  ts.lead = lead;
  if (lot_threshold >= 0)
    ts.lot_threshold = static_cast<uint32_t>(std::min<int64_t>(lot_threshold, UINT32_MAX));
  const std::vector<double> a(angle.data(), angle.data() + angle.shape(0));
  std::vector<double> ref;
  if (theta) {
    if (theta->shape(0) != angle.shape(0))
      throw InputError("estimate: theta_ref differs in length");
    ref.assign(theta->data(), theta->data() + theta->shape(0));
  }
  if (t && t->shape(0) != angle.shape(0)) throw InputError("estimate: t differs in length");
  nlohmann::json extra = nlohmann::json::object();
  TrackedSeries tr;
  {
    nb::gil_scoped_release release;
    tr = track_series(a, fs, periodicity, img.cfg.angle_w, ts);
    if (fs > 0) {
      extra["track"] = track_json(tr);
      if (theta)
        extra["velocity_error_rpm"] =
            stats_json(error_stats(track_velocity_error_rpm(tr, ref, periodicity)));
    }
  }
  nb::object rpm = tr.has_rate() ? to_numpy(std::move(tr.rpm)) : nb::none();
  return nb::make_tuple(rpm, to_numpy(std::move(tr.turns)), to_numpy(std::move(tr.comp)),
                        to_numpy(std::move(tr.lot)), to_python(extra));
}

// --- calibrate ---------------------------------------------------------------------------------

// Options by their CLI names ('-' -> '_'), each into the same CalibrateSpec the CLI fills.
CalibrateSpec spec_from_python(const nb::dict& o) {
  CalibrateSpec s;
  for (auto [k, v] : o) {
    const std::string key = nb::cast<std::string>(nb::str(k));
    if (key == "correction")
      s.correction = nb::cast<std::string>(v);
    else if (key == "degree")
      s.degree = nb::cast<int>(v);
    else if (key == "regions")
      s.regions = nb::cast<int>(v);
    else if (key == "xcenter")
      s.xcenter = nb::cast<bool>(v);
    else if (key == "iterations")
      s.iterations = nb::cast<int>(v);
    else if (key == "coef_frac")
      s.coef_frac = nb::cast<int>(v);
    else if (key == "angle_w")
      s.angle_w = nb::cast<int>(v);
    else if (key == "in_w")
      s.in_w = nb::cast<int>(v);
    else if (key == "in_scale")
      s.in_scale = nb::cast<double>(v);
    else if (key == "periodicity")
      s.periodicity = nb::cast<int>(v);
    else if (key == "fourier")
      s.fourier = nb::cast<int>(v);
    else if (key == "fourier_iterations")
      s.fourier_iterations = nb::cast<int>(v);
    else if (key == "fourier_guard")
      s.fourier_guard = nb::cast<int>(v);
    else if (key == "zero_offset")
      s.zero_offset = nb::cast<std::string>(v);
    else if (key == "zero_word")
      s.zero_word = nb::cast<bool>(v);
    else if (key == "mult")
      s.mult = nb::cast<int>(v);
    else if (key == "reference")
      s.reference = nb::cast<std::string>(v);
    else if (key == "selfcal_harmonics")
      s.selfcal_harmonics = nb::cast<int>(v);
    else
      throw nb::type_error(("calibrate: unknown option '" + key + "'").c_str());
  }
  return s;
}

nb::tuple calibrate_py(const nb::dict& rec_py, const nb::dict& options, const std::string& what,
                       const std::string& command) {
  const Recording rec = recording_from_python(rec_py);
  const CalibrateSpec spec = spec_from_python(options);
  std::unique_ptr<CalibrateOutcome> out;
  {
    nb::gil_scoped_release release;
    out = std::make_unique<CalibrateOutcome>(calibrate_recording(rec, spec, what, command));
  }
  return nb::make_tuple(out->image, to_python(out->report));
}

// --- lab -----------------------------------------------------------------------------------------

nb::object harmonics_py(nb::handle spec, int grid) {
  const SignalSpec s = nb::isinstance<nb::str>(spec) ? load_signal_spec(nb::cast<std::string>(spec))
                                                     : parse_signal_spec(to_json(spec));
  nlohmann::json j;
  {
    nb::gil_scoped_release release;
    j = analyze(s, grid).to_json();
  }
  return to_python(j);
}

// `harmonics --attribute`'s JSON field "attribution" of the spec (attribute_exact).
nb::object harmonics_attribution_py(nb::handle spec, int grid) {
  const SignalSpec s = nb::isinstance<nb::str>(spec) ? load_signal_spec(nb::cast<std::string>(spec))
                                                     : parse_signal_spec(to_json(spec));
  nlohmann::json j;
  {
    nb::gil_scoped_release release;
    const HarmonicAnalysis a = analyze(s, grid);
    j = a.to_json();
    j["attribution"] = attribution_json(attribute_exact(a));
  }
  return to_python(j);
}

nb::object diagnose_py(const nb::dict& sim, const nb::dict& real, std::optional<nb::dict> holdout,
                       int order) {
  const Recording s = recording_from_python(sim), r = recording_from_python(real);
  std::unique_ptr<Recording> h;
  if (holdout) h = std::make_unique<Recording>(recording_from_python(*holdout));
  DiagnoseOptions opt;
  if (order > 0) opt.fourier_order = order;
  nlohmann::json j;
  {
    nb::gil_scoped_release release;
    j = diagnose(s, r, h.get(), opt).to_json();
  }
  return to_python(j);
}

nb::dict physics_py(const std::string& name, size_t samples, uint64_t seed, size_t index) {
  for (const PhysicsScenario& sc : physics_scenarios()) {
    if (sc.name != name) continue;
    const PhysicsCase c = draw_physics_case(seed, index, sc);
    BenchRecordings r = make_physics_recordings(c, samples);
    nb::dict d;
    d["sim"] = recording_to_python(std::move(r.sim));
    d["real"] = recording_to_python(std::move(r.real));
    d["holdout"] = recording_to_python(std::move(r.holdout));
    d["truth"] = sc.truth;
    d["sensor"] = sc.sensor;
    d["why"] = sc.why;
    return d;
  }
  std::string names;
  for (const PhysicsScenario& sc : physics_scenarios())
    names += (names.empty() ? "" : ", ") + sc.name;
  throw InputError("physics scenario '" + name + "': not one of " + names);
}

}  // namespace
}  // namespace acore

NB_MODULE(_core, m) {
  using namespace acore;
  m.doc() =
      "AngleCore's C++ model (acore_ip, acore_lab) and RTL engine (acore_rtlsim); use the "
      "anglecore package, not this.";
  // A missing RTL module: its own type (a ValueError, as every input error), so that a caller can
  // tell it apart; the message names the command that builds the module. The module attribute
  // keeps the type alive (a plain pointer: nothing to release after the interpreter has gone).
  static PyObject* rtl_not_built =
      nb::exception<RtlNotBuilt>(m, "RtlNotBuilt", PyExc_ValueError).ptr();
  // The model's input errors are the caller's to fix: ValueError with the model's own message.
  nb::register_exception_translator([](const std::exception_ptr& p, void*) {
    try {
      std::rethrow_exception(p);
    } catch (const RtlNotBuilt& e) {
      PyErr_SetString(rtl_not_built, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const CheckFailed& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const nlohmann::json::exception& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  nb::class_<RegImage>(m, "RegImage")
      .def_prop_ro("words",
                   [](const RegImage& img) {
                     return to_numpy(std::vector<uint64_t>(img.words.begin(), img.words.end()));
                   })
      .def_prop_ro("text", [](const RegImage& img) { return format_regimage(img); })
      .def_prop_ro("crc32", [](const RegImage& img) { return image_crc32(img); })
      .def_prop_ro("in_scale", [](const RegImage& img) { return img.in_scale; })
      .def_prop_ro("angle_w", [](const RegImage& img) { return img.cfg.angle_w; })
      .def_prop_ro("zero_offset", [](const RegImage& img) { return img.zero_offset; })
      .def("write", [](const RegImage& img, const std::string& path) { write_regimage(img, path); })
      .def("calibrated_float", [](const RegImage& img) {
        // The dequantized coefficients the float engine runs, as JSON-like dict.
        const FloatCoefficients fc = dequantize(img);
        return to_python({{"offset", {fc.offset[0], fc.offset[1]}},
                          {"amplitude", {fc.amp[0], fc.amp[1]}},
                          {"poly", fc.poly},
                          {"fourier", fc.fourier}});
      });
  m.def("read_image", &read_regimage, "path"_a);
  m.def("parse_image", &parse_regimage, "text"_a, "name"_a);

  m.def("read_recording",
        [](const std::string& path) { return recording_to_python(read_recording(path)); });
  m.def("parse_recording", [](const std::string& text, const std::string& name) {
    return recording_to_python(parse_recording(text, name));
  });
  m.def("write_recording", [](const nb::dict& rec, const std::string& path) {
    write_recording(recording_from_python(rec), path);
  });
  m.def("format_recording",
        [](const nb::dict& rec) { return format_recording(recording_from_python(rec)); });
  m.def("recording_periodicity", [](const nb::dict& rec, const std::string& what) {
    Recording r;
    for (auto [k, v] : nb::cast<nb::dict>(rec["meta"]))
      r.meta[nb::cast<std::string>(nb::str(k))] = nb::cast<std::string>(nb::str(v));
    return recording_periodicity(r, what);
  });

  m.def("scenario_names", &builtin_scenario_names);
  m.def(
      "scenario_json",
      [](nb::handle s, int channels) {
        Scenario sc = scenario_from_python(s);
        if (channels) sc = with_channels(sc, channels);
        return to_python(sc.to_json());
      },
      "scenario"_a, "channels"_a = 0);
  m.def(
      "simulate",
      [](nb::handle s, size_t samples, uint64_t seed, int channels) {
        Scenario sc = scenario_from_python(s);
        if (channels) sc = with_channels(sc, channels);
        if (samples < 1) throw InputError("simulate: samples must be >= 1");
        Recording rec;
        {
          nb::gil_scoped_release release;
          rec = simulate(sc, samples, seed);
        }
        rec.comments.push_back("anglecore simulate: " +
                               (sc.description.empty() ? sc.name : sc.description));
        return recording_to_python(std::move(rec));
      },
      "scenario"_a, "samples"_a, "seed"_a, "channels"_a = 0);
  m.def("physics_scenarios", [] {
    nb::list l;
    for (const PhysicsScenario& s : physics_scenarios())
      l.append(
          to_python({{"name", s.name}, {"sensor", s.sensor}, {"truth", s.truth}, {"why", s.why}}));
    return l;
  });
  m.def("simulate_physics", &physics_py, "name"_a, "samples"_a, "seed"_a, "index"_a = 0);

  m.def("calibrate", &calibrate_py, "recording"_a, "options"_a, "what"_a, "command"_a);
  m.def("estimate_fixed_batch", &estimate_fixed_batch, "image"_a, "channels"_a,
        "arrays"_a.noconvert(), "theta_ref"_a.noconvert().none(), "periodicity"_a);
  m.def("board_mag_agc", &board_mag_agc, "image"_a, "magnitude"_a.noconvert());
  m.def("estimate_series", &estimate_series, "image"_a, "recording"_a, "engine"_a, "fold"_a = 1,
        "trace"_a = "", "rtl_dir"_a = "");
  m.def("judged_error_deg", &judged_error_py, "image"_a, "angle"_a.noconvert(),
        "theta_ref"_a.noconvert(), "periodicity"_a);
  m.def("estimate_report", &estimate_report, "image"_a, "engine"_a, "fold"_a, "samples"_a,
        "error_deg"_a.noconvert().none(), "uncorrected_error_deg"_a.noconvert().none(),
        "flagged"_a);
  m.def("harmonics", &harmonics_py, "spec"_a, "grid"_a = 0);
  m.def("harmonics_attributed", &harmonics_attribution_py, "spec"_a, "grid"_a = 0);
  m.def("track", &track_py, "image"_a, "angle"_a.noconvert(), "t"_a.noconvert().none(),
        "theta_ref"_a.noconvert().none(), "periodicity"_a, "bandwidth_hz"_a, "lead"_a,
        "lot_threshold"_a);
  m.def("diagnose", &diagnose_py, "sim"_a, "real"_a, "holdout"_a.none(), "order"_a = 0);
}
