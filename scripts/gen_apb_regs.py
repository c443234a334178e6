#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The APB register shell's map, from its one description rtl/acore_apb_regs.txt.

  gen_apb_regs.py [--root DIR] [--out DIR]     write the generated files
  gen_apb_regs.py [--root DIR] --check DIR     write them into DIR and compare with ROOT's

Generated (paths relative to ROOT, or to OUT when given):
  rtl/acore_apb_regs.vh     localparams of rtl/acore_apb.v (included inside it): word indices,
                            field positions and widths, the decode's register sets, reset values,
                            the constant registers' values
  tb/shell/shell_regs.hpp         C++ constants of the shell's driver and tests (acore::shell)
  docs/register-shell.md    the register table (addresses, fields, bits, access, reset, meaning)

--check exits 1, printing a diff, when a file under ROOT differs from what the description gives
(CTest apb_regs_generated). Exit 2 on a malformed description, naming its file, line and field.
"""
import argparse
import difflib
import os
import re
import sys
import textwrap

SOURCE = "rtl/acore_apb_regs.txt"
COMMAND = "python3 scripts/gen_apb_regs.py"
OUTPUTS = ("rtl/acore_apb_regs.vh", "tb/shell/shell_regs.hpp", "docs/register-shell.md")
ACCESS = {"RO": "read only", "RW": "read/write", "W1C": "write 1 to clear", "W1": "write 1 to act, reads 0"}


class DescError(Exception):
    pass


class Field:
    def __init__(self, msb, lsb, name, access, reset, meaning):
        self.msb, self.lsb, self.name, self.access, self.reset, self.meaning = (
            msb, lsb, name, access, reset, meaning)

    def width(self):
        """The width: an int, or 'PARAM' when the msb is PARAM-1 (lsb 0)."""
        return self.msb + 1 - self.lsb if isinstance(self.msb, int) else self.msb

    def bits(self):
        if isinstance(self.msb, int):
            return f"{self.msb}:{self.lsb}" if self.msb != self.lsb else f"{self.lsb}"
        return f"{self.msb}-1:{self.lsb}"


class Reg:
    def __init__(self, kind, offset, name, access, summary, words=1):
        self.kind, self.offset, self.name, self.access, self.summary, self.words = (
            kind, offset, name, access, summary, words)
        self.fields = []
        self.when = None  # a parameter of acore_apb.v: the register exists when it is nonzero


def camel(name):
    return "".join(p.capitalize() for p in name.lower().split("_"))


def parse(path):
    """(space, regs, notes) from the description; DescError names the line and the field."""
    regs, notes, space, when = [], [], None, None
    with open(path) as f:
        lines = f.read().split("\n")
    for n, raw in enumerate(lines, 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        where = f"{path}:{n}"
        kind, _, rest = line.partition(" ")
        rest = rest.strip()

        def num(text, what):
            try:
                return int(text, 0)
            except ValueError:
                raise DescError(f"{where}: {what} '{text}' is not a number")

        if kind == "space":
            space = num(rest, "space")
        elif kind == "when":
            if rest == "-":
                when = None
            elif re.fullmatch(r"[A-Z][A-Z0-9_]*", rest):
                when = rest
            else:
                raise DescError(f"{where}: 'when' takes a parameter name or '-', not '{rest}'")
        elif kind == "note":
            notes.append(rest)
        elif kind in ("reg", "const", "window"):
            parts = rest.split(None, 4 if kind == "window" else 3)
            if len(parts) < (5 if kind == "window" else 4):
                raise DescError(f"{where}: expected '{kind} OFFSET NAME ACCESS "
                                f"{'WORDS ' if kind == 'window' else ''}summary'")
            offset = num(parts[0], "offset")
            name, access = parts[1], parts[2]
            if not re.fullmatch(r"[A-Z][A-Z0-9_]*", name):
                raise DescError(f"{where}: register name '{name}' is not UPPER_CASE")
            if access not in ACCESS:
                raise DescError(f"{where}: access '{access}' of {name} is not one of {', '.join(ACCESS)}")
            if offset % 4:
                raise DescError(f"{where}: offset {parts[0]} of {name} is not word-aligned")
            words = num(parts[3], "words") if kind == "window" else 1
            if kind == "window" and (words & (words - 1) or offset % (4 * words) or offset < 0x100):
                raise DescError(f"{where}: window {name}: WORDS must be a power of two and OFFSET a "
                                f"multiple of 4 WORDS above the registers (the decode compares the "
                                f"address bits above the window)")
            if kind != "window" and offset >= 0x100:
                raise DescError(f"{where}: register {name} at {parts[0]}: registers live below 0x100")
            if kind == "const" and access != "RO":
                raise DescError(f"{where}: register of constants {name} must be RO")
            if when and kind != "reg":
                raise DescError(f"{where}: {name}: only a 'reg' can depend on a parameter ('when')")
            regs.append(Reg(kind, offset, name, access, parts[-1], words))
            regs[-1].when = when
        elif kind == "field":
            if not regs:
                raise DescError(f"{where}: a field before any register")
            parts = rest.split(None, 4)
            if len(parts) < 5:
                raise DescError(f"{where}: expected 'field BITS NAME ACCESS RESET meaning'")
            bits, name, access, reset, meaning = parts
            m = re.fullmatch(r"(\d+)(?::(\d+))?|([A-Z][A-Z0-9_]*)-1:0", bits)
            if not m:
                raise DescError(f"{where}: bits '{bits}' of field {name}: expected msb:lsb, a bit or PARAM-1:0")
            if m.group(3):
                msb, lsb = m.group(3), 0
            else:
                msb = int(m.group(1))
                lsb = int(m.group(2)) if m.group(2) is not None else msb
                if not 0 <= lsb <= msb <= 31:
                    raise DescError(f"{where}: bits '{bits}' of field {name} are not within 31:0")
            if not re.fullmatch(r"[A-Z][A-Z0-9_]*", name):
                raise DescError(f"{where}: field name '{name}' is not UPPER_CASE")
            if access not in ACCESS:
                raise DescError(f"{where}: access '{access}' of field {name} is not one of {', '.join(ACCESS)}")
            if not re.fullmatch(r"-|0x[0-9A-Fa-f]+|\d+|[A-Z][A-Z0-9_]*", reset):
                raise DescError(f"{where}: reset '{reset}' of field {name}: a number, a parameter or '-'")
            reg = regs[-1]
            if any(x.name == name for x in reg.fields):
                raise DescError(f"{where}: field {name} twice in {reg.name}")
            if isinstance(msb, int):
                for x in reg.fields:
                    if isinstance(x.msb, int) and not (msb < x.lsb or lsb > x.msb):
                        raise DescError(f"{where}: field {name} ({bits}) overlaps {x.name} ({x.bits()})")
            reg.fields.append(Field(msb, lsb, name, access, reset, meaning))
        else:
            raise DescError(f"{where}: unknown line kind '{kind}' (space, reg, field, window, when, note)")
    if space is None:
        raise DescError(f"{path}: no 'space' line")
    names, offsets = set(), set()
    for r in regs:
        if r.name in names:
            raise DescError(f"{path}: register {r.name} twice")
        if r.offset in offsets:
            raise DescError(f"{path}: two registers at 0x{r.offset:03X}")
        names.add(r.name)
        offsets.add(r.offset)
        if not r.fields:
            raise DescError(f"{path}: register {r.name} has no field")
        if r.kind == "const" and any(not isinstance(x.msb, int) or x.reset == "-" for x in r.fields):
            raise DescError(f"{path}: register of constants {r.name}: every field needs fixed bits "
                            f"and a reset value")
        ro = all(x.access == "RO" for x in r.fields)
        if (r.access == "RO") != ro:
            raise DescError(f"{path}: register {r.name} is {r.access} but its fields say "
                            f"{'read only' if ro else 'writable'}")
    # The sticky STATUS bits, their enables and the pending bits share positions (rtl/acore_apb.v).
    by = {r.name: r for r in regs}
    w1c = sorted(x.lsb for x in by["STATUS"].fields if x.access == "W1C")
    if w1c != list(range(len(w1c))):
        raise DescError(f"{path}: STATUS's W1C bits must be bits 0..N-1")
    for reg, field in (("CTRL", "IRQ_EN"), ("IRQ", "PENDING")):
        f = next((x for x in by[reg].fields if x.name == field), None)
        if f is None or f.width() != len(w1c):
            raise DescError(f"{path}: {reg}.{field} must have one bit per sticky STATUS bit ({len(w1c)})")
    return space, regs, notes


def header(comment, lines):
    return "".join(f"{comment} {l}".rstrip() + "\n" for l in lines)


PROVENANCE = [f"Generated by scripts/gen_apb_regs.py from {SOURCE}: do not edit. Regenerate with",
              f"  {COMMAND}"]


def gen_vh(space, regs, notes):
    out = ["// SPDX-License-Identifier: MIT\n",
           header("//", PROVENANCE + [
               "The APB register map of rtl/acore_apb.v, included inside it after its parameters and its",
               "LATENCY, CYCLES and CAPACITY: the CONFIG registers read them. <REG>_<FIELD> is a field's lsb,",
               "<REG>_<FIELD>_W its width (fields wider than a bit)."]), "\n"]
    plain = [r for r in regs if r.kind != "window"]
    out.append("// Register word indices (byte address / 4).\n")
    for r in plain:
        out.append(f"localparam [5:0] R_{r.name} = 6'h{r.offset >> 2:02X};\n")
    ro = sum(1 << (r.offset >> 2) for r in plain if r.access == "RO" and not r.when)
    wr = sum(1 << (r.offset >> 2) for r in plain if r.access != "RO" and not r.when)
    out.append("// The registers the decode answers, one bit per word index: read only, and writable.\n")
    conds = sorted({r.when for r in plain if r.when})
    if not conds:
        out.append(f"localparam [63:0] REGS_RO = 64'h{ro:016X};\n")
        out.append(f"localparam [63:0] REGS_WR = 64'h{wr:016X};\n")
    else:
        out.append("// (The registers of a 'when PARAM' group only when that parameter is nonzero.)\n")
        for kind, base, test in (("RO", ro, lambda r: r.access == "RO"), ("WR", wr, lambda r: r.access != "RO")):
            terms = [f"64'h{base:016X}"]
            for c in conds:
                m = sum(1 << (r.offset >> 2) for r in plain if r.when == c and test(r))
                if m:
                    terms.append(f"(({c}) != 0 ? 64'h{m:016X} : 64'h0)")
            out.append(f"localparam [63:0] REGS_{kind} = " + " |\n    ".join(terms) + ";\n")
    for w in (r for r in regs if r.kind == "window"):
        out.append(f"// {w.name}: {w.words} words from byte 0x{w.offset:03X} (word index {w.offset >> 2}).\n")
        out.append(f"localparam integer {w.name}_BASE = {w.offset};\n")
        out.append(f"localparam integer {w.name}_WORDS = {w.words};\n")
    out.append("// Fields.\n")
    for r in regs:
        for f in r.fields:
            w = f.width()
            line = f"localparam integer {r.name}_{f.name} = {f.lsb}"
            if w != 1:
                line += f", {r.name}_{f.name}_W = {w}"
            out.append(line + ";\n")
    out.append("// Reset values of the writable registers (fields with a constant reset).\n")
    for r in plain:
        if r.access == "RO":
            continue
        if all(re.fullmatch(r"0x[0-9A-Fa-f]+|\d+", f.reset) for f in r.fields):
            v = sum(int(f.reset, 0) << f.lsb for f in r.fields)
            out.append(f"localparam [31:0] {r.name}_RESET = 32'h{v:08X};\n")
    out.append("// The registers of constants (the CONFIG registers read the build's parameters).\n")
    for r in (r for r in regs if r.kind == "const"):
        terms = []
        for f in r.fields:
            if re.fullmatch(r"0x[0-9A-Fa-f]+|\d+", f.reset):
                terms.append(f"(32'h{int(f.reset, 0):X} << {r.name}_{f.name})")
            else:
                terms.append(f"((({f.reset}) & 32'h{(1 << f.width()) - 1:X}) << {r.name}_{f.name})")
        out.append(f"localparam [31:0] {r.name}_VALUE =\n    " + " |\n    ".join(terms) + ";\n")
    return "".join(out)


def cpp_comment(text, indent=""):
    """A // comment wrapped below 100 columns (clang-format leaves it as it is)."""
    return "".join(f"{indent}// {l}\n" for l in textwrap.wrap(text, 96 - len(indent)))


