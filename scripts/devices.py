#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The devices table synth/devices.toml (synthesis families and FPGA devices), read by every
synthesis and report script through this one reader; its header documents the fields.

usage: devices.py [--root DIR] list
         one line per family and device: "family NAME synth OPTIONS..." / "device NAME family part
         package" (the table checked)
Exit 2 on a malformed table (file, line and field named).
"""

import functools
import glob
import os
import re
import shutil
import sys
import tempfile

import tomllib

PATH = os.path.join("synth", "devices.toml")
NAME = r"[a-z][a-z0-9_]*"
CAPACITY = ("logic_cells", "luts", "ffs", "bram_blocks", "bram_bits", "dsp", "user_io")
FLOW_FIELDS = {"default_device": str, "freq_mhz": int, "seed": int, "yosys": str}
FAMILY_FIELDS = {"title": str, "synth": str, "options": list, "cells": dict, "columns": list}
PNR_FIELDS = {
    "netlist": list,
    "pnr": str,
    "pnr_output": list,
    "constrained": list,
    "unconstrained": list,
    "constraint_comment": str,
    "constraint_pin": str,
    "pnr_cell": str,
    "pnr_cell_label": str,
    "pnr_bram": str,
    "pnr_dsp": str,
    "unconstrained_log": str,
    "measured_with": str,
    "constraint_line": str,
}
# Optional fields of a family: Yosys commands after its synthesis command ({root}: the repository).
# A family with them writes its netlist after them: its netlist field is then that Yosys command.
FAMILY_OPTIONAL = {"after": list}
DEVICE_FIELDS = {
    "family": str,
    "title": str,
    "short": str,
    "part": str,
    "package": str,
    "speed": str,
    "pnr_args": list,
    "aliases": list,
    "constraints": str,
    "wrapper": (str, list),  # one pattern, or patterns in preference order
    "wrapper_required": bool,
    "suffix": str,
    "bare_suffix": str,
    "wrapper_doc": str,
    "capacity": dict,
    "synth_options": list,
    "pins": list,
    "tested": bool,
}
CLOCK_PORT = r"clk(_i)?"  # the placed designs' clock input, given the first of a device's pins


class DevicesError(Exception):
    pass


class PinsError(Exception):
    """A design with more ports than the device has free pins: it does not fit the package."""


class Family:
    """A synthesis target: Yosys command, the cell classes it counts, its report columns, and, for
    a family whose devices are placed, its place-and-route program."""

    def __init__(self, name, f, root="."):
        self.name = name
        self.title, self.synth, self.options = f["title"], f["synth"], list(f["options"])
        self.after = [c.format(root=os.path.abspath(root)) for c in f.get("after", [])]
        self.cells = dict(f["cells"])
        self.columns = [(c["label"], list(c["count"])) for c in f["columns"]]
        self.placed = "pnr" in f
        for k in PNR_FIELDS:
            setattr(self, k, f.get(k))

    def yosys_command(self, top, netlist=None, device=None):
        """The Yosys synthesis command of the top (writing the netlist to place when given; with a
        device's own options, such as the UP5K's hard multipliers, when given)."""
        out = [a.format(file=netlist) for a in self.netlist] if netlist else []
        extra = list(device.synth_options) if device else []
        if not self.after:
            return " ".join([self.synth, *self.options, *extra, "-top", top, *out])
        cmd = " ".join([self.synth, *self.options, *extra, "-top", top])
        return "; ".join([cmd, *self.after, *([" ".join(out)] if out else [])])

    def count(self, cells, classes):
        """Sum of the cells of these classes in a `registry.cells()` dict (None when it is None)."""
        if cells is None:
            return None
        n = 0
        for c in classes:
            if c == "total":
                n += cells["total"]
                continue
            pat = self.cells.get(c)
            if pat is None:  # the family has no such cell
                continue
            n += sum(v for k, v in cells.items() if k != "total" and re.fullmatch(pat, k))
        return n

    def column_titles(self):
        return [f"{self.title} {label}" for label, _ in self.columns]


def wrapper_patterns(d):
    """A device entry's wrapper patterns in order of preference (one pattern or a list of them)."""
    return [d["wrapper"]] if isinstance(d["wrapper"], str) else list(d["wrapper"])


