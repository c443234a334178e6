# SPDX-License-Identifier: MIT
"""The cocotb benches' library: a registry line's build, its register image, the stimulus, the
scoreboard (the Python package's bit-accurate model, `anglecore.estimate(..., engine="fixed")`, on
the same input codes), and the drivers a bench is made of (valid/ready streams with random gaps and
stalls, the top's host port, an APB master, an AS5047P SPI master, a quadrature decoder).

Two sides use it. The pytest side (tb/cocotb/test_benches.py) reads the registry line
(rtl/configs.txt through scripts/registry.py: the module, its parameters, the elaborated constants),
calibrates the image, builds the simulator and hands the bench a JSON settings file
($ACORE_COCOTB_SETTINGS). The bench side (tb/cocotb/bench_*.py, inside the simulator) reads that
file with `settings()` and never needs Verilator or the registry.
"""

from __future__ import annotations

import json
import math
import os
import random
import sys
import zlib
from dataclasses import dataclass, field

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# --- pytest side: the registry line, its image, the build ------------------------------------

# The image header's configuration keys whose parameter name is not the key in capitals.
HEADER_PARAM = {
    "iterations": "K",
    "acc_guard": "ACC_G",
    "acc_int": "ACC_I",
    "cordic_guard": "CORDIC_G",
    "scale_guard": "SCALE_G",
}


def _scripts():
    path = os.path.join(ROOT, "scripts")
    if path not in sys.path:
        sys.path.insert(0, path)


def registry_line(name: str) -> dict:
    """The registry line `name` of rtl/configs.txt: its module, parameters and the module's
    elaborated constants (WORDS, LATENCY, CYCLES, widths)."""
    _scripts()
    import registry

    line = registry.get(ROOT, name)
    return {
        "name": line.name,
        "module": line.module,
        "params": dict(line.params),
        "consts": registry.rtl_constants(ROOT, line.module, line.params),
    }


def check_image(img, line: dict) -> None:
    """Raises ValueError when the image's configuration (its header) is not the build's."""
    c = line["consts"]
    bad = []
    for key, value in img.header.items():
        p = HEADER_PARAM.get(key, key.upper())
        if key == "correction":
            want = c.get(f"ACORE_CORR_{value.upper()}")
            if want is not None and want != c.get("CORRECTION"):
                bad.append(f"correction={value} (build: CORRECTION={c.get('CORRECTION')})")
        elif p in c and value.lstrip("-").isdigit() and int(value) != c[p]:
            bad.append(f"{key}={value} (build: {p}={c[p]})")
    if bad:
        raise ValueError(
            f"the register image does not fit registry line {line['name']}: {', '.join(bad)}"
        )


def rtl_sources() -> list[str]:
    _scripts()
    import registry

    return [os.path.join(ROOT, "rtl", f) for f in registry.rtl_files(ROOT)]


# --- bench side: the settings ----------------------------------------------------------------


@dataclass
class Settings:
    """What the pytest side hands the bench (JSON, $ACORE_COCOTB_SETTINGS)."""

    line: dict  # registry_line()
    image: str  # the register image file
    samples: int = 200
    seed: int = 1
    scenario: str = "paper"
    gap: float = 0.3  # probability of an idle clock before each input sample
    stall: float = 0.3  # probability of out_ready_i low on a clock
    corrupt_word: int = -1  # >= 0: the bench writes this word wrong (a planted bug)
    extra: dict = field(default_factory=dict)

    def write(self, path: str) -> None:
        with open(path, "w") as f:
            json.dump(self.__dict__, f, indent=1)

    @property
    def consts(self) -> dict:
        return self.line["consts"]


def settings() -> Settings:
    path = os.environ.get("ACORE_COCOTB_SETTINGS")
    if not path:
        raise RuntimeError("ACORE_COCOTB_SETTINGS is not set (tb/cocotb/test_benches.py sets it)")
    with open(path) as f:
        return Settings(**json.load(f))


# --- stimulus and the scoreboard -------------------------------------------------------------


