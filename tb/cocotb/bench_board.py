# SPDX-License-Identifier: MIT
"""The bench of the board top acore_board: the register image through the APB bus (as the shell's
bench), the ABZ index moved through the bus, the scenario's codes in with random input gaps (the
board's estimator output is never held: the tracking observer takes every sample). Checked:
- every estimator output on angle_o/los_o/dos_o against the Python package's bit-accurate model;
- an AS5047P SPI master reading ANGLEUNC as SimpleFOC's driver does (the command, then a NOP frame
  for the answer) while samples stream: each answer an output of the model, in order;
- after the stream: ANGLEUNC the model's last angle, DIAAGC's flags the model's last ones, ANGLECOM
  read as ODrive's driver does (the read command every frame, each answer the previous frame's)
  the observer's compensated angle on its pins, TRK_POSITION its tracked angle;
- a quadrature decoder on A/B from reset: no step changing A and B together, Z only at the index
  count, and caught up at the count of the compensated angle;
- MAG and DIAAGC.AGC over SPI the package's (anglecore.board_mag_agc of the model's magnitude)
  after the stream, then after a few of the scenario's codes at full and at half amplitude: the
  weaker field reads a lower MAG and a higher AGC, as the AS5047P's."""

import acore_cocotb as acb
import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles

ANGLEUNC, ANGLECOM, DIAAGC, MAG = 0x3FFE, 0x3FFF, 0x3FFC, 0x3FFD
ABZ_INDEX = 1234  # Z at this count


async def spi_during_stream(spi, exp_angles, angle_w, stop, log):
    """SimpleFOC-style reads of ANGLEUNC until `stop` is set; each answer must be the angle of an
    output of the model at or after the previous answer's (or the reset value 0 before any)."""
    want = [acb.spi_angle(int(a), angle_w) for a in exp_angles]
    at, reads = -1, 0
    while not stop["done"]:
        v = await spi.read(ANGLEUNC)
        reads += 1
        nxt = next((k for k in range(max(at, 0), len(want)) if want[k] == v), None)
        assert nxt is not None or (at < 0 and v == 0), (
            f"SPI ANGLEUNC {v:#06x}: no output of the model at or after sample {at} carries it"
        )
        if nxt is not None:
            at = nxt
    log.info("SPI: %d ANGLEUNC reads during the stream, the last at sample %d", reads, at)
    stop["reads"] = reads