class Device:
    """A part placed and routed: its family, part, pnr arguments, constraints, wrapper, capacity."""

    def __init__(self, name, d, family):
        self.name, self.family = name, family
        for k in DEVICE_FIELDS:
            if k != "family":
                setattr(self, k, d[k])
        self.capacity = dict(d["capacity"])
        self.synth_options = list(d.get("synth_options", []))
        self.wrappers = wrapper_patterns(d)

    def wrapper_names(self, module):
        """The module's wrapper names on this device, in the table's order of preference."""
        return [w.format(module=module) for w in self.wrappers]

    def wrapper_module(self, module, source):
        """(wrapper module, its file) of the module on this device: the first of wrapper_names
        that `source` (module name -> the file defining it, or None) finds; (None, None) when
        none is defined (the module is placed as it is)."""
        for w in self.wrapper_names(module):
            src = source(w)
            if src:
                return w, src
        return None, None

    def constraint_files(self, root):
        if not self.constraints:
            return []
        return sorted(glob.glob(os.path.join(root, self.constraints)))

    def constraint_ports(self, path):
        """The port bits a constraint file places (the family's constraint_pin on each line,
        comments stripped)."""
        placed = set()
        pat = re.compile(self.family.constraint_pin)
        for line in open(path):
            m = pat.search(line.split(self.family.constraint_comment, 1)[0])
            if m:
                placed.add(m.group(1))
        return placed

    def pin_constraints(self, ports, path):
        """Writes a constraint file placing the ports (the port bits a constraint line names) on
        the device's free pins, the clock on the first (a global clock input), and returns its
        path: for a family whose program places no unconstrained port. PinsError when there are
        more ports than pins."""
        if len(ports) > len(self.pins):
            raise PinsError(
                f"{len(ports)} port bits, {len(self.pins)} free user pins of the {self.title} "
                f"{self.package} (synth/devices.toml [device.{self.name}] pins)"
            )
        clock = sorted(p for p in ports if re.fullmatch(CLOCK_PORT, p))
        order = clock + sorted(set(ports) - set(clock), key=_port_key)
        with open(path, "w") as f:
            f.write(
                f"{self.family.constraint_comment} written by scripts/registry.py from "
                f"synth/devices.toml [device.{self.name}] pins\n"
            )
            f.writelines(
                self.family.constraint_line.format(port=port, pin=pin) + "\n"
                for port, pin in zip(order, self.pins)
            )
        return path

    def program(self, root):
        """The place-and-route program's path: on PATH, or in the project's .venv/bin (the PyPI
        builds of nextpnr that scripts/setup.sh pins); None when neither has it."""
        venv = os.path.join(root, ".venv", "bin")
        return shutil.which(self.family.pnr) or shutil.which(self.family.pnr, path=venv)

    def pnr_command(self, netlist, stem, log, constraint, freq, seed, root=None):
        """The place-and-route command line (a list of words)."""
        # nextpnr's WebAssembly builds see a private directory of their own at /tmp: a file under
        # the system's temporary directory is named relative to the working directory instead.
        tmp = os.path.realpath(tempfile.gettempdir()) + os.sep

        def rel(p):
            return os.path.relpath(p) if p and os.path.realpath(p).startswith(tmp) else p

        netlist, stem, log, constraint = rel(netlist), rel(stem), rel(log), rel(constraint)
        pins = (
            [a.format(file=constraint) for a in self.family.constrained]
            if constraint
            else list(self.family.unconstrained)
        )
        return (
            [(self.program(root) if root else None) or self.family.pnr]
            + list(self.pnr_args)
            + ["--json", netlist]
            + [a.format(stem=stem) for a in self.family.pnr_output]
            + ["--freq", str(freq)]
            + pins
            + ["--timing-allow-fail", "--seed", str(seed), "-l", log]
        )

    def tool_missing(self, root):
        """Why the device cannot be placed on this machine ("" when it can)."""
        if self.program(root):
            return ""
        untested = " (the row has datasheet fields only: no report made with it yet)"
        return (
            f"device {self.name} ({self.title}): its place-and-route program {self.family.pnr} is "
            f"not installed (scripts/setup.sh installs it){'' if self.tested else untested}"
        )


