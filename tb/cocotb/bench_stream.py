# SPDX-License-Identifier: MIT
"""The bench of the bare tops, acore_top (any FOLD) and acore_serial_top: the register image through
the raw host port (read back), then the scenario's codes in with random input gaps and output
stalls, every output against the Python package's bit-accurate model on the same codes."""

import acore_cocotb as acb
import cocotb


@cocotb.test()
async def top_against_model(dut):
    import anglecore as ac

    s = acb.settings()
    img = ac.read_image(s.image)
    codes = acb.stimulus(img, s)
    exp = acb.reference(img, codes, s)
    await acb.start_top(dut, img)
    await acb.write_host_port(dut, dut.clk_i, acb.image_words(img, s))
    c = s.consts
    # Every sample at its full-rate period, stretched by the gaps and stalls, plus the latency.
    per = c["CYCLES"] * 4 + 8
    drain = 4 * (c["LATENCY"] + c["CYCLES"]) + 1200  # the folded top's output FIFO: 256 words
    sink, src = await acb.stream(dut, dut.clk_i, codes, s, per * len(codes), drain)
    acb.check_stream(sink, src, exp, s, ("angle", "region", "flags"))
    dut._log.info(
        "%d samples bit-exact to anglecore (fixed): %d idle input clocks, %d held outputs, "
        "%d refused offers",
        len(codes),
        src.idle_clocks,
        sink.held_clocks,
        src.refused_clocks,
    )