def gen_hpp(space, regs, notes):
    out = ["// SPDX-License-Identifier: MIT\n",
           header("//", PROVENANCE + [
               "The register map of the APB shell (rtl/acore_apb.v, docs/register-shell.md): byte",
               "addresses and bit fields, for the driver (tb/shell/shell_driver.*) and the tests. A one-bit field",
               "is its mask; a wider one has <Field>Shift and <Field>Mask (in place; a width set by a",
               "parameter has a shift only)."]),
           "#pragma once\n#include <cstdint>\n\nnamespace acore::shell {\n\n",
           "// The address space the default APB_AW decodes.\n",
           f"constexpr uint32_t kAddrSpace = 0x{space:X};\n"]
    for r in regs:
        what = (f"{r.words} words, word a at 0x{r.offset:03X} + 4a" if r.kind == "window"
                else f"{r.access}" + (f", when {r.when} != 0" if r.when else ""))
        out.append(f"\n{cpp_comment(f'{r.name} ({what}): {r.summary}')}")
        out.append(f"constexpr uint32_t k{camel(r.name)} = 0x{r.offset:03X};\n")
        for f in r.fields:
            c = f"k{camel(r.name)}{camel(f.name)}"
            w = f.width()
            out.append(cpp_comment(f"{f.name} [{f.bits()}] ({f.access}): {f.meaning}"))
            if w == 1:
                out.append(f"constexpr uint32_t {c} = 1u << {f.lsb};\n")
            else:
                out.append(f"constexpr int {c}Shift = {f.lsb};\n")
                if isinstance(w, int):
                    out.append(f"constexpr uint32_t {c}Mask = 0x{((1 << w) - 1) << f.lsb:X}u;\n")
        if r.kind == "const" and all(re.fullmatch(r"0x[0-9A-Fa-f]+|\d+", f.reset) for f in r.fields):
            out.append(f"constexpr uint32_t k{camel(r.name)}Value = "
                       f"0x{sum(int(f.reset, 0) << f.lsb for f in r.fields):X}u;\n")
        if r.kind == "reg" and r.access != "RO" and all(isinstance(f.width(), int) for f in r.fields):
            if all(re.fullmatch(r"0x[0-9A-Fa-f]+|\d+|-", f.reset) for f in r.fields):
                v = sum(int(f.reset, 0) << f.lsb for f in r.fields if f.reset != "-")
                out.append(f"constexpr uint32_t k{camel(r.name)}Reset = 0x{v:X}u;\n")
            out.append("// The bits that read back.\n")
            rd = sum(((1 << f.width()) - 1) << f.lsb for f in r.fields if f.access != "W1")
            out.append(f"constexpr uint32_t k{camel(r.name)}ReadMask = 0x{rd:X}u;\n")
            w1c = sum(((1 << f.width()) - 1) << f.lsb for f in r.fields if f.access == "W1C")
            if w1c:
                out.append("// The sticky bits.\n")
                out.append(f"constexpr uint32_t k{camel(r.name)}W1cMask = 0x{w1c:X}u;\n")
    out.append("\n}  // namespace acore::shell\n")
    return "".join(out)