@cocotb.test()
async def board_against_model(dut):
    import anglecore as ac

    s = acb.settings()
    img = ac.read_image(s.image)
    codes = acb.stimulus(img, s)
    exp = acb.reference(img, codes, s)
    flags = exp.flags.copy()
    exp.flags = exp.flags & 6  # the board's pins carry los and dos (ovf only through DIAAGC)
    Clock(dut.clk_i, 10, unit="ns").start()
    dut.in_valid_i.value = 0
    spi = acb.As5047Master(dut, dut.clk_i)
    apb = acb.apb_master(dut, dut.clk_i)
    await acb.reset(dut, dut.clk_i)
    regs = acb.Regs("rtl/acore_apb_regs.txt", "rtl/acore_board_regs.txt")
    await acb.check_config(apb, regs, s, img)
    words = acb.image_words(img, s)
    await acb.commit_image(apb, regs, words, acb.crc32_words(img.words), acb.status_window(img))
    # ABZ at its reset resolution (the description's), counting from 0 since the reset, as a
    # decoder reset with the board does; the index moved through the bus.
    abz_n = int(next(f.reset for f in regs.regs["ABZ_N"].fields if f.name == "N"))
    abz_hys = int(next(f.reset for f in regs.regs["ABZ_HYS"].fields if f.name == "WIDTH"))
    await apb.write(regs.addr("ABZ_INDEX"), ABZ_INDEX)
    assert await apb.read(regs.addr("ABZ_INDEX")) == ABZ_INDEX
    dec = acb.QuadratureDecoder(dut, dut.clk_i)
    cocotb.start_soon(dec.run())

    c, w = s.consts, s.consts["ANGLE_W"]
    stop = {"done": False}
    reading = cocotb.start_soon(spi_during_stream(spi, exp.angle, w, stop, dut._log))
    per = c["CYCLES"] * 4 + 8
    drain = 4 * (c["LATENCY"] + c["CYCLES"]) + 1200
    sink, src = await acb.stream(dut, dut.clk_i, codes, s, per * len(codes), drain)
    stop["done"] = True
    await reading
    acb.check_stream(sink, src, exp, s, ("angle", "flags"))
    assert stop["reads"] > 1, "fewer than two SPI reads during the stream"

    # After the stream: the registers the SPI port reads hold the last output.
    await ClockCycles(dut.clk_i, 4 * abz_n + 64)  # ABZ catches up: at most 2N edges, one a clock
    last = int(exp.angle[-1])
    assert await spi.read(ANGLEUNC) == acb.spi_angle(last, w)
    last_flags = int(flags[-1])
    diag = await spi.read(DIAAGC)
    got = {
        "MAGL": diag >> 11 & 1,
        "MAGH": diag >> 10 & 1,
        "COF": diag >> 9 & 1,
        "LF": diag >> 8 & 1,
    }
    want = {
        "MAGL": last_flags >> 1 & 1,
        "MAGH": last_flags >> 2 & 1,
        "COF": last_flags & 1,
        "LF": 1 - int(dut.trk_lot_o.value),
    }
    assert got == want, f"SPI DIAAGC {diag:#06x}: {got}, expected {want}"
    want_mag, want_agc = acb.board_mag_agc(img, codes)
    got_mag = await spi.read(MAG)
    assert (got_mag, diag & 0xFF) == (int(want_mag[-1]), int(want_agc[-1])), (
        f"SPI MAG {got_mag}, AGC {diag & 0xFF}; the model's {want_mag[-1]}, {want_agc[-1]}"
    )
    # ODrive's habit: the read command every frame; each answer is the previous frame's.
    comp = int(dut.trk_angle_comp_o.value)
    answers = [await spi.frame(acb.as5047_command(ANGLECOM)) for _ in range(3)]
    for a in answers[1:]:
        assert spi.data(a) == acb.spi_angle(comp, w), (
            f"SPI ANGLECOM {spi.data(a):#06x}, the observer's compensated angle {comp:#06x}"
        )
    pos = await apb.read(regs.addr("TRK_POSITION"))
    tracked = int(dut.trk_angle_o.value)
    assert regs.get("TRK_POSITION", "ANGLE", pos) == tracked >> (w - 16)

    # The quadrature decoder: caught up with the compensated angle, Z only at the index.
    assert dec.errors == 0, f"ABZ: {dec.errors} steps changed A and B together"
    assert dec.edges > 0, "ABZ: no edge"
    count = dec.count % (4 * abz_n)
    allowed = acb.abz_counts(comp, w, abz_n, abz_hys)
    assert count in allowed, f"ABZ count {count}, the compensated angle {comp} gives {allowed}"
    zs = {z % (4 * abz_n) for z in dec.z_counts}
    assert zs <= {ABZ_INDEX}, f"ABZ: Z high at counts {sorted(zs)}, the index is {ABZ_INDEX}"

    # A weaker field: a few of the scenario's codes (its calibrated amplitude), then the same at
    # half amplitude; MAG and AGC after each are the package's, MAG falls and AGC rises.
    field = []
    for scale in (1, 2):
        few = codes[:8] // scale
        await acb.stream(dut, dut.clk_i, few, s, per * len(few), drain)
        await ClockCycles(dut.clk_i, 64)
        m_want, a_want = acb.board_mag_agc(img, few)
        got_mag = await spi.read(MAG)
        got_agc = await spi.read(DIAAGC) & 0xFF
        assert (got_mag, got_agc) == (int(m_want[-1]), int(a_want[-1])), (
            f"amplitude 1/{scale}: SPI MAG {got_mag}, AGC {got_agc}; the model's "
            f"{m_want[-1]}, {a_want[-1]}"
        )
        field.append((got_mag, got_agc))
    (mag_full, agc_full), (mag_half, agc_half) = field
    assert mag_half < mag_full and agc_half > agc_full, f"MAG, AGC at full and half field: {field}"
    dut._log.info("MAG/AGC: full field %d/%d, half field %d/%d", *field[0], *field[1])

    dut._log.info(
        "%d samples bit-exact to anglecore (fixed) on the board: %d idle input clocks; ABZ %d "
        "edges, count %d, Z seen %d clocks; SPI reads matched",
        len(codes),
        src.idle_clocks,
        dec.edges,
        count,
        len(dec.z_counts),
    )