class Table:
    def __init__(self, flow, families, devices):
        self.flow, self.families, self.devices = flow, families, devices
        self.aliases = {a: d.name for d in devices.values() for a in d.aliases}

    @property
    def default(self):
        return self.devices[self.flow["default_device"]]

    @property
    def freq(self):
        return self.flow["freq_mhz"]

    @property
    def seed(self):
        return self.flow["seed"]

    def flows(self):
        """Every synthesis flow name: the families, the devices, then the aliases."""
        return list(self.families) + list(self.devices) + list(self.aliases)

    def canonical(self, flow):
        return self.aliases.get(flow, flow)

    def target(self, flow):
        """The Family or Device a flow names (None: not a synthesis flow)."""
        flow = self.canonical(flow)
        return self.families.get(flow) or self.devices.get(flow)


def _port_key(port):
    """Name, then bit index: a bus's bits on neighbouring pins in order."""
    m = re.fullmatch(r"(.*)\[(\d+)\]", port)
    return (m.group(1), int(m.group(2))) if m else (port, -1)


def article(text):
    """'a' or 'an' before a device's name, by its sound (an acronym's letters are spelt:
    "an HX8K")."""
    acronym = len(text) > 1 and text[:2].upper() == text[:2] and text[:1].isalpha()
    return ("an " if text[:1] in ("AEFHILMNORSX" if acronym else "aeiouAEIOU") else "a ") + text


def _where(text, rel):
    """(table header, key) -> line number, for the error messages (tomllib gives none)."""
    at, table = {}, ""
    for n, line in enumerate(text.splitlines(), 1):
        s = line.strip()
        m = re.match(r"\[([A-Za-z0-9_.\-]+)\]\s*(#.*)?$", s)
        if m:
            table = m.group(1)
            at.setdefault((table, None), n)
            continue
        m = re.match(r"([A-Za-z0-9_\-]+)\s*=", s)
        if m:
            at.setdefault((table, m.group(1)), n)
    return lambda table, key=None: f"{rel}:{at.get((table, key), at.get((table, None), 1))}"


def _check(where, table, section, fields, required=True):
    for k, t in fields.items():
        if k not in section:
            if required:
                raise DevicesError(f"{where(table)}: [{table}] has no field '{k}'")
            continue
        v = section[k]
        if not isinstance(v, t) or (t is int and isinstance(v, bool)):
            types = " or ".join(x.__name__ for x in (t if isinstance(t, tuple) else (t,)))
            raise DevicesError(f"{where(table, k)}: {k}: expected {types}, got {v!r}")
        if isinstance(v, list) and not all(isinstance(x, str) for x in v) and k != "columns":
            raise DevicesError(f"{where(table, k)}: {k}: expected a list of strings")


def _regex(where, table, key, pat, groups=0):
    try:
        r = re.compile(pat)
    except re.error as e:
        raise DevicesError(f"{where(table, key)}: {key}: '{pat}' is not a regular expression ({e})")
    if r.groups < groups:
        raise DevicesError(f"{where(table, key)}: {key}: '{pat}' needs a group (the port bit)")