def stimulus(img, s: Settings) -> np.ndarray:
    """Input codes, shape (samples, 4), int64: the scenario's recording converted as an ADC would
    (the image's in_scale, IN_W-bit saturation), its last eighth replaced by random full-scale
    codes (saturating stages, the flags). Two-channel recordings leave c3 = c4 = 0."""
    import anglecore as ac

    in_w = s.consts["IN_W"]
    lo, hi = -(1 << (in_w - 1)), (1 << (in_w - 1)) - 1
    rec = ac.simulate(s.scenario, samples=s.samples, seed=s.seed)
    codes = np.zeros((s.samples, 4), dtype=np.int64)
    for i, n in enumerate(rec.channel_names):
        codes[:, i] = np.clip(np.rint(rec.columns[n] * img.in_scale), lo, hi)
    rng = np.random.default_rng(s.seed)
    k = s.samples // 8
    codes[s.samples - k :, : rec.channels] = rng.integers(lo, hi + 1, (k, rec.channels))
    return codes


@dataclass
class Expected:
    angle: np.ndarray  # ANGLE_W-bit codes
    region: np.ndarray
    flags: np.ndarray  # bit 0 ovf, 1 los, 2 dos


def reference(img, codes: np.ndarray, s: Settings) -> Expected:
    """The package's bit-accurate model on exactly these codes: each code c is handed to it as
    c / in_scale, which its input conversion turns back into c."""
    import anglecore as ac

    channels = 4 if codes[:, 2:].any() else 2
    names = ("c1", "c2", "c3", "c4") if channels == 4 else ("sin", "cos")
    cols = {n: codes[:, i] / img.in_scale for i, n in enumerate(names)}
    res = ac.estimate(img, ac.Recording(**cols), engine="fixed", uncorrected=False)
    # The angle comes back in rad in the reference frame: without a ZERO word the package removes
    # the image's zero offset in software, which the hardware does not.
    w = s.consts["ANGLE_W"]
    sw = 0.0 if s.consts.get("ZERO", 0) else img.zero_offset
    turn = 2 * math.pi
    angle = np.rint(np.mod(res.angle + sw, turn) * (1 << w) / turn).astype(np.int64) % (1 << w)
    return Expected(angle, res.region.astype(np.int64), res.flags.astype(np.int64))


