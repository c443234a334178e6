# SPDX-License-Identifier: MIT
# A check of your own on acore_top (docs/cocotb.md; the CTest cocotb_doc_example runs it).
import acore_cocotb as acb
import anglecore as ac
import cocotb


@cocotb.test()
async def my_check(dut):
    s = acb.settings()  # the image, samples, seed and the build's parameters
    img = ac.read_image(s.image)
    codes = acb.stimulus(img, s)  # or your own input codes: an (n, 4) integer array
    exp = acb.reference(img, codes, s)  # the package's bit-accurate answer on them
    await acb.start_top(dut, img)
    await acb.write_host_port(dut, dut.clk_i, [int(w) for w in img.words])
    sink, _ = await acb.stream(dut, dut.clk_i, codes, s, 100 * len(codes), 2000)
    nominal = len(codes) - len(codes) // 8  # acb.stimulus: the last eighth is random codes
    assert [g["angle"] for g in sink.got] == list(exp.angle)
    assert not any(g["flags"] for g in sink.got[:nominal]), "a nominal sample was flagged"
