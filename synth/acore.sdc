# SPDX-License-Identifier: MIT
# Clock constraint of acore_top / acore_serial_top (and their pin wrappers) for SDC/XDC tools
# (Vivado, Quartus, Libero, OpenSTA, ...): one clock, clk_i, every path register to register.
# 150 MHz is the target scripts/synth.sh gives nextpnr-ice40 (--freq 150); the HX8K reaches less
# (synth/reports/summary.md): relax the period to the part's figure, or keep it to see the slack.
create_clock -name clk_i -period 6.667 [get_ports clk_i]