def md_escape(text):
    return text.replace("|", "\\|")


def gen_md(space, regs, notes):
    out = ["# The APB register shell's register map\n\n",
           f"<!-- Generated by scripts/gen_apb_regs.py from {SOURCE}: do not edit. Regenerate with\n"
           f"     {COMMAND} -->\n\n",
           "The registers of `rtl/acore_apb.v`, the APB4 register shell around `acore_top` (pipelined "
           "or folded) or `acore_serial_top`. Byte addresses; 32-bit registers, 32-bit accesses only. "
           f"The default `APB_AW` = {space.bit_length() - 1} decodes 0x000..0x{space - 1:03X}. "
           "Access: " + "; ".join(f"{k} {v}" for k, v in ACCESS.items()) + ". A reset that names a "
           "parameter is the build's value; `-` is live state.\n\n",
           "| address | register | access | reset | summary |\n|---|---|---|---|---|\n"]
    for r in regs:
        addr = f"0x{r.offset:03X} + 4a" if r.kind == "window" else f"0x{r.offset:03X}"
        name = f"{r.name}\\[a\\]" if r.kind == "window" else r.name
        consts = [f for f in r.fields if re.fullmatch(r"0x[0-9A-Fa-f]+|\d+", f.reset)]
        if r.kind != "window" and len(consts) == len(r.fields):
            reset = f"0x{sum(int(f.reset, 0) << f.lsb for f in r.fields):08X}"
        elif all(f.reset == "-" or re.fullmatch(r"0x[0-9A-Fa-f]+|\d+", f.reset) for f in r.fields) \
                and any(f.reset != "-" for f in r.fields):
            reset = f"0x{sum(int(f.reset, 0) << f.lsb for f in r.fields if f.reset != '-'):08X}"
        elif len(r.fields) == 1:
            reset = r.fields[0].reset
        else:
            reset = "parameters"
        cond = f" (only when `{r.when}` = 1)" if r.when else ""
        out.append(f"| {addr} | [{name}](#{r.name.lower()}) | {r.access} | {reset} | "
                   f"{md_escape(r.summary)}{cond} |\n")
    for r in regs:
        addr = (f"0x{r.offset:03X} + 4a, a < WORDS (at most {r.words})" if r.kind == "window"
                else f"0x{r.offset:03X}")
        cond = f" Present only when the shell's parameter `{r.when}` is 1." if r.when else ""
        out.append(f"\n## {r.name}\n\n{addr}, {r.access}. {md_escape(r.summary)}{cond}\n\n")
        out.append("| bits | field | access | reset | meaning |\n|---|---|---|---|---|\n")
        for f in sorted(r.fields, key=lambda x: -x.lsb if isinstance(x.msb, int) else 0):
            out.append(f"| {f.bits()} | {f.name} | {f.access} | {f.reset} | {md_escape(f.meaning)} |\n")
    if notes:
        out.append("\n## Transfers and errors\n\n")
        out.append("\n\n".join(notes) + "\n")
    return "".join(out)


