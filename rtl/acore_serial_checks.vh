// SPDX-License-Identifier: MIT
// The serial core's options (SERIAL = 1: rtl/acore_serial_top.v): the 1-D polynomial on the raw x,
// no Fourier stage, not folded (MULT 0 or 1: its hardware product, rtl/acore_serial_datapath.v);
// which correction modes it builds is the mode table's (rtl/acore_mode_checks.vh). The same rules as DatapathConfig::validate(DatapathTop::kSerial).
// Included in rtl/acore_config_check.v, and in rtl/acore_apb.v, at the shell's own level: there a
// mode or option the serial core lacks also changes the map the shell hands the core, and the
// core's derived-parameter rules would otherwise be the first that Yosys reports.
  acore_check #(.OK(SERIAL == 0 || XCENTER == 0), .VALUE(XCENTER),
    .MSG("illegal parameter: XCENTER must be 0 on the serial core (it has no centred argument)"))
    XCENTER_must_be_0_on_the_serial_core ();
  acore_check #(.OK(SERIAL == 0 || FOURIER_K == 0), .VALUE(FOURIER_K),
    .MSG("illegal parameter: FOURIER_K must be 0 on the serial core (it has no Fourier stage)"))
    FOURIER_K_must_be_0_on_the_serial_core ();
  acore_check #(.OK(SERIAL == 0 || FOLD == 1), .VALUE(FOLD),
    .MSG("illegal parameter: FOLD must be 1 on the serial core (it is not folded)"))
    FOLD_must_be_1_on_the_serial_core ();
