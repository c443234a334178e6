#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""APB register blocks, each generated whole from its one description rtl/<owner>_regs.txt.

  gen_apb_regs.py [--root DIR] [--out DIR] [DESC ...]    write the generated files
  gen_apb_regs.py [--root DIR] --check DIR [DESC ...]    write them into DIR and compare with ROOT's
  gen_apb_regs.py --syntax                               print the description's line kinds

DESC: descriptions relative to ROOT (default: every rtl/*_regs.txt). A description names its owner,
the module that instantiates its register block (`block acore_apb`), and gives (paths relative to
ROOT, or to OUT when given):
  rtl/<owner>_regblock.v   the register block: an APB4 slave (decode and read in the setup phase,
                           zero wait states) with the flops, reset values, write strobes and W1
                           pulses, W1C sticky bits with their hardware set inputs, the read mux,
                           range and lock refusals (PSLVERR, no effect), a port per field
  rtl/<owner>_regs.vh      included inside the owner: the map's localparams (word indices, field
                           positions and widths, reset values, the constant registers' values), a
                           wire per field port (rg_<reg>_<field>...) and the block's instance
  the `cpp` header         C++ constants: addresses, fields, widths, ranges, reset values
  the `doc` page           the register table (addresses, fields, bits, access, reset, meaning)

--check exits 1, printing a diff, when a file under ROOT differs from what its description gives
(CTest apb_regs_generated). Exit 2 on a malformed description, naming its file, line and field.
"""

import argparse
import difflib
import glob
import itertools
import os
import re
import sys
import textwrap

COMMAND = "python3 scripts/gen_apb_regs.py"
RTL = "rtl"  # the folder of the descriptions and of the RTL they give
# Software access of a field, and what the register block builds for it (the hardware's view).
ACCESS = {
    "RO": (
        "read only",
        (
            "no flop: a `reg`'s field reads the hardware's value (input rg_<reg>_<field>), "
            "a `const`'s its RESET"
        ),
    ),
    "RW": (
        "read/write",
        (
            "a flop with its RESET: its value (rg_<reg>_<field>) and its write strobe "
            "(rg_<reg>_<field>_we, high in the clock it is written)"
        ),
    ),
    "W1C": (
        "write 1 to clear",
        (
            "a sticky flop: the hardware sets it (input rg_<reg>_<field>_set, "
            "a set wins over a clear in the same clock), a write of 1 clears it; its value"
        ),
    ),
    "W1": (
        "write 1 to act, reads 0",
        (
            "no flop: a pulse (rg_<reg>_<field>) in the clock a write "
            "with the field's bits set takes effect"
        ),
    ),
}
# The description's line kinds: (syntax, what it means). Attributes apply to the field (or window)
# above them.
KINDS = {
    "block": ("block OWNER", "the module that instantiates the register block (first line)"),
    "cpp": ("cpp PATH NAMESPACE", "the C++ header of the constants and its namespace"),
    "doc": ("doc PATH", "the generated register table"),
    "title": ("title TEXT", "the table's title"),
    "intro": ("intro TEXT", "a paragraph before the table"),
    "space": ("space SIZE", "the address space the default APB_AW decodes"),
    "reg": ("reg OFFSET NAME ACCESS summary", "a 32-bit register at a byte OFFSET below 0x100"),
    "const": ("const OFFSET NAME RO summary", "a register of constants (its fields' RESET values)"),
    "window": (
        "window OFFSET NAME ACCESS WORDS summary",
        "WORDS 32-bit words from OFFSET (word a at OFFSET + 4a), kept outside the block",
    ),
    "field": ("field BITS NAME ACCESS RESET meaning", "a field of the register (or window) above"),
    "range": (
        "range LO HI [word]",
        (
            "the RW field above accepts LO..HI (numbers, or parameters of the "
            "owner on a field of at most 8 bits); a write outside is an error without effect; "
            "`word`: the whole written word from the field's lsb up is compared (bits above the "
            "field must be 0)"
        ),
    ),
    "lock": (
        "lock TEXT",
        (
            "the owner refuses the field above (W1: a write that sets it; RW: a write "
            "to its register) or any access to the window above, with an error and no effect, "
            "while its input rg_<reg>_<field>_lock is high; TEXT says when"
        ),
    ),
    "hw": (
        "hw TEXT",
        (
            "the owner also writes the RW field above: inputs rg_<reg>_<field>_hw_we and "
            "rg_<reg>_<field>_hw_d (a value within the field's range; an APB write of its "
            "register in the same clock wins); TEXT says who"
        ),
    ),
    "mem": (
        "mem WINDOW",
        (
            "the owner keeps the RO or RW field above (bits 31:0, its register's only field) in "
            "a word of WINDOW's memory beyond the window's own: the block reads it through the "
            "window's read port (output rg_<reg>_<field>_re, high in a setup phase at its "
            "address: the owner reads that word instead; the window's read data is then 32 bits "
            "wide) and the access phase returns it, zero wait states. RO: input "
            "rg_<reg>_<field>_zero: the word holds no value yet, the register reads 0. RW: no "
            "flops; outputs rg_<reg>_<field>_we (an error-free write's access phase) and "
            "rg_<reg>_<field>_wdata (PWDATA): the owner writes the word, and writes the field's "
            "reset value into it in reset"
        ),
    ),
    "clears": (
        "clears REG",
        "the W1 field above clears every W1C field of REG (no port of its own)",
    ),
    "frac": ("frac N", "the field above is unsigned fixed point with N fraction bits"),
    "size": ("size PARAM", "the window above holds PARAM words of the owner (at most its WORDS)"),
    "irq": (
        "irq REG EN_REG.FIELD PEND_REG.FIELD",
        (
            "REG's W1C bits are bits 0..n-1, and the enable "
            "and pending fields have one bit per W1C bit at the same positions"
        ),
    ),
    "note": ("note text", "a paragraph of the table's page, after the tables"),
}
NUM = r"0x[0-9A-Fa-f]+|\d+"
NAME = r"[A-Z][A-Z0-9_]*"


class DescError(Exception):
    pass


def isnum(text):
    return bool(re.fullmatch(NUM, text))


class Field:
    def __init__(self, msb, lsb, name, access, reset, meaning, where):
        self.msb, self.lsb, self.name, self.access, self.reset, self.meaning, self.where = (
            msb,
            lsb,
            name,
            access,
            reset,
            meaning,
            where,
        )
        self.range = None  # (lo, hi, word): lo/hi an int or a parameter name
        self.lock = None  # when the owner refuses it (text)
        self.hw = None  # who else writes it (text): the hardware write port
        self.mem = None  # the window whose memory keeps it (a name)
        self.clears = None  # the register whose W1C fields a W1 field clears
        self.frac = None
        self.reg = None

    def width(self):
        """The width: an int, or 'PARAM' when the msb is PARAM-1 (lsb 0)."""
        return self.msb + 1 - self.lsb if isinstance(self.msb, int) else self.msb

    def vwidth(self):
        """The width as a Verilog expression."""
        return str(self.width())

    def bits(self):
        if isinstance(self.msb, int):
            return f"{self.msb}:{self.lsb}" if self.msb != self.lsb else f"{self.lsb}"
        return f"{self.msb}-1:{self.lsb}"

    def mask(self):
        return ((1 << self.width()) - 1) << self.lsb

    def port(self):
        """The field's port stem: <reg>_<field>, or <reg> when the names are equal."""
        r = self.reg.name.lower()
        return (
            r
            if self.name == self.reg.name or self.reg.kind == "window"
            else f"{r}_{self.name.lower()}"
        )

    def lp(self):
        """The localparam of its lsb (<REG>_<FIELD>)."""
        return f"{self.reg.name}_{self.name}"

    def decl(self):
        """The Verilog range of its port ('' for one bit)."""
        w = self.width()
        return "" if w == 1 else f"[{w}-1:0]" if not isinstance(w, int) else f"[{w - 1}:0]"

    def live(self):
        """A read-only field of a `reg`: the hardware's value."""
        return self.access == "RO" and self.reg.kind == "reg"


class Reg:
    def __init__(self, kind, offset, name, access, summary, words, where):
        self.kind, self.offset, self.name, self.access, self.summary, self.words, self.where = (
            kind,
            offset,
            name,
            access,
            summary,
            words,
            where,
        )
        self.fields = []
        self.size = None  # window: the owner's parameter of the words in use
        self.lock = None

    def idx(self):
        return self.offset >> 2

    def writable(self):
        return self.access != "RO"


class Block:
    def __init__(self, path):
        self.path = path
        self.owner = self.cpp = self.namespace = self.doc = self.title = self.space = None
        self.intro, self.notes, self.regs, self.irq = [], [], [], None

    def plain(self):
        return [r for r in self.regs if r.kind != "window"]

    def windows(self):
        return [r for r in self.regs if r.kind == "window"]

    def mems(self, w):
        """The RO fields window w's memory keeps."""
        return [f for r in self.regs for f in r.fields if f.mem == w.name]

    def fields(self):
        return [f for r in self.regs for f in r.fields]

    def params(self):
        """The owner's parameters the block reads: (name, what) in order of first use."""
        out = {}
        for r in self.regs:
            for f in r.fields:
                if not isinstance(f.msb, int):
                    out.setdefault(f.msb, "width")
                if r.kind == "reg" and f.access in ("RW", "W1C") and not isnum(f.reset):
                    out.setdefault(f.reset, "reset")
                if f.range:
                    for side, v in zip(("lo", "hi"), f.range[:2]):
                        if not isinstance(v, int):
                            out.setdefault(v, ("range", side, f))
        return out


def num(text, what, where):
    try:
        return int(text, 0)
    except ValueError:
        raise DescError(f"{where}: {what} '{text}' is not a number")


def parse(root, rel):
    """The Block of a description; DescError names the file, the line and the field."""
    blk = Block(rel)
    last_field = last_reg = None
    with open(os.path.join(root, rel)) as f:
        lines = f.read().split("\n")
    for n, raw in enumerate(lines, 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        where = f"{rel}:{n}"
        kind, _, rest = line.partition(" ")
        rest = rest.strip()
        if kind not in KINDS:
            raise DescError(f"{where}: unknown line kind '{kind}' ({', '.join(KINDS)})")
        if kind != "block" and blk.owner is None:
            raise DescError(f"{where}: the first line must be '{KINDS['block'][0]}'")
        args = rest.split()

        def need(count, text=None):
            if len(args) < count or (text is None and len(args) > count):
                raise DescError(f"{where}: expected '{KINDS[kind][0]}'")

        def attr_field(accesses, what):
            if last_field is None or last_field.reg is not last_reg:
                raise DescError(f"{where}: '{kind}' must follow the field it applies to")
            if last_field.access not in accesses:
                raise DescError(f"{where}: '{kind}' of field {last_field.name}: {what}")
            return last_field

        if kind == "block":
            need(1)
            if blk.owner is not None:
                raise DescError(f"{where}: a second 'block' line")
            if not re.fullmatch(r"[a-z][a-z0-9_]*", args[0]):
                raise DescError(f"{where}: block owner '{args[0]}' is not a module name")
            blk.owner = args[0]
        elif kind == "cpp":
            need(2)
            if not re.fullmatch(r"[\w/]+\.hpp", args[0]) or not re.fullmatch(
                r"\w+(::\w+)*", args[1]
            ):
                raise DescError(f"{where}: expected 'cpp PATH.hpp NAME::SPACE', not '{rest}'")
            blk.cpp, blk.namespace = args
        elif kind == "doc":
            need(1)
            if not re.fullmatch(r"docs/[\w/-]+\.md", args[0]):
                raise DescError(f"{where}: doc '{args[0]}' is not a page under docs/")
            blk.doc = args[0]
        elif kind == "title":
            need(1, "text")
            blk.title = rest
        elif kind == "intro":
            need(1, "text")
            blk.intro.append(rest)
        elif kind == "note":
            need(1, "text")
            blk.notes.append(rest)
        elif kind == "space":
            need(1)
            blk.space = num(args[0], "space", where)
            if blk.space & (blk.space - 1) or blk.space < 0x800:
                raise DescError(f"{where}: space {args[0]} is not a power of two >= 0x800")
        elif kind in ("reg", "const", "window"):
            parts = rest.split(None, 4 if kind == "window" else 3)
            if len(parts) < (5 if kind == "window" else 4):
                raise DescError(f"{where}: expected '{KINDS[kind][0]}'")
            offset = num(parts[0], "offset", where)
            name, access = parts[1], parts[2]
            if not re.fullmatch(NAME, name):
                raise DescError(f"{where}: register name '{name}' is not UPPER_CASE")
            if access not in ACCESS:
                raise DescError(
                    f"{where}: access '{access}' of {name} is not one of {', '.join(ACCESS)}"
                )
            if offset % 4:
                raise DescError(f"{where}: offset {parts[0]} of {name} is not word-aligned")
            words = num(parts[3], "words", where) if kind == "window" else 1
            if kind == "window" and (words < 2 or words & (words - 1) or offset % (4 * words)):
                raise DescError(
                    f"{where}: window {name}: WORDS {parts[3]} must be a power of two >= 2 "
                    f"and the offset a multiple of its size"
                )
            if kind == "window" and access != "RW":
                raise DescError(f"{where}: window {name} must be RW")
            if kind != "window" and offset >= 0x100:
                raise DescError(
                    f"{where}: register {name} at {parts[0]}: registers live below 0x100"
                )
            if kind == "window" and offset < 0x100:
                raise DescError(
                    f"{where}: window {name} at {parts[0]}: windows live above the registers"
                )
            if kind == "const" and access != "RO":
                raise DescError(f"{where}: register of constants {name} must be RO")
            last_reg = Reg(kind, offset, name, access, parts[-1], words, where)
            blk.regs.append(last_reg)
            last_field = None
        elif kind == "field":
            if last_reg is None:
                raise DescError(f"{where}: a field before any register")
            parts = rest.split(None, 4)
            if len(parts) < 5:
                raise DescError(f"{where}: expected '{KINDS[kind][0]}'")
            bits, name, access, reset, meaning = parts
            m = re.fullmatch(r"(\d+)(?::(\d+))?|(" + NAME + r")-1:0", bits)
            if not m:
                raise DescError(
                    f"{where}: bits '{bits}' of field {name}: expected msb:lsb, a bit or PARAM-1:0"
                )
            if m.group(3):
                msb, lsb = m.group(3), 0
            else:
                msb = int(m.group(1))
                lsb = int(m.group(2)) if m.group(2) is not None else msb
                if not 0 <= lsb <= msb <= 31:
                    raise DescError(f"{where}: bits '{bits}' of field {name} are not within 31:0")
            if not re.fullmatch(NAME, name):
                raise DescError(f"{where}: field name '{name}' is not UPPER_CASE")
            if access not in ACCESS:
                raise DescError(
                    f"{where}: access '{access}' of field {name} is not one of {', '.join(ACCESS)}"
                )
            if not re.fullmatch(r"-|" + NUM + "|" + NAME, reset):
                raise DescError(
                    f"{where}: reset '{reset}' of field {name}: a number, a parameter or '-'"
                )
            reg = last_reg
            if any(x.name == name for x in reg.fields):
                raise DescError(f"{where}: field {name} twice in {reg.name}")
            if reg.kind == "window" and (reg.fields or access != "RW"):
                raise DescError(f"{where}: window {reg.name} has one RW field (the word)")
            if reg.fields and (not isinstance(msb, int) or not isinstance(reg.fields[0].msb, int)):
                raise DescError(
                    f"{where}: field {name}: a field whose width is a parameter is its "
                    f"register's only field"
                )
            if isinstance(msb, int):
                for x in reg.fields:
                    if not (msb < x.lsb or lsb > x.msb):
                        raise DescError(
                            f"{where}: field {name} ({bits}) overlaps {x.name} ({x.bits()})"
                        )
            if access in ("W1", "W1C") and not (isinstance(msb, int) and isnum(reset)):
                raise DescError(
                    f"{where}: field {name}: a {access} field has fixed bits and a number as RESET"
                )
            if access == "W1" and int(reset, 0) != 0:
                raise DescError(f"{where}: field {name}: a W1 field reads 0: RESET 0")
            if access == "RW" and reg.kind == "reg" and reset == "-":
                raise DescError(
                    f"{where}: field {name}: an RW field has a RESET (a number or a parameter)"
                )
            if isnum(reset) and isinstance(msb, int) and int(reset, 0) >> (msb + 1 - lsb):
                raise DescError(
                    f"{where}: reset {reset} of field {name} does not fit its {msb + 1 - lsb} bits"
                )
            last_field = Field(msb, lsb, name, access, reset, meaning, where)
            last_field.reg = reg
            reg.fields.append(last_field)
        elif kind == "range":
            f = attr_field(("RW",), "only an RW field has a range")
            if len(args) not in (2, 3) or (len(args) == 3 and args[2] != "word"):
                raise DescError(f"{where}: expected '{KINDS[kind][0]}'")
            lim = []
            for a in args[:2]:
                if isnum(a):
                    lim.append(int(a, 0))
                elif re.fullmatch(NAME, a):
                    lim.append(a)
                else:
                    raise DescError(
                        f"{where}: range limit '{a}' of field {f.name}: a number or a parameter"
                    )
            word = len(args) == 3
            if word and len(f.reg.fields) > 1:
                raise DescError(
                    f"{where}: range of field {f.name}: 'word' needs the register's only field"
                )
            w = f.width()
            if not isinstance(w, int):
                raise DescError(f"{where}: range of field {f.name}: its width is a parameter")
            nums = [v for v in lim if isinstance(v, int)]
            if any(v > (1 << w) - 1 for v in nums) or (len(nums) == 2 and nums[0] > nums[1]):
                raise DescError(
                    f"{where}: range {args[0]}..{args[1]} of field {f.name}: not within its "
                    f"{w} bits, or empty"
                )
            if isnum(f.reset) and len(nums) == 2 and not nums[0] <= int(f.reset, 0) <= nums[1]:
                raise DescError(
                    f"{where}: field {f.name}: its reset {f.reset} is outside its range"
                )
            f.range = (lim[0], lim[1], word)
        elif kind == "lock":
            need(1, "text")
            if last_reg is not None and last_reg.kind == "window" and last_field is None:
                last_reg.lock = rest
            elif last_reg is not None and last_reg.kind == "window":
                raise DescError(f"{where}: 'lock' of a window follows its window line")
            else:
                attr_field(
                    ("RW", "W1"), "only an RW or W1 field (or a window) has a lock"
                ).lock = rest
        elif kind == "hw":
            need(1, "text")
            attr_field(("RW",), "only an RW field has a hardware write port").hw = rest
        elif kind == "mem":
            need(1)
            f = attr_field(("RO", "RW"), "only an RO or RW field is kept in a window's memory")
            if f.reg.kind != "reg" or f.reg.fields != [f] or (f.msb, f.lsb) != (31, 0):
                raise DescError(
                    f"{where}: mem of field {f.name}: a register's only field, bits 31:0"
                )
            f.mem = args[0]
        elif kind == "clears":
            need(1)
            attr_field(("W1",), "only a W1 field clears").clears = args[0]
        elif kind == "frac":
            need(1)
            f = attr_field(("RW", "RO"), "only an RW or RO field is fixed point")
            f.frac = num(args[0], "fraction bits", where)
            if not isinstance(f.width(), int) or not 0 < f.frac <= f.width():
                raise DescError(f"{where}: frac {args[0]} of field {f.name}: 1..its fixed width")
        elif kind == "size":
            need(1)
            if last_reg is None or last_reg.kind != "window" or last_field is not None:
                raise DescError(f"{where}: 'size' follows its window line")
            if not re.fullmatch(NAME, args[0]):
                raise DescError(
                    f"{where}: size '{args[0]}' of window {last_reg.name} is not a parameter"
                )
            last_reg.size = args[0]
        elif kind == "irq":
            need(3)
            blk.irq = (args, where)
    validate(blk)
    return blk


def validate(blk):
    path = blk.path
    for key, what in (("cpp", "cpp"), ("doc", "doc"), ("space", "space"), ("title", "title")):
        if getattr(blk, key) is None:
            raise DescError(f"{path}: no '{what}' line ({KINDS[what][0]})")
    names, offsets, ports = {}, {}, {}
    for r in blk.regs:
        if r.name in names:
            raise DescError(f"{r.where}: register {r.name} twice (first at {names[r.name]})")
        names[r.name] = r.where
        span = range(r.offset, r.offset + 4 * r.words, 4)
        for o in span:
            if o in offsets:
                raise DescError(f"{r.where}: register {r.name} at 0x{o:03X} overlaps {offsets[o]}")
            offsets[o] = r.name
        if not r.fields:
            raise DescError(f"{r.where}: register {r.name} has no field")
        if r.kind == "const" and any(
            not isinstance(x.msb, int) or x.reset == "-" for x in r.fields
        ):
            raise DescError(
                f"{r.where}: register of constants {r.name}: every field needs fixed bits "
                f"and a reset value"
            )
        ro = all(x.access == "RO" for x in r.fields)
        if (r.access == "RO") != ro:
            raise DescError(
                f"{r.where}: register {r.name} is {r.access} but its fields say "
                f"{'read only' if ro else 'writable'}"
            )
        if r.kind == "window" and r.size is None:
            raise DescError(f"{r.where}: window {r.name} has no 'size' line ({KINDS['size'][0]})")
        for f in r.fields:
            if f.mem is not None and f.hw is not None:
                raise DescError(f"{f.where}: field {f.name}: mem and hw: one writer of its word")
            if f.mem is not None and not any(
                x.kind == "window" and x.name == f.mem for x in blk.regs
            ):
                raise DescError(f"{f.where}: field {f.name}: mem {f.mem} is not a window")
            if f.clears is not None:
                target = next((x for x in blk.regs if x.name == f.clears), None)
                if target is None or not any(x.access == "W1C" for x in target.fields):
                    raise DescError(
                        f"{f.where}: field {f.name} clears {f.clears}, which has no W1C field"
                    )
            stem = f.port() if r.kind != "window" else r.name.lower()
            if stem in ports:
                raise DescError(
                    f"{f.where}: field {r.name}.{f.name}: its port name {stem} is also "
                    f"{ports[stem]}'s"
                )
            ports[stem] = f"{r.name}.{f.name}"
    params = blk.params()
    for p in params:
        if p in names or p == "APB_AW":
            raise DescError(f"{path}: parameter {p} has a register's or the block's own name")
    if blk.irq:
        (st, en, pend), where = blk.irq
        by = {r.name: r for r in blk.regs}
        if st not in by:
            raise DescError(f"{where}: irq: no register {st}")
        w1c = sorted(x.lsb for x in by[st].fields if x.access == "W1C")
        if (
            not w1c
            or w1c != list(range(len(w1c)))
            or any(x.width() != 1 for x in by[st].fields if x.access == "W1C")
        ):
            raise DescError(f"{where}: irq: {st}'s W1C fields must be one bit each, bits 0..n-1")
        for rf in (en, pend):
            reg, _, fld = rf.partition(".")
            f = next(
                (x for x in by.get(reg, Reg("", 0, "", "", "", 1, "")).fields if x.name == fld),
                None,
            )
            if f is None or f.width() != len(w1c):
                raise DescError(
                    f"{where}: irq: {rf} must be a field with one bit per W1C bit of {st} "
                    f"({len(w1c)})"
                )


def header(comment, lines):
    return "".join(f"{comment} {l}".rstrip() + "\n" for l in lines)


def provenance(blk):
    return [
        f"Generated by scripts/gen_apb_regs.py from {blk.path}: do not edit. Regenerate with",
        f"  {COMMAND}",
    ]


def reset_value(r):
    """The register's reset as a number (fields with a numeric reset), or None."""
    if all(isnum(f.reset) or f.reset == "-" for f in r.fields) and any(
        isnum(f.reset) for f in r.fields
    ):
        return sum(int(f.reset, 0) << f.lsb for f in r.fields if isnum(f.reset))
    return None


# ---- rtl/<owner>_regs.vh: the owner's view -------------------------------------------------------


def mem_read_port(s, desc, mem):
    """The owner's read strobe of a field kept in a window's memory (RO or RW alike)."""
    return (
        f"{s}_re_o",
        f"rg_{s}_re",
        "output",
        "",
        f"{desc}: read its word of {mem}'s memory now (a setup phase)",
    )


def owner_ports(blk):
    """The block's field ports: (port, wire, direction, Verilog range, comment)."""
    out = []
    for r in blk.regs:
        if r.kind == "window":
            w = r.name.lower()
            fw = r.fields[0].vwidth()
            kept = blk.mems(r)
            aw = f"{r.name}_ADDR_W"
            out += [
                (
                    f"{w}_re_o",
                    f"rg_{w}_re",
                    "output",
                    "",
                    f"{r.name}: read the word at the address",
                ),
                (
                    f"{w}_addr_o",
                    f"rg_{w}_addr",
                    "output",
                    f"[{aw}-1:0]",
                    f"{r.name}: the word index",
                ),
                (f"{w}_we_o", f"rg_{w}_we", "output", "", f"{r.name}: write the word"),
                (
                    f"{w}_wdata_o",
                    f"rg_{w}_wdata",
                    "output",
                    f"[{fw}-1:0]",
                    f"{r.name}: the word written",
                ),
                (
                    f"{w}_rdata_i",
                    f"rg_{w}_rdata",
                    "input",
                    "[31:0]" if kept else f"[{fw}-1:0]",
                    f"{r.name}: the word read, the clock after {w}_re_o"
                    + (
                        f" (its {fw} low bits; all 32 for "
                        + ", ".join(f"{f.reg.name}" for f in kept)
                        + ")"
                        if kept
                        else ""
                    ),
                ),
            ]
            if r.lock:
                out.append(
                    (
                        f"{w}_lock_i",
                        f"rg_{w}_lock",
                        "input",
                        "",
                        f"{r.name}: any access refused {r.lock}",
                    )
                )
            continue
        if r.kind == "const":
            continue
        for f in r.fields:
            s, d = f.port(), f.decl()
            desc = f"{r.name}.{f.name}"
            if f.access == "RW" and f.mem:
                out.append(mem_read_port(s, desc, f.mem))
                out.append((f"{s}_we_o", f"rg_{s}_we", "output", "", f"{desc}: write its word now"))
                out.append(
                    (f"{s}_wdata_o", f"rg_{s}_wdata", "output", "[31:0]", f"{desc}: the word")
                )
            elif f.access == "RW":
                out.append((f"{s}_o", f"rg_{s}", "output", d, f"{desc}: the value"))
                out.append(
                    (f"{s}_we_o", f"rg_{s}_we", "output", "", f"{desc}: written in this clock")
                )
                if f.hw:
                    out.append(
                        (f"{s}_hw_we_i", f"rg_{s}_hw_we", "input", "", f"{desc}: {f.hw} writes")
                    )
                    out.append(
                        (
                            f"{s}_hw_d_i",
                            f"rg_{s}_hw_d",
                            "input",
                            d,
                            f"{desc}: the value {f.hw} writes",
                        )
                    )
            elif f.access == "W1C":
                out.append((f"{s}_o", f"rg_{s}", "output", d, f"{desc}: the sticky value"))
                out.append(
                    (f"{s}_set_i", f"rg_{s}_set", "input", d, f"{desc}: set (wins over a clear)")
                )
            elif f.access == "W1" and f.clears is None:
                out.append((f"{s}_o", f"rg_{s}", "output", d, f"{desc}: a write of 1, this clock"))
            elif f.mem:
                out.append(mem_read_port(s, desc, f.mem))
                out.append(
                    (f"{s}_zero_i", f"rg_{s}_zero", "input", "", f"{desc}: no value yet, reads 0")
                )
            elif f.live():
                out.append((f"{s}_i", f"rg_{s}", "input", d, f"{desc}: the hardware's value"))
            if f.lock:
                out.append(
                    (f"{s}_lock_i", f"rg_{s}_lock", "input", "", f"{desc}: refused {f.lock}")
                )
    return out


def block_params(blk):
    """The block's parameters: (name, default, what), and what the owner passes for each."""
    out = [("APB_AW", str(blk.space.bit_length() - 1), "APB byte address width", "APB_AW")]
    for p, what in blk.params().items():
        if what == "width":
            out.append((p, "32", "a field's width (1..32)", p))
        elif what == "reset":
            out.append((p, "0", "a field's reset value", p))
        else:
            _, side, f = what
            # The default excludes nothing: the field's whole range.
            d = "0" if side == "lo" else str((1 << f.width()) - 1)
            out.append(
                (
                    p,
                    d,
                    (
                        f"the {'lowest' if side == 'lo' else 'highest'} value "
                        f"{f.reg.name}.{f.name} accepts"
                    ),
                    p,
                )
            )
    for r in blk.windows():
        out.append(
            (
                f"{r.name}_SIZE",
                str(r.words),
                f"the {r.name} window's words in use (1..{r.words})",
                r.size,
            )
        )
    for r in blk.regs:
        if r.kind == "const" and not all(isnum(f.reset) for f in r.fields):
            out.append((f"{r.name}_VALUE", "0", f"the value of {r.name}", f"{r.name}_VALUE"))
    return out


def gen_vh(blk):
    out = [
        "// SPDX-License-Identifier: MIT\n",
        header(
            "//",
            [
                *provenance(blk),
                (
                    f"The register map of {RTL}/{blk.owner}.v, included inside it "
                    "(after the parameters and"
                ),
                (
                    "localparams its registers read): <REG>_<FIELD> is a field's lsb, "
                    "<REG>_<FIELD>_W its width"
                ),
                "(fields wider than a bit); then a wire per port of its register block",
                f"({RTL}/{blk.owner}_regblock.v) and the block's instance u_regs.",
            ],
        ),
        "\n",
    ]
    plain = blk.plain()
    out.append("// Register word indices (byte address / 4).\n")
    for r in plain:
        out.append(f"localparam [5:0] R_{r.name} = 6'h{r.idx():02X};\n")
    ro = sum(1 << r.idx() for r in plain if not r.writable())
    wr = sum(1 << r.idx() for r in plain if r.writable())
    out.append(
        "// The registers the block answers, one bit per word index: read only, writable, either.\n"
    )
    out.append(f"localparam [63:0] REGS_RO = 64'h{ro:016X};\n")
    out.append(f"localparam [63:0] REGS_WR = 64'h{wr:016X};\n")
    out.append(f"localparam [63:0] REGS_ALL = 64'h{ro | wr:016X};\n")
    for w in blk.windows():
        out.append(
            f"// {w.name}: {w.words} words from byte 0x{w.offset:03X} (word index {w.idx()}); "
            f"{w.size} in use.\n"
        )
        out.append(f"localparam integer {w.name}_BASE = {w.offset};\n")
        out.append(f"localparam integer {w.name}_WORDS = {w.words};\n")
        out.append(f"localparam integer {w.name}_ADDR_W = ({w.size} > 1) ? $clog2({w.size}) : 1;\n")
    out.append("// Fields.\n")
    for f in blk.fields():
        w = f.width()
        line = f"localparam integer {f.lp()} = {f.lsb}"
        if w != 1:
            line += f", {f.lp()}_W = {w}"
        if f.frac is not None:
            line += f", {f.lp()}_F = {f.frac}"
        out.append(line + ";\n")
    ranged = [f for f in blk.fields() if f.range and all(isinstance(v, int) for v in f.range[:2])]
    if ranged:
        out.append("// Ranges (a write outside is refused).\n")
        for f in ranged:
            out.append(
                f"localparam integer {f.lp()}_MIN = {f.range[0]}, {f.lp()}_MAX = {f.range[1]};\n"
            )
    out.append("// Reset values of the writable registers (fields with a constant reset).\n")
    for r in plain:
        if r.writable() and all(isnum(f.reset) for f in r.fields):
            out.append(f"localparam [31:0] {r.name}_RESET = 32'h{reset_value(r):08X};\n")
    consts = [r for r in blk.regs if r.kind == "const"]
    if consts:
        out.append("// The registers of constants (the owner's parameters).\n")
    for r in consts:
        terms = []
        for f in r.fields:
            if isnum(f.reset):
                terms.append(f"(32'h{int(f.reset, 0):X} << {f.lp()})")
            else:
                terms.append(f"((({f.reset}) & 32'h{(1 << f.width()) - 1:X}) << {f.lp()})")
        out.append(f"localparam [31:0] {r.name}_VALUE =\n    " + " |\n    ".join(terms) + ";\n")
    # The block's instance and its wires.
    ports = owner_ports(blk)
    out.append(f"\n// ---- the register block ({RTL}/{blk.owner}_regblock.v) ----\n")
    out.append(
        "// APB: the owner drives rg_psel (its PSEL for the block's addresses) "
        "and returns rg_prdata\n"
        "// (zero unless the block answers a read) and rg_pslverr; PREADY is always high.\n"
    )
    out.append("wire rg_psel;\nwire [31:0] rg_prdata;\nwire rg_pslverr;\n")
    out.append("// A wire per field port: the owner drives the inputs (live values, set, lock).\n")
    for _port, wire, dirn, rng, comment in ports:
        out.append(
            f"wire {rng + ' ' if rng else ''}{wire};  // "
            f"{'in: ' if dirn == 'input' else ''}{comment}\n"
        )
    params = block_params(blk)
    out.append(f"{blk.owner}_regblock #(\n")
    out.append(",\n".join(f"  .{p}({v})" for p, _, _, v in params) + "\n")
    out.append(") u_regs (\n")
    conns = [
        "clk_i(clk_i)",
        "rst_i(rst_i)",
        "psel_i(rg_psel)",
        "penable_i(penable_i)",
        "pwrite_i(pwrite_i)",
        "paddr_i(paddr_i)",
        "pwdata_i(pwdata_i)",
        "pstrb_i(pstrb_i)",
        "prdata_o(rg_prdata)",
        "pslverr_o(rg_pslverr)",
    ] + [f"{p}({w})" for p, w, _, _, _ in ports]
    out.append(",\n".join(f"  .{c}" for c in conns) + "\n);\n")
    return "".join(out)


# ---- rtl/<owner>_regblock.v: the register block --------------------------------------------------


def decode_bits(idx, others):
    """The fewest bits of a 6-bit word index that tell idx from every index of others."""
    for size in range(7):
        for bits in itertools.combinations(range(6), size):
            if all(any((idx ^ x) >> b & 1 for b in bits) for x in others):
                return bits
    raise ValueError(f"index {idx} is among the others")


def const_gt(x, w, c):
    """A Verilog expression: the w-bit x > the constant c (None when it cannot be)."""
    if c >= (1 << w) - 1:
        return None
    if c < 0:
        return "1'b1"
    terms = []
    for i in range(w):
        if not c >> i & 1:
            hi = f" & ({x}[{w - 1}:{i + 1}] == {w - 1 - i}'d{c >> (i + 1)})" if i < w - 1 else ""
            terms.append(f"({x}[{i}]{hi})")
    return "(" + " | ".join(terms) + ")"


def const_lt(x, w, c):
    """A Verilog expression: the w-bit x < the constant c (None when it cannot be)."""
    if c <= 0:
        return None
    if c > (1 << w) - 1:
        return "1'b1"
    terms = []
    for i in range(w):
        if c >> i & 1:
            hi = f" & ({x}[{w - 1}:{i + 1}] == {w - 1 - i}'d{c >> (i + 1)})" if i < w - 1 else ""
            terms.append(f"(~{x}[{i}]{hi})")
    return "(" + " | ".join(terms) + ")"


def gen_regblock(blk):
    mod = f"{blk.owner}_regblock"
    plain, wins = blk.plain(), blk.windows()
    params = block_params(blk)
    ports = owner_ports(blk)
    o = [
        "// SPDX-License-Identifier: MIT\n",
        header(
            "//",
            provenance(blk)
            + textwrap.wrap(
                f"{mod}: the registers of {RTL}/{blk.owner}.v ({blk.doc}), an APB4 slave. It "
                "decodes the address and reads in the setup phase (PSEL && !PENABLE), so the "
                "access phase returns registered data (a window's word from the owner's memory, "
                "read the clock after the setup phase) with zero wait states; a write takes effect "
                "at the end of its access phase. PSLVERR (with PRDATA 0 and no effect) answers: an "
                "address outside the map or not word-aligned, a write with PSTRB other than "
                "4'b1111, a write to a read-only register, a value outside its field's range, and "
                "a locked field or window (decided in the setup phase). The owner keeps the "
                "behaviour: it drives the live values, the W1C set inputs and the locks, and uses "
                "the values, the strobes and the W1 pulses.",
                96,
            ),
        ),
        "`resetall\n`default_nettype none\n\n",
        f"module {mod} #(\n",
    ]
    o.append(
        ",\n".join(
            f"  // {what}\n  parameter integer {p} = {d}"
            if not p.endswith("_VALUE")
            else f"  // {what}\n  parameter [31:0] {p} = 32'h0"
            for p, d, what, _ in params
        )
    )
    o.append(
        "\n) (\n  input  wire clk_i,\n"
        "  // Synchronous, active high: every flop to its reset value.\n"
        "  input  wire rst_i,\n  // APB4 slave (PREADY is the owner's: always high).\n"
        "  input  wire psel_i,\n  input  wire penable_i,\n  input  wire pwrite_i,\n"
        "  input  wire [APB_AW-1:0] paddr_i,\n  input  wire [31:0] pwdata_i,\n"
        "  input  wire [3:0] pstrb_i,\n  output wire [31:0] prdata_o,\n  output wire pslverr_o"
    )
    for port, _, dirn, rng, comment in ports:
        # (A port's range cannot name the body's localparams: the window's address width inline.)
        rng = re.sub(r"\[(\w+)_ADDR_W-1:0\]", r"[((\1_SIZE > 1) ? $clog2(\1_SIZE) : 1)-1:0]", rng)
        o.append(
            f",\n  // {comment}\n  {dirn + ' ' if dirn == 'input' else dirn} wire "
            f"{rng + ' ' if rng else ''}{port}"
        )
    o.append("\n);\n\n")
    # Localparams.
    o.append("  // Word indices (byte address / 4), the register sets, field positions.\n")
    for r in plain:
        o.append(f"  localparam [5:0] R_{r.name} = 6'h{r.idx():02X};\n")
    ro = sum(1 << r.idx() for r in plain if not r.writable())
    wr = sum(1 << r.idx() for r in plain if r.writable())
    o.append(
        f"  localparam [63:0] REGS_RO = 64'h{ro:016X};\n"
        f"  localparam [63:0] REGS_WR = 64'h{wr:016X};\n"
    )
    for f in blk.fields():
        if f.reg.kind == "reg" and not f.mem:
            o.append(f"  localparam integer {f.lp()} = {f.lsb};\n")
    for w in wins:
        o.append(
            f"  localparam integer {w.name}_ADDR_W = ({w.name}_SIZE > 1) ? "
            f"$clog2({w.name}_SIZE) : 1;\n"
        )
    for r in blk.regs:
        if r.kind == "const" and all(isnum(f.reset) for f in r.fields):
            v = sum(int(f.reset, 0) << f.lsb for f in r.fields)
            o.append(f"  localparam [31:0] {r.name}_VALUE = 32'h{v:08X};\n")
    wregs = [r for r in plain if r.writable()]
    stored = [f for r in wregs for f in r.fields if f.access in ("RW", "W1C") and not f.mem]
    rst_lps = [f for f in stored if not isnum(f.reset) or not isinstance(f.width(), int)]
    if rst_lps:
        o.append(
            "  // Reset values of fields whose reset or width is a parameter "
            "(the field's low bits).\n"
        )
    for f in rst_lps:
        v = f.reset if not isnum(f.reset) else str(int(f.reset, 0))
        o.append(f"  localparam [31:0] {f.port().upper()}_RST = {v};\n")
    # Parameter rules.
    top = max([r.offset + 4 * r.words for r in blk.regs] + [0x100])
    min_aw = (top - 1).bit_length()
    o.append("\n  // Parameter rules (rtl/acore_check.v: they stop Verilator, Icarus and Yosys).\n")
    o.append(
        f"  acore_check #(.OK(APB_AW >= {min_aw} && APB_AW <= 32), .VALUE(APB_AW),\n"
        f'    .MSG("illegal parameter: APB_AW must be {min_aw}..32 (the map reaches '
        f'0x{top - 1:03X})"))\n'
        f"    APB_AW_must_be_{min_aw}_to_32 ();\n"
    )
    for p, _d, what, _ in params:
        if what.startswith("a field's width"):
            o.append(
                f"  acore_check #(.OK({p} >= 1 && {p} <= 32), .VALUE({p}),\n"
                f'    .MSG("illegal parameter: {p} must be 1..32 (a field\'s width)"))\n'
                f"    {p}_must_be_1_to_32 ();\n"
            )
    for w in wins:
        o.append(
            f"  acore_check #(.OK({w.name}_SIZE >= 1 && {w.name}_SIZE <= {w.words}), "
            f".VALUE({w.name}_SIZE),\n"
            f'    .MSG("illegal parameter: {w.name}_SIZE must be 1..{w.words} (the '
            f'{w.name} window)"))\n'
            f"    {w.name}_SIZE_must_be_1_to_{w.words} ();\n"
        )
    for f in blk.fields():
        if f.range and not all(isinstance(v, int) for v in f.range[:2]):
            lo, hi, _ = f.range
            mx = (1 << f.width()) - 1
            rule = f.reg.name if len(f.reg.fields) == 1 else f.port().upper()
            o.append(
                f"  acore_check #(.OK({lo} >= 0 && {lo} <= {hi} && {hi} <= {mx}), .VALUE({hi}),\n"
                f'    .MSG("illegal parameter: {lo}..{hi} must lie in 0..{mx}"))\n'
                f"    {rule}_range_must_lie_in_0_to_{mx} ();\n"
            )
    # The fields' flops (RW and W1C).
    o.append("\n  // The fields' flops (RW values and W1C sticky bits).\n")
    for f in stored:
        o.append(f"  reg {f.decl() + ' ' if f.decl() else ''}{f.port()}_q;\n")
    # Decode.
    o.append(
        "\n  // ---- decode and read in the setup phase ----\n"
        "  wire setup = psel_i & ~penable_i;\n"
        + ("  wire access = psel_i & penable_i;\n" if wins else "")
        + "  wire [5:0] ridx = paddr_i[7:2];\n"
        "  wire in_regs = (paddr_i[APB_AW-1:8] == {(APB_AW-8){1'b0}});\n"
    )
    for w in wins:
        n, lw = w.name, w.name.lower()
        aw = w.words.bit_length() + 1  # byte address bits of the window
        o.append(
            f"  // {n}: address bits [{aw - 1}:2] index a word, the bits above select the window.\n"
            "  // (The width is kept positive for an illegal APB_AW, so that "
            "its rule reports it.)\n"
            f"  localparam integer {n}_SEL_W = (APB_AW > {aw}) ? APB_AW - {aw} : 1;\n"
            f"  localparam integer {n}_SEL_I = {w.offset} >> {aw};\n"
            f"  localparam [{n}_SEL_W-1:0] {n}_SEL = {n}_SEL_I[{n}_SEL_W-1:0];\n"
            f"  wire [{aw - 3}:0] {lw}_idx = paddr_i[{aw - 1}:2];\n"
            f"  // (The words present as a table, bit a for word a: a function of the index's bits,\n"  # noqa: E501
            "  // where a comparison with the size would take a carry chain.)\n"
            f"  localparam [{w.words - 1}:0] {n}_HAS = ~({{{w.words}{{1'b1}}}} << {n}_SIZE);\n"
            f"  wire in_{lw} = (paddr_i[APB_AW-1:{aw}] == {n}_SEL) && {n}_HAS[{lw}_idx];\n"
        )
    o.append(
        "  wire is_ro = REGS_RO[ridx];\n  wire is_rw = REGS_WR[ridx];\n"
        "  wire reg_ok = in_regs & (is_rw | (is_ro & ~pwrite_i));\n"
    )
    # Selects: an error-free transfer's address is one of the map's, so a register is told from
    # the others of its kind (read: every register; write: the writable ones) by the fewest
    # word-index bits; any other address is an error, which loads no data and changes nothing.
    wregs = [r for r in plain if r.writable()]
    o.append(
        "  // Selects: the fewest word-index bits that tell a register from the others it can\n"
        "  // be (an error-free read: any register; an error-free write: a writable one). Every\n"
        "  // other address is an error: it reads 0 and writes nothing, the selects ignore it.\n"
    )
    for kind, regs in (("rs", plain), ("ws", wregs)):
        for r in regs:
            mask = sum(1 << b for b in decode_bits(r.idx(), [x.idx() for x in regs if x is not r]))
            o.append(
                f"  wire {kind}_{r.name.lower()} = "
                f"(ridx & 6'h{mask:02X}) == (R_{r.name} & 6'h{mask:02X});\n"
            )
    # Locks, per register and window.
    lock_terms, reg_lock = [], {}
    for r in plain:
        terms = []
        for f in r.fields:
            if f.lock:
                s = f.port()
                if f.access == "W1":
                    sel = (
                        f"pwdata_i[{f.lp()}]"
                        if f.width() == 1
                        else f"(|pwdata_i[{f.lp()} +: {f.width()}])"
                    )
                    terms.append(f"{s}_lock_i & {sel}")
                else:
                    terms.append(f"{s}_lock_i")
        if terms:
            reg_lock[r.name] = (
                " | ".join(terms) if len(terms) == 1 else " | ".join(f"({t})" for t in terms)
            )
            lock_terms.append(f"(ws_{r.name.lower()} & ({reg_lock[r.name]}))")
    win_lock = [f"(in_{w.name.lower()} & {w.name.lower()}_lock_i)" for w in wins if w.lock]
    if lock_terms or win_lock:
        o.append(
            "  // Refused while the owner locks them: a window's any access, a register's write.\n"
        )
        terms = win_lock + (
            ["(in_regs & pwrite_i & (" + " |\n        ".join(lock_terms) + "))"]
            if lock_terms
            else []
        )
        o.append("  wire lock_err = " + " |\n      ".join(terms) + ";\n")
    # Ranges: logic on the written word's bits, no comparator (a constant bound is a sum of
    # products of the bits; a parameter's, a table of the field's values when the field is
    # narrow).
    range_terms = {}
    for r in plain:
        for f in r.fields:
            if not f.range:
                continue
            lo, hi, word = f.range
            s = f.port()
            w = f.width()
            val = f"pwdata_i[{f.lp()} +: {w}]"
            o.append(f"  // {r.name}.{f.name}: {lo}..{hi}{' (the whole word)' if word else ''}.\n")
            o.append(f"  wire [{w - 1}:0] {s}_wr = {val};\n")
            bad = []
            if word and f.lsb + w < 32:
                # (the bounds lie within the field: any bit above it set is outside)
                bad.append(f"(|pwdata_i[31:{f.lsb + w}])")
            if isinstance(lo, int) and isinstance(hi, int):
                bad += [t for t in (const_lt(f"{s}_wr", w, lo), const_gt(f"{s}_wr", w, hi)) if t]
            else:
                if w > 8:
                    raise DescError(
                        f"{f.where}: field {f.name}: a range set by parameters needs a field of at "
                        "most 8 bits (its values' table)"
                    )
                lp = f"{s.upper()}"
                o.append(
                    f"  localparam integer {lp}_LO = {lo};\n  localparam integer {lp}_HI = {hi};\n"
                    f"  // Its values' table: bit v is 1 when v is outside {lo}..{hi}.\n"
                    f"  wire [{(1 << w) - 1}:0] {s}_out;\n"
                    f"  genvar {s}_v;\n  generate\n"
                    f"    for ({s}_v = 0; {s}_v < {1 << w}; {s}_v = {s}_v + 1) begin : g_{s}_out\n"
                    f"      assign {s}_out[{s}_v] = ({s}_v < {lp}_LO) || ({s}_v > {lp}_HI);\n"
                    f"    end\n  endgenerate\n"
                )
                bad.append(f"{s}_out[{s}_wr]")
            o.append(f"  wire {s}_bad = {' | '.join(bad) if bad else chr(49) + chr(39) + 'b0'};\n")
            range_terms.setdefault(r.name, []).append(f"{s}_bad")
    if range_terms:
        o.append(
            "  wire range_err = in_regs & pwrite_i & (\n      "
            + " |\n      ".join(
                f"(ws_{n.lower()} & ({' | '.join(t)}))" for n, t in range_terms.items()
            )
            + ");\n"
        )
    err = [
        "(paddr_i[1:0] != 2'b00)",
        "(pwrite_i & (pstrb_i != 4'hF))",
        "~"
        + (
            "(reg_ok" + "".join(f" | in_{w.name.lower()}" for w in wins) + ")" if wins else "reg_ok"
        ),
    ]
    if lock_terms or win_lock:
        err.append("lock_err")
    if range_terms:
        err.append("range_err")
    o.append("  wire err_d = " + " |\n      ".join(err) + ";\n")
    # Read mux: an AND-OR of the selects over each register's bits.
    o.append(
        "\n  // Each register's fields at their positions, zero elsewhere (W1 fields read 0),\n"
        "  // and the read data: the OR of the selected register's (an AND-OR over the bits each\n"
        "  // has).\n"
    )
    words = []
    body = []
    for r in plain:
        lr = r.name.lower()
        if r.kind == "const":
            words.append(f"({{32{{rs_{lr}}}}} & {r.name}_VALUE)")
            continue
        items = []
        for f in r.fields:
            if f.access == "W1" or f.mem:
                continue
            src = f"{f.port()}_i" if f.live() else f"{f.port()}_q"
            if f.width() == 1:
                items.append(f"rv_{lr}[{f.lp()}] = {src};")
            else:
                items.append(f"rv_{lr}[{f.lp()} +: {f.vwidth()}] = {src};")
        if items:
            body.append((lr, items))
            words.append(f"({{32{{rs_{lr}}}}} & rv_{lr})")
    if body:
        o.append(
            "".join(f"  reg [31:0] rv_{lr};\n" for lr, _ in body)
            + "  always @(*) begin\n"
            + "".join(
                f"    rv_{lr} = 32'd0;\n" + "".join(f"    {i}\n" for i in items)
                for lr, items in body
            )
            + "  end\n"
        )
    o.append("  wire [31:0] rd_d =\n      " + (" |\n      ".join(words) or "32'd0") + ";\n")
    for w in wins:
        kept = blk.mems(w)
        if not kept:
            continue
        lw = w.name.lower()
        o.append(
            f"  // Registers kept in {w.name}'s memory: read through its port (their words the\n"
            "  // owner's), 0 while the owner has no value for them.\n"
            f"  wire mem_{lw}_sel = in_regs & ("
            + " | ".join(
                f"rs_{f.reg.name.lower()}"
                if f.access == "RW"
                else f"(rs_{f.reg.name.lower()} & ~{f.port()}_zero_i)"
                for f in kept
            )
            + ");\n"
        )
    # Setup flops.
    o.append(
        "\n  // Setup phase: the answer and which register an error-free write will change,\n"
        "  // each a flop set only by a setup phase and clear in every other clock. Under the\n"
        "  // APB4 protocol the access phase is the clock after the setup phase, so these flops\n"
        "  // are the access phase's PRDATA (0 unless an error-free read), PSLVERR and write\n"
        "  // enables as they are: no gate after them, the address decode off the data\n"
        "  // registers' enables.\n"
        "  wire ok = setup & ~err_d;\n"
        "  wire ok_wr = ok & pwrite_i;\n"
        "  wire ok_rd = ok & ~pwrite_i" + (" & in_regs" if wins else "") + ";\n"
    )
    flops = (
        ["err_q"]
        + [f"win_{w.name.lower()}_q" for w in wins]
        + [f"mem_{w.name.lower()}_q" for w in wins if blk.mems(w)]
        + [f"w_{r.name.lower()}_q" for r in wregs]
        + [f"w_{w.name.lower()}_q" for w in wins]
    )
    o.append(
        "".join(f"  reg {', '.join(flops[i : i + 6])};\n" for i in range(0, len(flops), 6))
        + "  reg [31:0] rdata_q;\n"
    )
    o.append(
        "  always @(posedge clk_i) begin\n"
        "    if (rst_i) begin\n      err_q <= 1'b0;\n      rdata_q <= 32'd0;\n"
    )
    for fl in flops[1:]:
        o.append(f"      {fl} <= 1'b0;\n")
    o.append(
        "    end else begin\n      err_q <= setup & err_d;\n"
        "      rdata_q <= ok_rd ? rd_d : 32'd0;\n"
    )
    for w in wins:
        lw = w.name.lower()
        if blk.mems(w):
            o.append(
                f"      win_{lw}_q <= ok & ~pwrite_i & (in_{lw} | mem_{lw}_sel);\n"
                f"      mem_{lw}_q <= ok_rd & mem_{lw}_sel;\n"
            )
        else:
            o.append(f"      win_{lw}_q <= ok & ~pwrite_i & in_{lw};\n")
    for r in wregs:
        o.append(f"      w_{r.name.lower()}_q <= ok_wr & in_regs & ws_{r.name.lower()};\n")
    for w in wins:
        lw = w.name.lower()
        o.append(f"      w_{lw}_q <= ok_wr & in_{lw};\n")
    o.append("    end\n  end\n")
    # Access phase.
    o.append("\n  // ---- the access phase ----\n")
    rd = "rdata_q"
    for w in wins:
        fw = w.fields[0].vwidth()
        lw = w.name.lower()
        if blk.mems(w):
            # (the window's words: their field's low bits; a kept register's: all 32. A kept
            # register's read sets mem_q with win_q, so the bits above the field need only
            # mem_q: one input fewer where the read data's OR takes another block's.)
            rd += (
                f" | ((({{32{{win_{lw}_q}}}} & ~({{32{{1'b1}}}} << {fw})) |"
                f" ({{32{{mem_{lw}_q}}}} & ({{32{{1'b1}}}} << {fw}))) & {lw}_rdata_i)"
            )
            continue
        pad = f"{{{{(32-{fw}){{1'b0}}}}, {lw}_rdata_i}}" if fw != "32" else f"{lw}_rdata_i"
        rd += f" | ({{32{{win_{lw}_q}}}} & {pad})"
    o.append(f"  assign prdata_o = {rd};\n  assign pslverr_o = err_q;\n")
    for w in wins:
        lw, fw = w.name.lower(), w.fields[0].vwidth()
        o.append(
            f"  // {w.name}: every setup phase reads the word (used only for a read "
            "of the window): the\n"
            "  // address decode stays off the memory's read enable; its write enable is gated\n"
            "  // by the access phase (the memory is the owner's).\n"
            f"  assign {lw}_re_o = setup;\n  assign {lw}_addr_o = {lw}_idx[{w.name}_ADDR_W-1:0];\n"
            f"  assign {lw}_we_o = access & w_{lw}_q;\n"
            f"  assign {lw}_wdata_o = pwdata_i[{fw}-1:0];\n"
        )
    for f in blk.fields():
        if f.mem:
            o.append(
                f"  assign {f.port()}_re_o = setup & ~pwrite_i & in_regs & "
                f"rs_{f.reg.name.lower()};\n"
            )
    for r in wregs:
        o.append(f"  wire wr_{r.name.lower()} = w_{r.name.lower()}_q;\n")
    clears = {}
    for r in wregs:
        for f in r.fields:
            sel = (
                f"pwdata_i[{f.lp()}]" if f.width() == 1 else f"(|pwdata_i[{f.lp()} +: {f.width()}])"
            )
            if f.access == "W1" and f.clears:
                clears.setdefault(f.clears, []).append(f"(wr_{r.name.lower()} & {sel})")
            elif f.access == "W1":
                o.append(f"  assign {f.port()}_o = wr_{r.name.lower()} & {sel};\n")
    for reg, terms in clears.items():
        o.append(f"  wire clear_{reg.lower()} = {' | '.join(terms)};\n")
    # Flops.
    o.append("  always @(posedge clk_i) begin\n    if (rst_i) begin\n")
    for f in stored:
        if isnum(f.reset):
            v = int(f.reset, 0)
            o.append(
                f"      {f.port()}_q <= {f.vwidth()}'d{v};\n"
                if isinstance(f.width(), int)
                else f"      {f.port()}_q <= {f.port().upper()}_RST[{f.vwidth()}-1:0];\n"
            )
        else:
            o.append(f"      {f.port()}_q <= {f.port().upper()}_RST[{f.vwidth()}-1:0];\n")
    o.append("    end else begin\n")
    for r in wregs:
        rw = [f for f in r.fields if f.access == "RW" and not f.mem]
        if rw:
            o.append(f"      if (wr_{r.name.lower()}) begin\n")
            for f in rw:
                src = (
                    f"pwdata_i[{f.lp()}]"
                    if f.width() == 1
                    else f"pwdata_i[{f.lp()} +: {f.vwidth()}]"
                )
                o.append(f"        {f.port()}_q <= {src};\n")
            o.append("      end\n")
            for f in rw:
                if f.hw:
                    o.append(
                        f"      if ({f.port()}_hw_we_i && !wr_{r.name.lower()}) "
                        f"{f.port()}_q <= {f.port()}_hw_d_i;\n"
                    )
        for f in r.fields:
            if f.access != "W1C":
                continue
            s, w = f.port(), f.width()
            src = f"pwdata_i[{f.lp()}]" if w == 1 else f"pwdata_i[{f.lp()} +: {w}]"
            clr = (
                f"({{{w}{{wr_{r.name.lower()}}}}} & {src})"
                if w != 1
                else f"(wr_{r.name.lower()} & {src})"
            )
            if r.name in clears:
                clr += (
                    f" | {{{w}{{clear_{r.name.lower()}}}}}"
                    if w != 1
                    else f" | clear_{r.name.lower()}"
                )
            o.append(f"      {s}_q <= ({s}_q & ~({clr})) | {s}_set_i;\n")
    o.append("    end\n  end\n")
    for f in stored:
        o.append(f"  assign {f.port()}_o = {f.port()}_q;\n")
        if f.access == "RW":
            o.append(f"  assign {f.port()}_we_o = wr_{f.reg.name.lower()};\n")
    for f in blk.fields():
        if f.mem and f.access == "RW":
            o.append(
                f"  assign {f.port()}_we_o = wr_{f.reg.name.lower()};\n"
                f"  assign {f.port()}_wdata_o = pwdata_i;\n"
            )
    o.append("\nendmodule\n\n`resetall\n")
    return "".join(o)


# ---- C++ -----------------------------------------------------------------------------------------


def camel(name):
    return "".join(p.capitalize() for p in name.lower().split("_"))


def cpp_comment(text, indent=""):
    """A // comment wrapped below 100 columns (clang-format leaves it as it is)."""
    return "".join(f"{indent}// {l}\n" for l in textwrap.wrap(text, 96 - len(indent)))


def gen_hpp(blk):
    out = [
        "// SPDX-License-Identifier: MIT\n",
        header(
            "//",
            [
                *provenance(blk),
                (
                    f"The register map of {RTL}/{blk.owner}.v ({blk.doc}): byte "
                    "addresses and bit fields. A"
                ),
                (
                    "one-bit field is its mask; a wider one has <Field>Shift, and with "
                    "fixed bits <Field>Mask"
                ),
                "(in place) and <Field>Bits; a range gives <Field>Min and <Field>Max, fixed point",
                "<Field>Frac (fraction bits).",
            ],
        ),
        f"#pragma once\n#include <cstdint>\n\nnamespace {blk.namespace} {{\n\n",
        "// The address space the default APB_AW decodes.\n",
        f"constexpr uint32_t kAddrSpace = 0x{blk.space:X};\n",
    ]
    for r in blk.regs:
        what = (
            f"{r.words} words, word a at 0x{r.offset:03X} + 4a" if r.kind == "window" else r.access
        )
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
                    out.append(f"constexpr uint32_t {c}Mask = 0x{f.mask():X}u;\n")
                    out.append(f"constexpr int {c}Bits = {w};\n")
            if f.range:
                lo, hi, _word = f.range
                if isinstance(lo, int) and isinstance(hi, int):
                    out.append(
                        f"constexpr int64_t {c}Min = {lo};\nconstexpr int64_t {c}Max = {hi};\n"
                    )
                else:
                    out.append(
                        f"// (Its range {lo}..{hi} is set by parameters of {RTL}/{blk.owner}.v.)\n"
                    )
            if f.frac is not None:
                out.append(f"constexpr int {c}Frac = {f.frac};\n")
        if r.kind == "const" and all(isnum(f.reset) for f in r.fields):
            out.append(
                f"constexpr uint32_t k{camel(r.name)}Value = "
                f"0x{sum(int(f.reset, 0) << f.lsb for f in r.fields):X}u;\n"
            )
        if r.kind == "reg" and r.writable() and reset_value(r) is not None:
            out.append(f"constexpr uint32_t k{camel(r.name)}Reset = 0x{reset_value(r):X}u;\n")
        if r.kind == "reg" and r.writable() and all(isinstance(f.width(), int) for f in r.fields):
            out.append("// The bits that read back.\n")
            rdm = sum(f.mask() for f in r.fields if f.access != "W1")
            out.append(f"constexpr uint32_t k{camel(r.name)}ReadMask = 0x{rdm:X}u;\n")
            w1c = sum(f.mask() for f in r.fields if f.access == "W1C")
            if w1c:
                out.append("// The sticky bits.\n")
                out.append(f"constexpr uint32_t k{camel(r.name)}W1cMask = 0x{w1c:X}u;\n")
    out.append(f"\n}}  // namespace {blk.namespace}\n")
    return "".join(out)


# ---- the doc page --------------------------------------------------------------------------------


def md_escape(text):
    return text.replace("|", "\\|")


def fmt_frac(f):
    top = ((1 << f.width()) - 1) / (1 << f.frac)
    return f"{top:g}"


def field_meaning(f):
    text = f.meaning
    if f.range:
        lo, hi, word = f.range
        text += (
            " Range "
            f"{lo}..{hi}{' (the whole word: the bits above the field must be 0)' if word else ''}: "
            "a write outside it is an error without effect."
        )
    if f.frac is not None:
        text += f" Unsigned, {f.frac} fraction bits (0..{fmt_frac(f)})."
    if f.lock:
        text += (
            f" A write {'of 1 ' if f.access == 'W1' else ''}is an error without effect {f.lock}."
        )
    if f.hw:
        text += f" Also written by {f.hw} (an APB write in the same clock wins)."
    if f.mem:
        text += f" Kept in a word of the {f.mem} window's memory (read with zero wait states)."
    return text


def gen_md(blk):
    aw = blk.space.bit_length() - 1
    out = [
        f"# {blk.title}\n\n",
        (
            f"<!-- Generated by scripts/gen_apb_regs.py from {blk.path}: do not "
            "edit. Regenerate with\n"
            f"     {COMMAND} -->\n\n"
        ),
    ]
    for p in blk.intro:
        out.append(p + "\n\n")
    out.append(
        f"Byte addresses; 32-bit registers, 32-bit accesses only (an APB_AW of {aw} decodes "
        f"0x000..0x{blk.space - 1:03X}); the registers are `{RTL}/{blk.owner}_regblock.v`, "
        f"generated with this page. Access: "
        + "; ".join(f"{k} {v[0]}" for k, v in ACCESS.items())
        + ". A reset that names a "
        "parameter is the build's value; `-` is live state.\n\n"
    )
    out.append("| address | register | access | reset | summary |\n|---|---|---|---|---|\n")
    for r in blk.regs:
        addr = f"0x{r.offset:03X} + 4a" if r.kind == "window" else f"0x{r.offset:03X}"
        name = f"{r.name}\\[a\\]" if r.kind == "window" else r.name
        consts = [f for f in r.fields if isnum(f.reset)]
        if r.kind != "window" and len(consts) == len(r.fields):
            reset = f"0x{sum(int(f.reset, 0) << f.lsb for f in r.fields):08X}"
        elif reset_value(r) is not None:
            reset = f"0x{reset_value(r):08X}"
        elif all(f.reset == "-" for f in r.fields):
            reset = "-"
        elif len(r.fields) == 1:
            reset = r.fields[0].reset
        else:
            reset = "parameters"
        out.append(
            f"| {addr} | [{name}](#{r.name.lower()}) | {r.access} | {reset} | "
            f"{md_escape(r.summary)} |\n"
        )
    for r in blk.regs:
        addr = (
            f"0x{r.offset:03X} + 4a, a < {r.size} (at most {r.words})"
            if r.kind == "window"
            else f"0x{r.offset:03X}"
        )
        lock = f" Any access is an error without effect {r.lock}." if r.lock else ""
        out.append(f"\n## {r.name}\n\n{addr}, {r.access}. {md_escape(r.summary)}{lock}\n\n")
        out.append("| bits | field | access | reset | meaning |\n|---|---|---|---|---|\n")
        for f in sorted(r.fields, key=lambda x: -x.lsb if isinstance(x.msb, int) else 0):
            out.append(
                f"| {f.bits()} | {f.name} | {f.access} | {f.reset} | "
                f"{md_escape(field_meaning(f))} |\n"
            )
    if blk.irq:
        (st, en, pend), _ = blk.irq
        out.append(
            f"\n## Interrupts\n\n{st}'s W1C bits, their enables {en} and the pending bits {pend} "
            f"share positions (bit i of each is the same event).\n"
        )
    if blk.notes:
        out.append("\n## Transfers and errors\n\n")
        out.append("\n\n".join(blk.notes) + "\n")
    return "".join(out)


def generate(root, rel):
    blk = parse(root, rel)
    return {
        f"{RTL}/{blk.owner}_regs.vh": gen_vh(blk),
        f"{RTL}/{blk.owner}_regblock.v": gen_regblock(blk),
        blk.cpp: gen_hpp(blk),
        blk.doc: gen_md(blk),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    )
    ap.add_argument("--out", help="write under this directory instead of ROOT")
    ap.add_argument("--check", metavar="DIR", help="write under DIR and compare with ROOT's files")
    ap.add_argument(
        "--syntax", action="store_true", help="print the line kinds and the access types"
    )
    ap.add_argument("desc", nargs="*", help="descriptions (default: every rtl/*_regs.txt)")
    args = ap.parse_args()
    if args.syntax:
        for syn, what in KINDS.values():
            print(f"{syn:44s} {what}")
        for k, (name, hw) in ACCESS.items():
            print(f"{k:4s} {name}: {hw}")
        return 0
    descs = args.desc or sorted(
        os.path.relpath(p, args.root) for p in glob.glob(os.path.join(args.root, RTL, "*_regs.txt"))
    )
    if not descs:
        print("gen_apb_regs.py: no description (rtl/*_regs.txt)", file=sys.stderr)
        return 2
    files = {}
    try:
        for d in descs:
            for rel, text in generate(args.root, d).items():
                if rel in files:
                    raise DescError(f"{d}: {rel} is also another description's output")
                files[rel] = (text, d)
    except (DescError, OSError) as e:
        print(f"gen_apb_regs.py: {e}", file=sys.stderr)
        return 2
    out = args.check or args.out or args.root
    for rel, (text, _) in files.items():
        path = os.path.join(out, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    if not args.check:
        print(f"wrote {', '.join(os.path.join(out, r) for r in files)}")
        return 0
    differ = 0
    for rel, (text, d) in files.items():
        mine = os.path.join(args.root, rel)
        have = open(mine).read() if os.path.exists(mine) else ""
        if have != text:
            differ += 1
            print(f"FAIL {rel} differs from {d} (regenerate: {COMMAND}):")
            sys.stdout.writelines(
                difflib.unified_diff(
                    have.splitlines(True),
                    text.splitlines(True),
                    rel,
                    os.path.join(args.check, rel),
                    n=1,
                )
            )
        else:
            print(f"ok   {rel} is {d}'s")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