def generate(root):
    space, regs, notes = parse(os.path.join(root, SOURCE))
    return {"rtl/acore_apb_regs.vh": gen_vh(space, regs, notes),
            "tb/shell/shell_regs.hpp": gen_hpp(space, regs, notes),
            "docs/register-shell.md": gen_md(space, regs, notes)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    ap.add_argument("--out", help="write under this directory instead of ROOT")
    ap.add_argument("--check", metavar="DIR", help="write under DIR and compare with ROOT's files")
    args = ap.parse_args()
    try:
        files = generate(args.root)
    except (DescError, OSError) as e:
        print(f"gen_apb_regs.py: {e}", file=sys.stderr)
        return 2
    out = args.check or args.out or args.root
    for rel, text in files.items():
        path = os.path.join(out, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    if not args.check:
        print(f"wrote {', '.join(os.path.join(out, r) for r in files)}")
        return 0
    differ = 0
    for rel, text in files.items():
        mine = os.path.join(args.root, rel)
        have = open(mine).read() if os.path.exists(mine) else ""
        if have != text:
            differ += 1
            print(f"FAIL {rel} differs from {SOURCE} (regenerate: {COMMAND}):")
            sys.stdout.writelines(difflib.unified_diff(have.splitlines(True), text.splitlines(True),
                                                       rel, os.path.join(args.check, rel), n=1))
        else:
            print(f"ok   {rel} is {SOURCE}'s")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