def board_mag_agc(img, codes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The board's SPI MAG and DIAAGC.AGC after each of these codes, from the package: the
    bit-accurate model's CORDIC magnitude (Estimate.magnitude, the per-sample path) through
    anglecore.board_mag_agc."""
    import anglecore as ac

    channels = 4 if codes[:, 2:].any() else 2
    names = ("c1", "c2", "c3", "c4") if channels == 4 else ("sin", "cos")
    cols = {n: codes[:, i] / img.in_scale for i, n in enumerate(names)}
    res = ac.estimate(img, ac.Recording(**cols), engine="fixed", track=False)
    return ac.board_mag_agc(img, res.magnitude)


def status_window(img) -> tuple[int, int]:
    """mag_lo, mag_hi as the model flags them (its default window: 0.5 and 1.5 times the nominal
    corrected vector length 2^S_F times the CORDIC gain of K iterations)."""
    k, s_f = int(img.header["iterations"]), int(img.header["s_f"])
    gain = math.prod(math.sqrt(1.0 + 2.0 ** (-2 * i)) for i in range(k))
    nominal = gain * 2.0**s_f
    return math.floor(0.5 * nominal + 0.5), math.floor(1.5 * nominal + 0.5)


def image_words(img, s: Settings) -> list[int]:
    """The words the bench writes: the image's, or with the planted bug one word changed."""
    words = [int(w) for w in img.words]
    if s.corrupt_word >= 0:
        words[s.corrupt_word] ^= 1 << (s.consts["REG_W"] - 2)
    return words


def crc32_words(words) -> int:
    """CRC-32 of the image (zlib's, over the words as 32-bit little-endian integers)."""
    return zlib.crc32(b"".join(int(w).to_bytes(4, "little") for w in words))


def compare(got: list, exp: Expected, fields=("angle", "region", "flags")) -> list[str]:
    """The mismatches of the outputs (dicts with the fields) against the model, one line each."""
    out = []
    if len(got) != len(exp.angle):
        out.append(f"{len(got)} outputs for {len(exp.angle)} samples")
    for i, g in enumerate(got[: len(exp.angle)]):
        diff = [
            f"{f} {g[f]} != {int(getattr(exp, f)[i])}" for f in fields if g[f] != getattr(exp, f)[i]
        ]
        if diff:
            out.append(f"sample {i}: " + ", ".join(diff))
    return out


# --- drivers (inside the simulator) ----------------------------------------------------------


def _int(sig) -> int:
    return int(sig.value)


async def reset(dut, clk, cycles: int = 4) -> None:
    from cocotb.triggers import RisingEdge

    dut.rst_i.value = 1
    for _ in range(cycles):
        await RisingEdge(clk)
    dut.rst_i.value = 0
    await RisingEdge(clk)


async def start_top(dut, img) -> None:
    """A bare top (acore_top, acore_serial_top) started: a 100 MHz clock on clk_i, the model's
    status window on mag_lo_i/mag_hi_i, the host port and both streams idle, a reset."""
    from cocotb.clock import Clock

    Clock(dut.clk_i, 10, unit="ns").start()
    dut.mag_lo_i.value, dut.mag_hi_i.value = status_window(img)
    dut.reg_we_i.value = 0
    dut.in_valid_i.value = 0
    dut.out_ready_i.value = 0
    await reset(dut, dut.clk_i)


class StreamSource:
    """Offers the codes on in_valid_i/c1_i..c4_i; before each sample, with probability `gap`, one
    or more idle clocks (valid low). A sample is held until the clock edge with in_ready_o high."""

    def __init__(self, dut, clk, codes: np.ndarray, in_w: int, gap: float, rng: random.Random):
        self.dut, self.clk, self.codes, self.gap, self.rng = dut, clk, codes, gap, rng
        self.mask = (1 << in_w) - 1
        self.sent = 0
        self.idle_clocks = 0  # clocks with valid low while samples were left
        self.refused_clocks = 0  # clocks with valid high and in_ready_o low

    async def run(self) -> None:
        from cocotb.triggers import RisingEdge

        d, n, valid = self.dut, len(self.codes), False
        d.in_valid_i.value = 0
        while True:
            await RisingEdge(self.clk)
            if valid:
                if _int(d.in_ready_o):
                    self.sent += 1
                    valid = False
                else:
                    self.refused_clocks += 1
            if self.sent == n:
                d.in_valid_i.value = 0
                return
            if not valid and self.rng.random() >= self.gap:
                c = self.codes[self.sent]
                d.c1_i.value = int(c[0]) & self.mask
                d.c2_i.value = int(c[1]) & self.mask
                d.c3_i.value = int(c[2]) & self.mask
                d.c4_i.value = int(c[3]) & self.mask
                valid = True
            elif not valid:
                self.idle_clocks += 1
            d.in_valid_i.value = int(valid)


class StreamSink:
    """Takes outputs on out_valid_o; out_ready_i is low on a clock with probability `stall`
    (never when the port has no out_ready_i). Records angle, region, flags (and the shell's tag)."""

    def __init__(self, dut, clk, stall: float, rng: random.Random):
        self.dut, self.clk, self.stall, self.rng = dut, clk, stall, rng
        self.has_ready = hasattr(dut, "out_ready_i")
        self.got: list[dict] = []
        self.held_clocks = 0  # clocks with out_valid_o high and out_ready_i low

    def _capture(self) -> dict:
        d = self.dut
        g = {"angle": _int(d.angle_o)}
        g["flags"] = (
            (_int(d.ovf_o) if hasattr(d, "ovf_o") else 0) | _int(d.los_o) << 1 | _int(d.dos_o) << 2
        )
        if hasattr(d, "region_o"):
            g["region"] = _int(d.region_o)
        if hasattr(d, "out_tag_o"):
            g["tag"] = _int(d.out_tag_o)
        return g

    async def run(self) -> None:
        """Runs until cancelled (stream() stops it once the outputs have drained)."""
        from cocotb.triggers import RisingEdge

        d, ready = self.dut, not self.has_ready or self.rng.random() >= self.stall
        if self.has_ready:
            d.out_ready_i.value = int(ready)
        while True:
            await RisingEdge(self.clk)
            if _int(d.out_valid_o):
                if ready:
                    self.got.append(self._capture())
                else:
                    self.held_clocks += 1
            if self.has_ready:
                ready = self.rng.random() >= self.stall
                d.out_ready_i.value = int(ready)


async def stream(dut, clk, codes, s: Settings, timeout_clocks: int, drain_clocks: int):
    """Runs the source until the core has taken every sample (AssertionError after timeout_clocks),
    then lets the outputs drain: until as many have come out as went in, or drain_clocks have
    passed, then 16 clocks more (an output too many is caught too). Returns (sink, source); the
    scoreboard (check_stream) judges what came out."""
    import cocotb
    from cocotb.triggers import ClockCycles, First, RisingEdge

    rng = random.Random(s.seed)
    src = StreamSource(dut, clk, codes, s.consts["IN_W"], s.gap, rng)
    sink = StreamSink(dut, clk, s.stall, rng)
    sent = cocotb.start_soon(src.run())
    taking = cocotb.start_soon(sink.run())
    await First(sent, ClockCycles(clk, timeout_clocks))
    assert sent.done(), (
        f"timeout: the core took {src.sent} of {len(codes)} samples in {timeout_clocks} clocks"
    )
    for _ in range(drain_clocks):
        if len(sink.got) >= len(codes):
            break
        await RisingEdge(clk)
    await ClockCycles(clk, 16)
    taking.cancel()
    if sink.has_ready:
        dut.out_ready_i.value = 1
    return sink, src


def check_stream(sink, src, exp: Expected, s: Settings, fields) -> None:
    """The scoreboard's verdict, and that the stalls and gaps asked for happened."""
    bad = compare(sink.got, exp, fields)
    assert not bad, f"{len(bad)} mismatches against anglecore (fixed):\n  " + "\n  ".join(bad[:20])
    if s.gap > 0:
        assert src.idle_clocks > 0, "no input gap was made"
    if s.stall > 0 and sink.has_ready:
        assert sink.held_clocks > 0, "no output was held by a stall"


async def write_host_port(dut, clk, words: list[int]) -> None:
    """Writes the image through the top's raw host port (a write taken at an edge lands at the
    next), then reads every word back (reg_rdata_o: the word at reg_addr_i two clocks before)."""
    from cocotb.triggers import RisingEdge

    for a, w in enumerate(words):
        dut.reg_addr_i.value = a
        dut.reg_wdata_i.value = w
        dut.reg_we_i.value = 1
        await RisingEdge(clk)
    dut.reg_we_i.value = 0
    for a, w in enumerate(words):
        dut.reg_addr_i.value = a
        for _ in range(3):
            await RisingEdge(clk)
        got = _int(dut.reg_rdata_o)
        assert got == w, f"host port: word {a} reads {got:#x}, wrote {w:#x}"


# --- APB --------------------------------------------------------------------------------------


class Regs:
    """Register offsets and fields by name from a block's description (rtl/*_regs.txt through
    scripts/gen_apb_regs.py, the generator of the RTL's register blocks)."""

    def __init__(self, *rels: str):
        _scripts()
        import gen_apb_regs

        self.regs = {}
        for rel in rels:
            for r in gen_apb_regs.parse(ROOT, rel).regs:
                self.regs[r.name] = r

    def addr(self, name: str) -> int:
        return self.regs[name].offset

    def field(self, reg: str, name: str) -> tuple[int, int]:
        """(lsb, width) of a field whose msb is a number."""
        f = next(f for f in self.regs[reg].fields if f.name == name)
        return f.lsb, f.msb + 1 - f.lsb

    def bit(self, reg: str, name: str) -> int:
        lsb, _ = self.field(reg, name)
        return 1 << lsb

    def get(self, reg: str, name: str, value: int) -> int:
        lsb, w = self.field(reg, name)
        return value >> lsb & ((1 << w) - 1)


def apb_master(dut, clk):
    """cocotbext-apb's master on the shell's pins (psel_i .. pslverr_o)."""
    from cocotbext.apb import ApbBus, ApbMaster

    sig = {"psel": "psel_i", "penable": "penable_i", "pwrite": "pwrite_i", "paddr": "paddr_i"}
    sig.update({"pwdata": "pwdata_i", "prdata": "prdata_o", "pready": "pready_o"})
    bus = ApbBus(dut, signals=sig, optional_signals={"pstrb": "pstrb_i", "pslverr": "pslverr_o"})
    m = ApbMaster(bus, clk)
    m.return_int = True
    return m


async def commit_image(apb, regs: Regs, words: list[int], crc: int, window) -> int:
    """Loads the image as the shell's guide does (docs/register-shell-guide.md "Driver"): the
    shadow words, CRC_EXPECTED, a checked commit, BUSY polled; the words read back; the status
    window written. Returns the active bank (the tag of outputs computed with the image)."""
    coef = regs.addr("COEF")
    for a, w in enumerate(words):
        await apb.write(coef + 4 * a, w)
    for a, w in enumerate(words):
        got = await apb.read(coef + 4 * a)
        assert got == w, f"APB: shadow word {a} reads {got:#x}, wrote {w:#x}"
    await apb.write(regs.addr("CRC_EXPECTED"), crc)
    ctrl = sum(regs.bit("CTRL", f) for f in ("SCRUB", "CRC_CHECK", "COMMIT"))
    await apb.write(regs.addr("CTRL"), ctrl)
    for _ in range(1000):
        st = await apb.read(regs.addr("STATUS"))
        if not regs.get("STATUS", "BUSY", st):
            break
    else:
        raise AssertionError("APB: STATUS.BUSY did not fall after a commit")
    assert regs.get("STATUS", "DONE", st), f"APB: commit ended without DONE (STATUS {st:#x})"
    assert not regs.get("STATUS", "CRC_SHADOW", st), (
        f"APB: commit refused: the shadow's CRC is not CRC_EXPECTED {crc:#010x} (STATUS {st:#x})"
    )
    await apb.write(regs.addr("STATUS"), regs.bit("STATUS", "DONE"))
    await apb.write(regs.addr("MAG_LO"), window[0])
    await apb.write(regs.addr("MAG_HI"), window[1])
    return regs.get("STATUS", "BANK", st)


async def check_config(apb, regs: Regs, s: Settings, img) -> None:
    """The shell's configuration registers against the registry line's elaborated parameters, and
    its window size against the image's word count."""
    c = s.consts
    for reg in ("CONFIG0", "CONFIG1", "CONFIG2", "CONFIG3"):
        v = await apb.read(regs.addr(reg))
        for f in regs.regs[reg].fields:
            if f.name in c:
                got = regs.get(reg, f.name, v)
                assert got == c[f.name], (
                    f"APB: {reg}.{f.name} reads {got}, the build has {c[f.name]}"
                )
    words = regs.get("CONFIG1", "WORDS", await apb.read(regs.addr("CONFIG1")))
    assert words == len(img.words), f"APB: CONFIG1.WORDS {words}, the image has {len(img.words)}"


# --- the board's interfaces -------------------------------------------------------------------


def parity_even(word: int) -> int:
    """The bit that makes the 16-bit frame's parity even (bit 15 of an AS5047P frame)."""
    return bin(word & 0x7FFF).count("1") & 1


def as5047_command(addr: int, read: bool = True) -> int:
    w = (int(read) << 14) | (addr & 0x3FFF)
    return w | parity_even(w) << 15


class As5047Master:
    """An SPI master framing as an AS5047P's datasheet (SPI mode 1: MOSI changes on SCLK's rising
    edge, MISO is sampled on its falling edge; 16 bits MSB first; CSn low for the frame; a read's
    answer comes in the next frame, {even parity, EF, 14 data bits}). Two habits of drive firmware:
    `read()` sends the command, then a NOP frame (0x0000) that collects its answer; `stream()`
    sends the same read command every frame and takes each frame's answer as the previous one's."""

    def __init__(self, dut, clk, half_period: int = 4):
        self.dut, self.clk, self.half = dut, clk, half_period
        dut.csn_i.value = 1
        dut.sclk_i.value = 0
        dut.mosi_i.value = 0

    async def frame(self, word: int) -> int:
        from cocotb.triggers import ClockCycles

        d = self.dut
        d.csn_i.value = 0
        await ClockCycles(self.clk, 2 * self.half)  # CSn low to the first edge (t_L)
        got = 0
        for i in range(15, -1, -1):
            d.sclk_i.value = 1
            d.mosi_i.value = word >> i & 1
            await ClockCycles(self.clk, self.half)
            got = got << 1 | _int(d.miso_o)  # sampled at the falling edge
            d.sclk_i.value = 0
            await ClockCycles(self.clk, self.half)
        await ClockCycles(self.clk, self.half)
        d.csn_i.value = 1
        await ClockCycles(self.clk, 2 * self.half)  # CSn high time
        return got

    @staticmethod
    def data(answer: int) -> int:
        """The answer's 14 data bits; AssertionError on odd parity or the error flag."""
        assert parity_even(answer) == answer >> 15, f"SPI: answer {answer:#06x} has odd parity"
        assert not answer >> 14 & 1, f"SPI: answer {answer:#06x} has EF set"
        return answer & 0x3FFF

    async def read(self, addr: int) -> int:
        await self.frame(as5047_command(addr))
        return self.data(await self.frame(0x0000))


class QuadratureDecoder:
    """A x4 quadrature decoder on A, B (Gray code 00 10 11 01 forward), watching every clock: the
    count, and at each clock with Z high the count then. A clock where A and B both change is an
    error (a lost edge)."""

    def __init__(self, dut, clk, count: int = 0):
        self.dut, self.clk = dut, clk
        self.count = count
        self.z_counts: list[int] = []
        self.errors = 0
        self.edges = 0

    async def run(self) -> None:
        from cocotb.triggers import RisingEdge

        step = {(0, 0): 0, (1, 0): 1, (1, 1): 2, (0, 1): 3}
        prev = (_int(self.dut.a_o), _int(self.dut.b_o))
        while True:
            await RisingEdge(self.clk)
            ab = (_int(self.dut.a_o), _int(self.dut.b_o))
            if ab != prev:
                delta = (step[ab] - step[prev]) % 4
                if delta == 1:
                    self.count += 1
                elif delta == 3:
                    self.count -= 1
                else:
                    self.errors += 1
                self.edges += 1
                prev = ab
            if _int(self.dut.z_o):
                self.z_counts.append(self.count)


def spi_angle(angle: int, angle_w: int) -> int:
    """The 14 bits an AS5047P frame carries of an ANGLE_W-bit angle: its upper 14."""
    return angle >> (angle_w - 14) if angle_w >= 14 else angle << (14 - angle_w)


def abz_counts(angle: int, angle_w: int, n: int, hys: int) -> set[int]:
    """The counts a caught-up ABZ output may rest at for this angle (rtl/acore_abz.v: the count
    holds on any count the window angle - HYS .. angle + HYS touches, else lands on floor(angle
    4N / 2^ANGLE_W))."""
    t = 1 << angle_w
    return {((a % t) * 4 * n // t) for a in range(angle - hys, angle + hys + 1)}
