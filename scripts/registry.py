#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The build registry rtl/configs.txt (`name module flows [PARAM=value ...]`), read by every script
through this one parser, and the rules that turn a registry line into builds and report names.

usage: registry.py lines [--flow F[,F...]] [--module M] [--names N[,N...]]
         the registry lines with any of the flows (all lines without --flow), in file order, one per
         line: "name module flows [PARAM=value ...]" (flows comma-separated, '-' for none)
       registry.py synth [--names N[,N...]] [--flows F[,F...]]
         the designs scripts/synth.sh builds, one per line: "design top source flows [PARAM=value ...]"
         (source: the synth/ file defining top, '-' for a module of rtl/files.f; flows
         comma-separated)
       registry.py pcf-covers NETLIST_JSON PCF
         exit 0 when the PCF places every port of the netlist's top module, 1 when it does not
Exit 2 on a malformed registry line (file, line and field named) or an unknown name.

Synthesis rules (scripts/synth.sh; the registry's header states them for its readers):
  generic, xilinx, ice40  the line's module with the line's parameters: design <name>, reports
                          synth/reports/<flow>_<name>.txt.
  pnr                     the module in its pin wrapper <module>_pinwrap (a module of synth/*.v, given
                          the line's parameters), synthesized for iCE40 and placed and routed on an
                          HX8K: design <name>_pnr, reports ice40_<name>_pnr.txt, nextpnr_<name>_pnr.log.
                          A module without a pin wrapper is placed as it is (its ports must fit the
                          package): its ice40 netlist is placed, log nextpnr_<name>.log.
                          Pins: synth/acore_hx8k_ct256.pcf when it places every port of the placed
                          design (the whole tops), unconstrained otherwise.
  pnr_up5k                the module in its SG48 wrapper <module>_sg48wrap (a module of synth/*.v with
                          few enough pins for the UP5K's 48-pin package, given the line's parameters),
                          synthesized for iCE40 and placed and routed on an iCE40 UP5K (sg48, pins
                          unconstrained): design <name>_up5k, reports ice40_<name>_up5k.txt,
                          nextpnr_<name>_up5k.log.
"""
import functools
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

FLOWS = ("sim", "lint", "icarus", "generic", "xilinx", "ice40", "pnr", "pnr_up5k", "formal")
SYNTH_FLOWS = ("generic", "xilinx", "ice40", "pnr", "pnr_up5k")
PLACE_FLOWS = ("pnr", "pnr_up5k")
AREA_FLOWS = ("generic", "xilinx", "ice40")


class RegistryError(Exception):
    pass


class Line:
    """One registry line: name, module, flows (tuple), params (list of (NAME, int) in line order)."""

    def __init__(self, where, name, module, flows, params):
        self.where, self.name, self.module, self.flows, self.params = where, name, module, flows, params

    def param_text(self):
        return " ".join(f"{k}={v}" for k, v in self.params)

    def __str__(self):
        return " ".join(x for x in (self.name, self.module, ",".join(self.flows) or "-", self.param_text()) if x)


def registry_path(root):
    return os.path.join(root, "rtl", "configs.txt")


@functools.lru_cache(maxsize=None)
def _load(root):
    path = registry_path(root)
    rel = os.path.relpath(path, root)
    lines, seen = [], {}
    try:
        text = open(path).read()
    except OSError as e:
        raise RegistryError(f"{rel}: cannot read: {e.strerror}")
    for n, raw in enumerate(text.splitlines(), 1):
        if not raw.strip() or raw.startswith("#"):
            continue
        where = f"{rel}:{n}"
        f = raw.split()
        if raw[0].isspace() or len(f) < 3:
            raise RegistryError(f"{where}: expected 'name module flows [PARAM=value ...]' starting in column 1")
        name, module, flows = f[0], f[1], f[2]
        if not re.fullmatch(r"[a-z][a-z0-9_]*", name):
            raise RegistryError(f"{where}: name '{name}': lower case letters, digits and '_', starting with a letter")
        if name.endswith("_pnr") or name.endswith("_up5k"):
            raise RegistryError(f"{where}: name '{name}': '_pnr' and '_up5k' are the suffixes of the placed "
                                "designs' reports")
        if name in seen:
            raise RegistryError(f"{where}: name '{name}': already on line {seen[name]}")
        seen[name] = n
        if not re.fullmatch(r"[a-z][a-z0-9_]*", module):
            raise RegistryError(f"{where}: module '{module}' is not a Verilog module name")
        fl = () if flows == "-" else tuple(flows.split(","))
        for x in fl:
            if x not in FLOWS:
                raise RegistryError(f"{where}: flows: '{x}' is not a flow (known: {', '.join(FLOWS)}; '-' for none)")
        params, pn = [], set()
        for t in f[3:]:
            m = re.fullmatch(r"([A-Z][A-Z0-9_]*)=(-?\d+)", t)
            if not m:
                raise RegistryError(f"{where}: parameter '{t}' is not PARAM=integer")
            if m.group(1) in pn:
                raise RegistryError(f"{where}: parameter {m.group(1)} set twice")
            pn.add(m.group(1))
            params.append((m.group(1), int(m.group(2))))
        lines.append(Line(where, name, module, fl, params))
    return tuple(lines)


def load(root):
    """Every registry line, in file order (RegistryError on a malformed line)."""
    return list(_load(os.path.abspath(root)))


def select(root, flows=None, module=None, names=None):
    """The lines with any of the flows (any line when None), of that module, among those names (in
    file order; RegistryError on an unknown name)."""
    lines = load(root)
    if names:
        known = {l.name for l in lines}
        for n in names:
            if n not in known:
                raise RegistryError(f"unknown configuration '{n}' (rtl/configs.txt names: {', '.join(sorted(known))})")
    return [l for l in lines
            if (not flows or set(flows) & set(l.flows)) and (not module or l.module == module)
            and (not names or l.name in names)]


def get(root, name):
    return select(root, names=[name])[0]


# --- The RTL ------------------------------------------------------------------------------------

def rtl_files(root):
    """rtl/files.f: the RTL sources in order (names relative to rtl/)."""
    with open(os.path.join(root, "rtl", "files.f")) as f:
        return [l.strip() for l in f if l.strip().endswith(".v") and not l.startswith("#")]


def _const(text):
    """A Verilator XML constant ("32'sh10", "32'h34", "32'shffffffff") as an int."""
    m = re.fullmatch(r"(\d+)'(s?)h([0-9a-fA-F]+)", text)
    if not m:
        return None
    width, signed, v = int(m.group(1)), m.group(2) == "s", int(m.group(3), 16)
    return v - (1 << width) if signed and v >> (width - 1) & 1 else v


@functools.lru_cache(maxsize=None)
def _elaborate(root, module, params):
    rtl = os.path.join(root, "rtl")
    with tempfile.TemporaryDirectory(prefix="acore_xml_") as tmp:
        xml = os.path.join(tmp, "top.xml")
        r = subprocess.run(["verilator", "--xml-only", "--xml-output", xml, "--Mdir", tmp, "verilator.vlt",
                            *rtl_files(root), "--top-module", module, *[f"-G{k}={v}" for k, v in params]],
                           cwd=rtl, capture_output=True, text=True)
        if r.returncode != 0:
            raise RegistryError(f"verilator --xml-only {module} {' '.join(f'{k}={v}' for k, v in params)}: "
                                f"{r.stderr.strip()[:500]}")
        tree = ET.parse(xml)
    subs = frozenset(m.get("origName") for m in tree.iter("module") if m.get("topModule") != "1")
    mod = next(m for m in tree.iter("module") if m.get("topModule") == "1")
    header, local = {}, {}
    for var in mod.findall("var"):
        const = var.find("const")
        if var.get("vartype") != "integer" or const is None:
            continue
        value = _const(const.get("name"))
        if var.get("param") == "true":
            header[var.get("name")] = value
        elif var.get("localparam") == "true":
            local[var.get("name")] = value
    return header, local, subs


def rtl_parameters(root, module, params=()):
    """The integer parameters of the module's header (declaration order) at their elaborated values
    with these overrides: `verilator --xml-only` of rtl/files.f (defaults: no overrides)."""
    return dict(_elaborate(os.path.abspath(root), module, tuple(params))[0])


def rtl_constants(root, module, params=()):
    """Every integer parameter and localparam of the elaborated module (WORDS, LATENCY, CYCLES, ...)."""
    header, local, _ = _elaborate(os.path.abspath(root), module, tuple(params))
    return dict(header, **local)


def rtl_submodules(root, module, params=()):
    """The modules the elaborated module instantiates, at any depth (their names in rtl/)."""
    return set(_elaborate(os.path.abspath(root), module, tuple(params))[2])


# --- Synthesis ----------------------------------------------------------------------------------

def _defines(path, module):
    return re.search(r"^module %s\b" % re.escape(module), open(path).read(), re.M) is not None


def synth_source(root, module):
    """The synth/*.v file defining the module (None when it is not there)."""
    d = os.path.join(root, "synth")
    for f in sorted(os.listdir(d)):
        if f.endswith(".v") and _defines(os.path.join(d, f), module):
            return os.path.join(d, f)
    return None


def module_source(root, module):
    """The file defining the module: one of rtl/files.f, else one of synth/*.v (None: nowhere)."""
    for f in rtl_files(root):
        if _defines(os.path.join(root, "rtl", f), module):
            return os.path.join(root, "rtl", f)
    return synth_source(root, module)


def with_includes(path, seen=()):
    """The file's text with each `include "X" replaced by X's text (searched beside the file, then in
    rtl/: the tops and the pin wrappers declare the datapath parameters with rtl/acore_datapath_params.vh)."""
    text = open(path).read()
    rtl = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(path))), "rtl")

    def expand(m):
        for d in (os.path.dirname(path), rtl):
            f = os.path.join(d, m.group(1))
            if os.path.isfile(f) and f not in seen:
                return with_includes(f, seen + (f,))
        return ""
    return re.sub(r'^\s*`include\s+"([^"]+)"', expand, text, flags=re.M)


def module_parameter_names(path, module):
    """The parameter names of a module in a Verilog file (comments stripped, includes read; the pin
    wrappers' check)."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", "", with_includes(path), flags=re.S)
    m = re.search(r"^\s*module\s+%s\b(.*?)\bendmodule\b" % re.escape(module), text, re.M | re.S)
    body = m.group(1) if m else ""
    return set(re.findall(r"\bparameter\s+(?:integer\s+|signed\s+|\[[^\]]*\]\s*)*(\w+)", body))


def pin_wrapper(root, module):
    """(wrapper module, its synth/ file) for the pnr flow, or (None, None): placed as it is."""
    w = module + "_pinwrap"
    src = synth_source(root, w)
    return (w, src) if src else (None, None)


def placed_design(root, line):
    """The design name whose netlist the pnr flow places (its nextpnr_<design>.log)."""
    return line.name + "_pnr" if pin_wrapper(root, line.module)[0] else line.name


class Design:
    def __init__(self, name, top, source, flows, params):
        self.name, self.top, self.source, self.flows, self.params = name, top, source, flows, params


def synth_designs(root, names=None, flows=None):
    """The designs of scripts/synth.sh for the registry lines with a synthesis flow (those names and
    flows only, when given), in registry order."""
    flows = flows or SYNTH_FLOWS
    for f in flows:
        if f not in SYNTH_FLOWS:
            raise RegistryError(f"'{f}' is not a synthesis flow (known: {', '.join(SYNTH_FLOWS)})")
    out = []
    for l in select(root, flows=[f for f in SYNTH_FLOWS if f in flows], names=names):
        area = [f for f in AREA_FLOWS if f in l.flows and f in flows]
        pnr = "pnr" in l.flows and "pnr" in flows
        src = synth_source(root, l.module)
        wrapper, wsrc = pin_wrapper(root, l.module) if pnr else (None, None)
        msrc = module_source(root, l.module)
        if not msrc:
            raise RegistryError(f"{l.where}: module {l.module}: defined neither in rtl/files.f nor in synth/*.v")
        check_params(root, l, l.module, msrc, "the line's module")
        if area or (pnr and not wrapper):
            out.append(Design(l.name, l.module, src, area + (["pnr"] if pnr and not wrapper else []), l.params))
        if wrapper:
            check_params(root, l, wrapper, wsrc, "its pin wrapper for the pnr flow")
            out.append(Design(l.name + "_pnr", wrapper, wsrc, ["pnr"], l.params))
        if "pnr_up5k" in l.flows and "pnr_up5k" in flows:
            w5 = l.module + "_sg48wrap"
            w5src = synth_source(root, w5)
            if not w5src:
                raise RegistryError(f"{l.where}: flow pnr_up5k: no module {w5} in synth/*.v (the UP5K's SG48 "
                                    "package has 39 user pins: the design is placed in that wrapper)")
            check_params(root, l, w5, w5src, "its SG48 wrapper for the pnr_up5k flow")
            out.append(Design(l.name + "_up5k", w5, w5src, ["pnr_up5k"], l.params))
    return out


def check_params(root, line, module, path, what):
    """Every parameter the line sets is one of the module's (Yosys would stop on the first that is
    not, with a message that names neither the line nor the module)."""
    have = module_parameter_names(path, module)
    for k, _ in line.params:
        if k not in have:
            raise RegistryError(f"{line.where}: parameter {k}: {module} ({os.path.relpath(path, root)}), {what}, "
                                f"has no parameter {k} (it has: {', '.join(sorted(have)) or 'none'})")


def pcf_covers(netlist, pcf):
    """True when the PCF has a set_io for every port bit of the netlist's top module (Yosys JSON)."""
    placed = set()
    for line in open(pcf):
        f = line.split("#", 1)[0].split()
        if len(f) >= 3 and f[0] == "set_io":
            placed.add(f[-2])
    mods = json.load(open(netlist))["modules"]
    top = next(m for m in mods.values() if int(m.get("attributes", {}).get("top", "0"), 2))
    for name, p in top["ports"].items():
        n, off = len(p["bits"]), p.get("offset", 0)
        for i in range(n):
            if (name if n == 1 else f"{name}[{off + i}]") not in placed:
                return False
    return True


# --- Reports (synth/reports/, written by scripts/synth.sh) -------------------------------------

def report(root, flow, design):
    """synth/reports/<flow>_<design>.txt (generic, xilinx, ice40) or nextpnr_<design>.log (pnr,
    pnr_up5k)."""
    name = f"nextpnr_{design}.log" if flow in PLACE_FLOWS else f"{flow}_{design}.txt"
    return os.path.join(root, "synth", "reports", name)


def cells(path):
    """Cell type -> count, and "total", from the last (flattened top's) `stat` block of a Yosys
    report; None when there is none."""
    if not os.path.exists(path):
        return None
    blocks = open(path).read().split("Number of cells:")
    if len(blocks) < 2:
        return None
    out = {"total": int(blocks[-1].split()[0])}
    for m in re.finditer(r"^\s+(\S+)\s+(\d+)\s*$", blocks[-1], re.M):
        out[m.group(1)] = int(m.group(2))
    return out


def pnr_result(path):
    """(Fmax MHz or None, (used, total) logic cells or None, why there is no Fmax: "not run",
    "does not fit", "failed" or "") of a nextpnr-ice40 log."""
    if not os.path.exists(path):
        return None, None, "not run"
    text = open(path).read()
    fmax = re.findall(r"Max frequency for clock\s+'[^']*':\s+([\d.]+) MHz", text)
    lc = re.findall(r"ICESTORM_LC:\s+(\d+)/\s*(\d+)", text)
    lc = (int(lc[-1][0]), int(lc[-1][1])) if lc else None
    if not fmax:
        why = "does not fit" if re.search(r"(Unable to place|utilisation|too many)", text, re.I) else "failed"
        return None, lc, why
    return float(fmax[-1]), lc, ""


def pnr_used_pcf(path):
    """True when the nextpnr log's run had pin constraints."""
    return os.path.exists(path) and "No PCF file specified" not in open(path).read()


def default_top_stages(root):
    """The registry lines that bound the default acore_top's clock on the HX8K, which it does not
    fit: the placed lines (pnr) without parameters of a module the default top instantiates (each
    stage at its defaults is the top's)."""
    subs = rtl_submodules(root, "acore_top")
    return [l for l in load(root) if "pnr" in l.flows and not l.params and l.module in subs]


# --- Command line -------------------------------------------------------------------------------

def main(argv):
    import argparse
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", default=root)
    sub = ap.add_subparsers(dest="cmd", required=True)
    a = sub.add_parser("lines")
    a.add_argument("--flow", default="")
    a.add_argument("--module", default="")
    a.add_argument("--names", default="")
    s = sub.add_parser("synth")
    s.add_argument("--names", default="")
    s.add_argument("--flows", default="")
    p = sub.add_parser("pcf-covers")
    p.add_argument("netlist")
    p.add_argument("pcf")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    split = lambda x: [v for v in x.split(",") if v]
    try:
        if args.cmd == "lines":
            for l in select(args.root, split(args.flow), args.module or None, split(args.names)):
                print(l)
        elif args.cmd == "synth":
            for d in synth_designs(args.root, split(args.names), split(args.flows)):
                params = " ".join(f"{k}={v}" for k, v in d.params)
                print(" ".join(x for x in (d.name, d.top, d.source or "-", ",".join(d.flows), params) if x))
        else:
            try:
                return 0 if pcf_covers(args.netlist, args.pcf) else 1
            except (OSError, ValueError, KeyError, StopIteration) as e:
                raise RegistryError(f"pcf-covers {args.netlist} {args.pcf}: not a Yosys netlist and a PCF ({e})")
    except RegistryError as e:
        print(f"registry: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
