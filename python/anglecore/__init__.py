# SPDX-License-Identifier: MIT
"""AngleCore's angle-sensor model on numpy arrays (docs/python.md).

    import anglecore as ac
    cal = ac.simulate("paper", samples=3600, seed=11)
    val = ac.simulate("paper", samples=3600, seed=12)
    img = ac.calibrate(cal)
    res = ac.estimate(img, val, engine="fixed")
    print(res.error_deg["rms"])

Every function calls the C++ model's own function (the one the `anglecore` command calls), so the
results equal the command's on the same inputs: register words, bit-accurate angles, statistics.
Bad input raises ValueError with the model's message; a wrong array type TypeError; an RTL engine
whose run-time module is not built RtlNotBuilt (a ValueError naming the command that builds it).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from importlib import metadata
from typing import Any, Optional

import numpy as np

from . import _core

__all__ = [
    "ENGINES",
    "Estimate",
    "Recording",
    "RegisterImage",
    "RtlNotBuilt",
    "board_mag_agc",
    "calibrate",
    "diagnose",
    "estimate",
    "harmonics",
    "physics_scenarios",
    "read_image",
    "read_recording",
    "scenarios",
    "simulate",
    "simulate_physics",
]

# The project's version (the top-level CMakeLists.txt's project(), its one source), as installed.
__version__ = metadata.version("anglecore")

RtlNotBuilt = _core.RtlNotBuilt  # a ValueError: an RTL engine's run-time module is not built
RtlNotBuilt.__module__ = __name__

ENGINES = ("float", "fixed", "rtl", "rtl-serial")
_CHANNELS = {4: ("c1", "c2", "c3", "c4"), 2: ("sin", "cos")}
_COLUMNS = ("t", "theta_ref", "c1", "c2", "c3", "c4", "sin", "cos", "temp")


def _column(name: str, x: Any) -> np.ndarray:
    """A float64, 1-D, C-contiguous array (the caller's own when it already is one: no copy)."""
    if isinstance(x, np.ndarray):
        if x.dtype != np.float64:
            raise TypeError(f"column '{name}': expected a float64 array, got dtype {x.dtype}")
    elif isinstance(x, (list, tuple)):
        x = np.asarray(x, dtype=np.float64)
    else:
        raise TypeError(f"column '{name}': expected a numpy float64 array, got {type(x).__name__}")
    if x.ndim != 1:
        raise ValueError(f"column '{name}': expected a 1-D array, got shape {x.shape}")
    return np.ascontiguousarray(x)


class Recording:
    """A sensor recording (docs/contracts.md, recording file): columns as numpy float64 arrays.

    Four channels c1..c4, or two (sin, cos); theta_ref (rad), t (s), temp (degC) optional.
    meta holds the `# key=value` lines (p = periodicity), comments the other `#` lines.
    """

    def __init__(
        self,
        *,
        theta_ref=None,
        t=None,
        temp=None,
        c1=None,
        c2=None,
        c3=None,
        c4=None,
        sin=None,
        cos=None,
        meta: Optional[dict[str, Any]] = None,
        comments: Optional[list[str]] = None,
    ):
        given = {
            k: v
            for k, v in {
                "t": t,
                "theta_ref": theta_ref,
                "c1": c1,
                "c2": c2,
                "c3": c3,
                "c4": c4,
                "sin": sin,
                "cos": cos,
                "temp": temp,
            }.items()
            if v is not None
        }
        four = [k for k in _CHANNELS[4] if k in given]
        two = [k for k in _CHANNELS[2] if k in given]
        if len(four) == 4 and not two:
            self.channels = 4
        elif len(two) == 2 and not four:
            self.channels = 2
        else:
            raise ValueError("Recording: give the four channels c1..c4 or the two sin, cos")
        self.columns: dict[str, np.ndarray] = {k: _column(k, v) for k, v in given.items()}
        lengths = {k: len(v) for k, v in self.columns.items()}
        if len(set(lengths.values())) != 1:
            raise ValueError(f"Recording: columns differ in length: {lengths}")
        self.meta: dict[str, str] = {str(k): str(v) for k, v in (meta or {}).items()}
        self.comments: list[str] = list(comments or [])

    @classmethod
    def _from_core(cls, d: dict) -> Recording:
        rec = cls.__new__(cls)
        rec.channels = d["channels"]
        rec.columns = dict(d["columns"])
        rec.meta = dict(d["meta"])
        rec.comments = list(d["comments"])
        return rec

    def _core(self) -> dict:
        return {
            "channels": self.channels,
            "columns": self.columns,
            "meta": self.meta,
            "comments": self.comments,
        }

    def __getattr__(self, name: str) -> np.ndarray:
        if name in _COLUMNS:
            cols = self.__dict__.get("columns", {})
            if name in cols:
                return cols[name]
            raise AttributeError(f"this recording has no column '{name}'")
        raise AttributeError(name)

    def __len__(self) -> int:
        return len(self.columns[_CHANNELS[self.channels][0]])

    def __repr__(self) -> str:
        return f"Recording({len(self)} samples, columns {list(self.columns)})"

    @property
    def channel_names(self):
        return _CHANNELS[self.channels]

    @property
    def periodicity(self) -> int:
        """The recording's `# p=` (1 when absent); ValueError when malformed."""
        return _core.recording_periodicity(self._core(), "recording")

    def write(self, path: os.PathLike | str) -> None:
        _core.write_recording(self._core(), os.fspath(path))

    def to_csv(self) -> str:
        return _core.format_recording(self._core())


def read_recording(path: os.PathLike | str) -> Recording:
    """Reads a recording CSV; ValueError "FILE:LINE: column 'NAME': ..." on any defect."""
    return Recording._from_core(_core.read_recording(os.fspath(path)))


class RegisterImage:
    """A register image: .words (uint64 array, address order), .header (the `// acore:` keys),
    .report (the `calibrate --json` object when made by calibrate), .write(path)."""

    def __init__(self, core: _core.RegImage, report: Optional[dict] = None):
        self._img = core
        self.report = report

    @property
    def words(self) -> np.ndarray:
        return self._img.words

    @property
    def text(self) -> str:
        """The image file's text ($readmemh with the header), as write() writes it."""
        return self._img.text

    @property
    def header(self) -> dict[str, str]:
        out: dict[str, str] = {}
        for line in self._img.text.splitlines():
            if line.startswith("// acore: ") and "=" in line:
                k, v = line[len("// acore: ") :].split("=", 1)
                out[k] = v
        return out

    @property
    def zero_offset(self) -> float:
        """The calibration's zero offset, rad (sensor angle - p theta_ref, electrical)."""
        return self._img.zero_offset

    @property
    def in_scale(self) -> float:
        return self._img.in_scale

    def write(self, path: os.PathLike | str) -> None:
        self._img.write(os.fspath(path))

    def __repr__(self) -> str:
        return f"RegisterImage({len(self.words)} words, crc32=0x{self._img.crc32:08x})"


def read_image(path: os.PathLike | str) -> RegisterImage:
    return RegisterImage(_core.read_image(os.fspath(path)))


def scenarios() -> list[str]:
    """The built-in scenario names (`anglecore simulate --list`)."""
    return list(_core.scenario_names())


def simulate(
    scenario_or_config: Any = "paper",
    samples: int = 4096,
    seed: int = 1,
    channels: Optional[int] = None,
) -> Recording:
    """A recording from a built-in scenario name, a scenario JSON file (path ending in .json) or a
    scenario dict (the fields of `simulate --dump-config`, effects included), as
    `anglecore simulate --scenario/--config ... --samples N --seed S [--channels C]`."""
    if isinstance(scenario_or_config, os.PathLike):
        scenario_or_config = os.fspath(scenario_or_config)
    if channels not in (None, 2, 4):
        raise ValueError(f"channels {channels}: not one of 2, 4")
    if int(samples) < 1:
        raise ValueError(f"samples {samples}: must be >= 1")
    return Recording._from_core(
        _core.simulate(scenario_or_config, int(samples), int(seed), channels or 0)
    )


def scenario_config(scenario_or_config: Any, channels: Optional[int] = None) -> dict:
    """The scenario as a dict (`simulate --dump-config`): a starting point for a custom one."""
    return _core.scenario_json(scenario_or_config, channels or 0)


def physics_scenarios() -> list[dict]:
    """The physics rig's scenarios (magnet, sensor, ADC chain; `diagnose-bench --physics`)."""
    return list(_core.physics_scenarios())


def simulate_physics(name: str, samples: int = 4096, seed: int = 1, index: int = 0) -> dict:
    """Case `index` of physics scenario `name` as diagnose-bench --physics draws it with `seed`:
    {"sim", "real", "holdout"} recordings of the physics rig, and the scenario's truth."""
    d = dict(_core.simulate_physics(name, int(samples), int(seed), int(index)))
    for k in ("sim", "real", "holdout"):
        d[k] = Recording._from_core(d[k])
    return d


def calibrate(recording: Recording, **options: Any) -> RegisterImage:
    """Fits and quantizes a register image, as `anglecore calibrate`: every option of the command
    by its name with '-' -> '_' (correction, degree, regions, xcenter, iterations, coef_frac,
    angle_w, in_w, in_scale, periodicity, fourier, fourier_iterations, fourier_guard,
    zero_offset ("auto" or degrees), zero_word, mult). The image's .report is the command's JSON."""
    _check_recording(recording)
    opts = dict(options)
    if "zero_offset" in opts and not isinstance(opts["zero_offset"], str):
        opts["zero_offset"] = repr(float(opts["zero_offset"]))
    call = ", ".join(f"{k}={v!r}" for k, v in options.items())
    img, report = _core.calibrate(
        recording._core(), opts, "recording", f"python anglecore.calibrate({call})"
    )
    return RegisterImage(img, report)


@dataclass
class Estimate:
    """estimate()'s result: per-sample arrays and the `estimate --json` object (.report).

    The drive outputs come from the tracking observer over `angle`, with estimate()'s observer
    settings, as the command's --out columns: velocity (velocity_rpm), turns, angle_comp
    (angle_comp_rad), lot. None when estimate() ran with track=False."""

    angle: np.ndarray  # rad, reference frame, [0, 2 pi)
    region: np.ndarray  # uint8
    flags: np.ndarray  # uint8: bit 0 ovf, 1 los, 2 dos
    error: Optional[np.ndarray]  # deg, angle - p theta_ref wrapped (None without theta_ref)
    uncorrected: Optional[np.ndarray]  # rad, the chain without correction (None when not asked)
    uncorrected_error: Optional[np.ndarray]
    report: dict
    velocity: Optional[np.ndarray] = None  # mechanical rpm (None without the recording's t)
    turns: Optional[np.ndarray] = None  # int64: signed electrical turns, 0 at the first sample
    angle_comp: Optional[np.ndarray] = None  # rad, [0, 2 pi): angle looked ahead by track_lead
    lot: Optional[np.ndarray] = None  # uint8: 1 where the observer lost tracking
    # int64: the CORDIC magnitude of each sample (the RTL's mag_o: the corrected vector length
    # times the CORDIC gain, 2^S_F a unit); None for the float engine and the fixed fast path
    # (uncorrected=False): ask with uncorrected=True.
    magnitude: Optional[np.ndarray] = None

    @property
    def error_deg(self) -> Optional[dict]:
        return self.report.get("error_deg")

    @property
    def uncorrected_error_deg(self) -> Optional[dict]:
        return self.report.get("uncorrected_error_deg")

    @property
    def flagged_samples(self) -> int:
        return self.report["flagged_samples"]

    @property
    def zero_offset(self) -> dict:
        return self.report["zero_offset"]

    @property
    def track(self) -> Optional[dict]:
        """The observer's settings and count of lost samples (the command's `track` object);
        None without the recording's t."""
        return self.report.get("track")

    @property
    def velocity_error_rpm(self) -> Optional[dict]:
        """Velocity against p theta_ref through the same observer: {rms, max_abs, mean}, rpm."""
        return self.report.get("velocity_error_rpm")


def _check_recording(recording: Any) -> None:
    if not isinstance(recording, Recording):
        raise TypeError(f"expected an anglecore.Recording, got {type(recording).__name__}")


def estimate(
    image: RegisterImage,
    recording: Recording,
    engine: str = "fixed",
    periodicity: Optional[int] = None,
    uncorrected: bool = True,
    fold: int = 1,
    trace: Optional[os.PathLike | str] = None,
    rtl_dir: Optional[os.PathLike | str] = None,
    track: bool = True,
    track_bandwidth: Optional[float] = None,
    track_lead: float = 0.0,
    track_lot: Optional[int] = None,
) -> Estimate:
    """Runs an engine over a recording, as `anglecore estimate --engine ENGINE [--fold N]`.

    Every engine runs through the command's own dispatch (run_engine): float (the double model on
    the image's dequantized coefficients), fixed (bit-accurate), rtl (the Verilated pipelined top,
    folded to `fold` clocks a sample), rtl-serial (the serial core). The RTL engines load the
    run-time modules of a CMake build: from rtl_dir when given, else $ACORE_RTL_DIR, else the
    build/rtl/ folder the set-up named; RtlNotBuilt (its message gives the command) when the module
    is not there. trace: an FST waveform of the RTL run.

    fixed with uncorrected=False takes the fast path: the bit-accurate batch straight on the
    recording's arrays (no copy; the GIL is released), the same angles bit for bit.

    The drive outputs (velocity, turns, angle_comp, lot; report's track and velocity_error_rpm)
    come from the tracking observer over the angles, as `estimate --out`: track_bandwidth (Hz at
    the recording's sample rate, from t: the nearest code; None: code 6), track_lead (samples
    angle_comp looks ahead, 1/16 steps), track_lot (the loss-of-tracking threshold, angle LSBs;
    None: 4096) are the command's --track-bandwidth, --track-lead, --track-lot. track=False skips
    the observer (those fields None, the report without them)."""
    if not isinstance(image, RegisterImage):
        raise TypeError(f"expected an anglecore.RegisterImage, got {type(image).__name__}")
    _check_recording(recording)
    p = int(periodicity) if periodicity else recording.periodicity
    theta = recording.columns.get("theta_ref")
    unc = unc_err = err = magnitude = None
    if engine == "fixed" and not uncorrected and fold == 1 and trace is None:
        arrays = [recording.columns[n] for n in recording.channel_names]
        angle, flags, region, err = _core.estimate_fixed_batch(
            image._img, recording.channels, arrays, theta, p
        )
    else:
        angle, unc, region, flags, magnitude = _core.estimate_series(
            image._img,
            recording._core(),
            engine,
            int(fold),
            "" if trace is None else os.fspath(trace),
            "" if rtl_dir is None else os.fspath(rtl_dir),
        )
        if not uncorrected:
            unc = None
        if theta is not None:
            err = _core.judged_error_deg(image._img, angle, theta, p)
    # A self-calibrated image does not know the reference's zero: the library judges its errors
    # about their mean, as the command reports them.
    if unc is not None and theta is not None:
        unc_err = _core.judged_error_deg(image._img, unc, theta, p)
    report = _core.estimate_report(
        image._img, engine, int(fold), len(recording), err, unc_err, int(np.count_nonzero(flags))
    )
    drive: dict[str, Any] = {}
    if track:
        has_ref = theta is not None or "t" in recording.columns
        velocity, turns, comp, lot, extra = _core.track(
            image._img,
            angle,
            recording.columns.get("t"),
            theta,
            p if has_ref else 1,
            float(track_bandwidth or 0.0),
            float(track_lead),
            -1 if track_lot is None else int(track_lot),
        )
        report.update(extra)
        drive = {"velocity": velocity, "turns": turns, "angle_comp": comp, "lot": lot}
    return Estimate(angle, region, flags, err, unc, unc_err, report, magnitude=magnitude, **drive)


def board_mag_agc(image: RegisterImage, magnitude: Any) -> tuple[np.ndarray, np.ndarray]:
    """The board's AS5047P MAG and DIAAGC.AGC (rtl/acore_board.v) of CORDIC magnitudes
    (Estimate.magnitude) at the image's widths: (mag uint16, agc uint8). MAG = the magnitude's upper
    14 bits (m >> (S_W - 13)); AGC = 128 + 32 (S_F + 20/32 - lg m) clamped to 0..255 (lg: the
    piecewise-linear base-2 logarithm), high for a weak field, low for a strong one."""
    if not isinstance(image, RegisterImage):
        raise TypeError(f"expected an anglecore.RegisterImage, got {type(image).__name__}")
    m = np.ascontiguousarray(np.asarray(magnitude, dtype=np.int64).reshape(-1))
    return _core.board_mag_agc(image._img, m)


def harmonics(spec: Any, grid: int = 0, attribute: bool = False) -> dict:
    """Kuntz's predicted vs exact angle-error harmonics (`anglecore harmonics --json`) of a
    signal spec: a dict {p, A0, B0, Ap, Bp, delta_p, terms: [...]} or a JSON file path.
    attribute=True adds "attribution" (`harmonics --attribute`): for each significant order of the
    exact spectrum, the signal imperfections that can cause it, best first."""
    if isinstance(spec, os.PathLike):
        spec = os.fspath(spec)
    if attribute:
        return _core.harmonics_attributed(spec, int(grid))
    return _core.harmonics(spec, int(grid))


def diagnose(
    sim: Recording,
    real: Recording,
    holdout: Optional[Recording] = None,
    order: Optional[int] = None,
) -> dict:
    """The sim-to-real gap diagnosis (`anglecore diagnose --json`) as a dict."""
    _check_recording(sim)
    _check_recording(real)
    if holdout is not None:
        _check_recording(holdout)
    return _core.diagnose(
        sim._core(), real._core(), None if holdout is None else holdout._core(), int(order or 0)
    )
