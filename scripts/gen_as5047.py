#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The AS5047P's register facts, generated from their one description rtl/acore_as5047_map.txt.

  gen_as5047.py [--root DIR] [--out DIR]

writes (paths under OUT, default ROOT):
  rtl/acore_as5047.vh               included inside rtl/acore_spi_as5047.v: localparams AS5047_*
                                    (addresses, select codes, field positions, resets, constants),
                                    the address decode as5047_sel, as5047_writable and a function a
                                    code table (as5047_<table>)
  model/ip/stages/as5047_regs.hpp   the same facts as C++ constants (namespace acore::as5047)
scripts/gen_tables.sh runs it; CTest gen_tables_current compares its output with the repository's.
Exit 2 on a malformed description, naming its file, line and field.
"""

import argparse
import os
import re
import sys
import textwrap

DESC = "rtl/acore_as5047_map.txt"
VH = "rtl/acore_as5047.vh"
HPP = "model/ip/stages/as5047_regs.hpp"
ADDR_W = 14  # the frame's address and data bits
NAME_RE = re.compile(r"^[A-Z][A-Z0-9_]*$")


class DescError(Exception):
    pass


def fail(line, field, msg):
    raise DescError(f"{DESC}:{line}: {field}: {msg}")


def number(text, line, field, base=0):
    try:
        return int(text, base)
    except ValueError:
        fail(line, field, f"not a number: {text!r}")


def parse(path):
    regs, tables, consts = [], [], []
    names = set()
    with open(path, encoding="utf-8") as f:
        lines = f.readlines()
    for ln, raw in enumerate(lines, 1):
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        kind, args = words[0], words[1:]
        if kind == "reg":
            if len(args) not in (3, 4):
                fail(ln, "reg", "expected: reg ADDR NAME ACCESS [FIXED]")
            addr = number(args[0], ln, "ADDR", 16)
            name, access = args[1], args[2]
            if not 0 <= addr < 1 << ADDR_W:
                fail(ln, "ADDR", f"{args[0]} is not a {ADDR_W}-bit address")
            if not NAME_RE.match(name):
                fail(ln, "NAME", f"{name!r} is not an upper-case name")
            if name in names:
                fail(ln, "NAME", f"{name} is defined twice")
            if any(r["addr"] == addr for r in regs):
                fail(ln, "ADDR", f"{args[0]} is another register's address")
            if not regs and addr != 0:
                fail(ln, "ADDR", "the first register must be NOP's, address 0 (select code 0)")
            if access not in ("r", "rw"):
                fail(ln, "ACCESS", f"{access!r}: expected r or rw")
            fixed = number(args[3], ln, "FIXED") if len(args) == 4 else 0
            if not 0 <= fixed < 1 << ADDR_W:
                fail(ln, "FIXED", f"{args[3]} does not fit {ADDR_W} bits")
            names.add(name)
            regs.append(
                {
                    "name": name,
                    "addr": addr,
                    "rw": access == "rw",
                    "fixed": fixed,
                    "fields": [],
                    "line": ln,
                }
            )
        elif kind == "field":
            if len(args) not in (3, 4):
                fail(ln, "field", "expected: field REG BITS NAME [RESET]")
            reg = next((r for r in regs if r["name"] == args[0]), None)
            if reg is None:
                fail(ln, "REG", f"{args[0]} is no register defined above")
            m = re.match(r"^(\d+)(?::(\d+))?$", args[1])
            if not m:
                fail(ln, "BITS", f"{args[1]!r}: expected MSB:LSB or one bit")
            msb = int(m.group(1))
            lsb = int(m.group(2)) if m.group(2) is not None else msb
            if not ADDR_W > msb >= lsb >= 0:
                fail(ln, "BITS", f"{args[1]} is not within {ADDR_W - 1}:0")
            name = args[2]
            if not NAME_RE.match(name):
                fail(ln, "NAME", f"{name!r} is not an upper-case name")
            mask = ((1 << (msb - lsb + 1)) - 1) << lsb
            for f in reg["fields"]:
                if f["name"] == name:
                    fail(ln, "NAME", f"{reg['name']}.{name} is defined twice")
                if f["mask"] & mask:
                    fail(ln, "BITS", f"{args[1]} overlaps {reg['name']}.{f['name']}")
            if mask & reg["fixed"]:
                fail(ln, "BITS", f"{args[1]} overlaps {reg['name']}'s FIXED bits")
            reset = None
            if len(args) == 4:
                reset = number(args[3], ln, "RESET")
                if not 0 <= reset < 1 << (msb - lsb + 1):
                    fail(ln, "RESET", f"{args[3]} does not fit {msb - lsb + 1} bits")
            reg["fields"].append(
                {"name": name, "msb": msb, "lsb": lsb, "mask": mask, "reset": reset}
            )
        elif kind == "table":
            if len(args) < 2 or len(args) > 9:
                fail(ln, "table", "expected: table NAME V0 [V1 ... V7] (1 to 8 entries)")
            if not NAME_RE.match(args[0]) or args[0] in names:
                fail(ln, "NAME", f"{args[0]!r} is not a new upper-case name")
            values = [number(v, ln, f"V{i}") for i, v in enumerate(args[1:])]
            if any(v < 0 or v >= 1 << 31 for v in values):
                fail(ln, "V", "entries must be 0 .. 2^31-1")
            names.add(args[0])
            tables.append((args[0], values))
        elif kind == "const":
            if len(args) != 2:
                fail(ln, "const", "expected: const NAME VALUE")
            if not NAME_RE.match(args[0]) or args[0] in names:
                fail(ln, "NAME", f"{args[0]!r} is not a new upper-case name")
            value = number(args[1], ln, "VALUE")
            if not 0 <= value < 1 << 31:
                fail(ln, "VALUE", "must be 0 .. 2^31-1")
            names.add(args[0])
            consts.append((args[0], value))
        else:
            fail(ln, "kind", f"unknown line kind {kind!r} (reg, field, table, const)")
    if not regs:
        fail(len(lines), "reg", "no register")
    return regs, tables, consts


def camel(name):
    return "".join(p[:1].upper() + p[1:].lower() for p in name.split("_"))


def sel_w(regs):
    return max(1, (len(regs) - 1).bit_length())


HEAD = (
    "Generated by scripts/gen_as5047.py from rtl/acore_as5047_map.txt: do not edit.\n"
    "// Regenerate with scripts/gen_tables.sh."
)


VH_INTRO = (
    "The AS5047P's registers (included inside rtl/acore_spi_as5047.v): addresses AS5047_A_*, the "
    "select codes AS5047_S_* (the address decode as5047_sel; NOP's 0 for an unknown address), each "
    "register's FIXED bits, its fields' _LSB, _MSB, _W (and _RESET of the fields the port keeps), "
    "the code tables as functions of the code and their _LAST code, and the constants."
)
HPP_INTRO = (
    "The AS5047P's registers as the SPI port answers them (model/ip/stages/interfaces.hpp): a "
    "register's address k<Reg>, the bits it reads outside its fields k<Reg>Fixed; a one-bit field "
    "is its mask k<Reg><Field>, a wider one has <Field>Shift, <Field>Mask (in place) and "
    "<Field>Bits; <Field>Reset for the fields the port keeps; the code tables (k<Table>, code 0 "
    "first, k<Table>Last the last code), the constants, and known() and writable() of an address."
)


def comment(text):
    return textwrap.wrap(text, width=100, initial_indent="// ", subsequent_indent="// ")


def verilog(regs, tables, consts):
    sw = sel_w(regs)
    o = [
        "// SPDX-License-Identifier: MIT",
        "// " + HEAD,
        *comment(VH_INTRO),
        f"localparam integer AS5047_S_W = {sw};",
    ]
    for i, r in enumerate(regs):
        o.append(f"localparam [{ADDR_W - 1}:0] AS5047_A_{r['name']} = {ADDR_W}'h{r['addr']:04X};")
        o.append(f"localparam [AS5047_S_W-1:0] AS5047_S_{r['name']} = {sw}'d{i};")
        o.append(
            f"localparam [{ADDR_W - 1}:0] AS5047_{r['name']}_FIXED = {ADDR_W}'h{r['fixed']:04X};"
        )
        for f in r["fields"]:
            p = f"AS5047_{r['name']}_{f['name']}"
            w = f["msb"] - f["lsb"] + 1
            o.append(f"localparam integer {p}_LSB = {f['lsb']}, {p}_MSB = {f['msb']}, {p}_W = {w};")
            if f["reset"] is not None:
                o.append(f"localparam [{w - 1}:0] {p}_RESET = {w}'d{f['reset']};")
    for name, value in consts:
        o.append(f"localparam integer AS5047_{name} = {value};")
    o.append("// The select code of an address.")
    o.append(f"function [AS5047_S_W-1:0] as5047_sel(input [{ADDR_W - 1}:0] addr);")
    o.append("  case (addr)")
    for r in regs[1:]:
        o.append(f"    AS5047_A_{r['name']}: as5047_sel = AS5047_S_{r['name']};")
    o.append(f"    default: as5047_sel = AS5047_S_{regs[0]['name']};")
    o.append("  endcase")
    o.append("endfunction")
    o.append("// A write's data frame is taken (rw).")
    o.append("function as5047_writable(input [AS5047_S_W-1:0] s);")
    rw = [f"s == AS5047_S_{r['name']}" for r in regs if r["rw"]]
    o.append("  as5047_writable = " + (" || ".join(rw) if rw else "1'b0") + ";")
    o.append("endfunction")
    for name, values in tables:
        fn = f"as5047_{name.lower()}"
        o.append(f"// {name}: the entry of a code (codes past the last take the last entry).")
        o.append(f"localparam integer AS5047_{name}_LAST = {len(values) - 1};")
        o.append(f"function integer {fn}(input [2:0] code);")
        o.append("  case (code)")
        for i, v in enumerate(values[:-1]):
            o.append(f"    3'd{i}: {fn} = {v};")
        o.append(f"    default: {fn} = {values[-1]};")
        o.append("  endcase")
        o.append("endfunction")
    return "\n".join(o) + "\n"


def cpp(regs, tables, consts):
    o = [
        "// SPDX-License-Identifier: MIT",
        "// " + HEAD,
        *comment(HPP_INTRO),
        "#pragma once",
        "#include <cstdint>",
        "",
        "namespace acore::as5047 {",
        "",
    ]
    for r in regs:
        c = "k" + camel(r["name"])
        o.append(f"// {r['name']} ({'RW' if r['rw'] else 'R'})")
        o.append(f"constexpr uint16_t {c} = 0x{r['addr']:04X};")
        o.append(f"constexpr uint16_t {c}Fixed = 0x{r['fixed']:04X};")
        for f in r["fields"]:
            p = c + camel(f["name"])
            if f["msb"] == f["lsb"]:
                o.append(f"constexpr uint16_t {p} = 0x{f['mask']:04X};")
            else:
                o.append(f"constexpr int {p}Shift = {f['lsb']};")
                o.append(f"constexpr uint16_t {p}Mask = 0x{f['mask']:04X};")
                o.append(f"constexpr int {p}Bits = {f['msb'] - f['lsb'] + 1};")
            if f["reset"] is not None:
                o.append(f"constexpr int {p}Reset = {f['reset']};")
    for fn, what, pick in (
        ("known", "a register (NOP included)", lambda r: True),
        ("writable", "a register whose write's data frame is taken (rw)", lambda r: r["rw"]),
    ):
        o.append("")
        o.append(f"// Whether an address is {what}.")
        o.append(f"constexpr bool {fn}(uint16_t addr) {{")
        o.append("  switch (addr) {")
        for r in regs:
            if pick(r):
                o.append(f"    case k{camel(r['name'])}:")
        o.append("      return true;")
        o.append("    default:")
        o.append("      return false;")
        o.append("  }")
        o.append("}")
    for name, values in tables:
        o.append("")
        o.append(f"// {name}, code 0 first (codes past k{camel(name)}Last take its entry).")
        o.append(f"inline constexpr int64_t k{camel(name)}[] = {{{', '.join(map(str, values))}}};")
        o.append(f"constexpr int k{camel(name)}Last = {len(values) - 1};")
    o.append("")
    for name, value in consts:
        o.append(f"constexpr int k{camel(name)} = {value};")
    o.append("")
    o.append("}  // namespace acore::as5047")
    return "\n".join(o) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    ap.add_argument("--out", help="write under this folder (default: ROOT)")
    a = ap.parse_args()
    out = a.out or a.root
    try:
        regs, tables, consts = parse(os.path.join(a.root, DESC))
    except DescError as e:
        print(f"gen_as5047.py: error: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"gen_as5047.py: error: {DESC}: {e.strerror}", file=sys.stderr)
        return 2
    for rel, text in ((VH, verilog(regs, tables, consts)), (HPP, cpp(regs, tables, consts))):
        path = os.path.join(out, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
