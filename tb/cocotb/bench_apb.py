# SPDX-License-Identifier: MIT
"""The bench of the APB register shell acore_apb: its configuration registers against the registry
line, the register image written through the bus into the shadow bank (read back, committed under
the CRC check, the status window set), then the scenario's codes in with random input gaps and
output stalls; every output against the Python package's bit-accurate model on the same codes and
tagged with the committed bank."""

import acore_cocotb as acb
import cocotb
from cocotb.clock import Clock


@cocotb.test()
async def shell_against_model(dut):
    import anglecore as ac

    s = acb.settings()
    img = ac.read_image(s.image)
    codes = acb.stimulus(img, s)
    exp = acb.reference(img, codes, s)
    Clock(dut.clk_i, 10, unit="ns").start()
    dut.in_valid_i.value = 0
    dut.out_ready_i.value = 0
    apb = acb.apb_master(dut, dut.clk_i)
    await acb.reset(dut, dut.clk_i)
    regs = acb.Regs("rtl/acore_apb_regs.txt")
    await acb.check_config(apb, regs, s, img)
    words = acb.image_words(img, s)
    bank = await acb.commit_image(
        apb, regs, words, acb.crc32_words(img.words), acb.status_window(img)
    )
    c = s.consts
    per = c["CYCLES"] * 4 + 8
    drain = 4 * (c["LATENCY"] + c["CYCLES"]) + 1200
    sink, src = await acb.stream(dut, dut.clk_i, codes, s, per * len(codes), drain)
    acb.check_stream(sink, src, exp, s, ("angle", "region", "flags"))
    tags = {g["tag"] for g in sink.got}
    assert tags == {bank}, f"out_tag_o {sorted(tags)}, the committed bank is {bank}"
    # The scrubber has read the active words back since the commit: no change found.
    passes = await apb.read(regs.addr("SCRUB_PASSES"))
    assert regs.get("SCRUB_PASSES", "PASSES", passes) > 0, "no scrubber pass was judged"
    st = await apb.read(regs.addr("STATUS"))
    assert not regs.get("STATUS", "CRC_ACTIVE", st), f"STATUS.CRC_ACTIVE set ({st:#x})"
    dut._log.info(
        "%d samples bit-exact to anglecore (fixed) through the shell (bank %d): %d idle input "
        "clocks, %d held outputs",
        len(codes),
        bank,
        src.idle_clocks,
        sink.held_clocks,
    )