@functools.cache
def _load(root):
    path = os.path.join(root, PATH)
    try:
        text = open(path, encoding="utf-8").read()
    except OSError as e:
        raise DevicesError(f"{PATH}: cannot read: {e.strerror}")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise DevicesError(f"{PATH}: {e}")
    where = _where(text, PATH)
    for k in data:
        if k not in ("flow", "family", "device"):
            raise DevicesError(
                f"{where(k)}: [{k}]: the table has [flow], [family.NAME] and [device.NAME] only"
            )
    flow = data.get("flow")
    if not isinstance(flow, dict):
        raise DevicesError(f"{PATH}: no [flow] table")
    _check(where, "flow", flow, FLOW_FIELDS)
    for k in flow:
        if k not in FLOW_FIELDS:
            raise DevicesError(
                f"{where('flow', k)}: [flow] {k}: unknown field (known: {', '.join(FLOW_FIELDS)})"
            )
    families = {}
    for name, f in data.get("family", {}).items():
        t = f"family.{name}"
        if not re.fullmatch(NAME, name):
            raise DevicesError(f"{where(t)}: family '{name}': lower case letters, digits and '_'")
        if not isinstance(f, dict):
            raise DevicesError(f"{where(t)}: family '{name}' is not a table")
        _check(where, t, f, FAMILY_FIELDS)
        _check(where, t, f, FAMILY_OPTIONAL, required=False)
        placed = any(k in f for k in PNR_FIELDS)
        _check(where, t, f, PNR_FIELDS, required=placed)
        for k in f:
            if k not in FAMILY_FIELDS and k not in PNR_FIELDS and k not in FAMILY_OPTIONAL:
                raise DevicesError(
                    f"{where(t, k)}: {k}: unknown field of a family (known: "
                    f"{', '.join(list(FAMILY_FIELDS) + list(PNR_FIELDS) + list(FAMILY_OPTIONAL))})"
                )
        for c, pat in f["cells"].items():
            if not isinstance(pat, str) or c == "total":
                raise DevicesError(
                    f"{where(t, 'cells')}: cells: {c}: expected a regular expression of "
                    "cell types ('total' is Yosys's cell count)"
                )
            _regex(where, t, "cells", pat)
        if not f["columns"]:
            raise DevicesError(
                f"{where(t, 'columns')}: columns: a family reports at least one column"
            )
        for c in f["columns"]:
            if (
                not isinstance(c, dict)
                or set(c) != {"label", "count"}
                or not isinstance(c["label"], str)
                or not isinstance(c["count"], list)
                or not c["count"]
            ):
                raise DevicesError(
                    f'{where(t, "columns")}: columns: {c!r}: expected {{ label = "...", '
                    'count = ["class", ...] }'
                )
            for cls in c["count"]:
                if cls != "total" and cls not in f["cells"]:
                    raise DevicesError(
                        f"{where(t, 'columns')}: columns: {c['label']}: '{cls}' is not a cell "
                        f"class of the family (cells: {', '.join(f['cells']) or 'none'}; or total)"
                    )
        if placed:
            _regex(where, t, "constraint_pin", f["constraint_pin"], groups=1)
            # The lines the flow writes must be lines it reads back (the port they place).
            try:
                line = f["constraint_line"].format(port="x_i[3]", pin="1")
            except (KeyError, IndexError, ValueError):
                line = None
            m = line and re.search(f["constraint_pin"], line)
            if not m or m.group(1) != "x_i[3]":
                raise DevicesError(
                    f"{where(t, 'constraint_line')}: constraint_line: '{f['constraint_line']}' "
                    "must name {port} and {pin} in a line that constraint_pin reads back"
                )
        families[name] = Family(name, f, root)
    devices = {}
    for name, d in data.get("device", {}).items():
        t = f"device.{name}"
        if not re.fullmatch(NAME, name):
            raise DevicesError(f"{where(t)}: device '{name}': lower case letters, digits and '_'")
        if name in families:
            raise DevicesError(
                f"{where(t)}: device '{name}': also a family's name (both are flow names)"
            )
        if not isinstance(d, dict):
            raise DevicesError(f"{where(t)}: device '{name}' is not a table")
        _check(where, t, d, DEVICE_FIELDS)
        for k in d:
            if k not in DEVICE_FIELDS:
                raise DevicesError(
                    f"{where(t, k)}: {k}: unknown field of a device (known: "
                    f"{', '.join(DEVICE_FIELDS)})"
                )
        fam = families.get(d["family"])
        if fam is None or not fam.placed:
            raise DevicesError(
                f"{where(t, 'family')}: family: '{d['family']}' is not a family with a "
                "place-and-route program (those: "
                f"{', '.join(f for f in families if families[f].placed)})"
            )
        for k in CAPACITY:
            v = d["capacity"].get(k)
            if not isinstance(v, int) or isinstance(v, bool) or v < 0:
                raise DevicesError(
                    f"{where(t, 'capacity')}: capacity: {k}: expected a count >= 0, got {v!r}"
                )
        for k in d["capacity"]:
            if k not in CAPACITY:
                raise DevicesError(
                    f"{where(t, 'capacity')}: capacity: {k}: unknown (known: {', '.join(CAPACITY)})"
                )
        patterns = wrapper_patterns(d)
        if not patterns:
            raise DevicesError(
                f"{where(t, 'wrapper')}: wrapper: an empty list (one pattern or a list of them)"
            )
        for w in patterns:
            if "{module}" not in w:
                raise DevicesError(f"{where(t, 'wrapper')}: wrapper: '{w}' must contain {{module}}")
        if not re.fullmatch(r"_[a-z0-9_]+", d["suffix"]):
            raise DevicesError(
                f"{where(t, 'suffix')}: suffix: '{d['suffix']}': '_' then lower "
                "case letters and digits"
            )
        if d["bare_suffix"] and not re.fullmatch(r"_[a-z0-9_]+", d["bare_suffix"]):
            raise DevicesError(
                f"{where(t, 'bare_suffix')}: bare_suffix: '{d['bare_suffix']}': empty, or '_' then "
                "lower case letters and digits"
            )
        if d["constraints"] and not glob.glob(os.path.join(root, d["constraints"])):
            raise DevicesError(
                f"{where(t, 'constraints')}: constraints: '{d['constraints']}' names no file"
            )
        if not fam.unconstrained and not d["pins"]:
            raise DevicesError(
                f"{where(t, 'pins')}: pins: {fam.pnr} places no unconstrained port (the family's "
                "unconstrained is empty): the device lists its free user pins"
            )
        if len(set(d["pins"])) != len(d["pins"]) or len(d["pins"]) > d["capacity"]["user_io"]:
            raise DevicesError(
                f"{where(t, 'pins')}: pins: {len(d['pins'])} pins, repeated or more than the "
                f"capacity's user_io ({d['capacity']['user_io']})"
            )
        devices[name] = Device(name, d, fam)
    # Flow names and report names must not collide.
    seen = {n: f"family {n}" for n in families}
    for dev in devices.values():
        seen[dev.name] = f"device {dev.name}"
    suffixes, bare_empty = {}, []
    for dev in devices.values():
        t = f"device.{dev.name}"
        for a in dev.aliases:
            if not re.fullmatch(NAME, a) or a in seen:
                raise DevicesError(
                    f"{where(t, 'aliases')}: aliases: '{a}' is "
                    f"{'already ' + seen[a] if a in seen else 'not a flow name'}"
                )
            seen[a] = f"an alias of device {dev.name}"
        for s in {dev.suffix, dev.bare_suffix} - {""}:
            if suffixes.get(s, dev.name) != dev.name:
                raise DevicesError(
                    f"{where(t, 'suffix')}: suffix '{s}': also device {suffixes[s]}'s "
                    "(report names would collide)"
                )
            suffixes[s] = dev.name
        if not dev.bare_suffix:
            bare_empty.append(dev.name)
    if len(bare_empty) > 1:
        raise DevicesError(
            f"{PATH}: bare_suffix: empty for {', '.join(bare_empty)}: at most one device places a "
            "module as it is under the line's own name"
        )
    if flow["default_device"] not in devices:
        raise DevicesError(
            f"{where('flow', 'default_device')}: default_device: '{flow['default_device']}' is not "
            f"a device (devices: {', '.join(devices)})"
        )
    return Table(flow, families, devices)


def load(root):
    """The table (DevicesError on a malformed entry)."""
    return _load(os.path.abspath(root))


def main(argv):
    import argparse

    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("cmd", choices=["list"])
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    try:
        t = load(a.root)
    except DevicesError as e:
        print(f"devices: {e}", file=sys.stderr)
        return 2
    for f in t.families.values():
        print(" ".join(["family", f.name, f.synth, *f.options]))
    for d in t.devices.values():
        print(f"device {d.name} {d.family.name} {d.part} {d.package}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
