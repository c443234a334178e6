#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The build registry rtl/configs.txt (`name module flows [tags=T,...] [PARAM=value ...]`), read by
every script and by CMake through this one parser (CMake includes what `registry.py cmake` writes at
configure time), and the rules that turn a registry line into builds and report names. The synthesis
flows are the families and devices of synth/devices.toml (scripts/devices.py reads it).

usage: registry.py lines [--flow F[,F...]] [--module M] [--names N[,N...]] [--tag T]
         the registry lines with any of the flows (all lines without --flow), in file order, one per
         line: "name module flows [PARAM=value ...]" (flows comma-separated, '-' for none; tags not
         shown)
       registry.py params NAME
         the line's parameters, "PARAM=value ..." (empty for none)
       registry.py cmake OUT
         writes OUT, the CMake file cmake/AcoreRegistry.cmake includes: ACORE_REG_NAMES, and per
         line ACORE_REG_MODULE_<name>, ACORE_REG_FLOWS_<name>, ACORE_REG_PARAMS_<name>
         (PARAM=value), ACORE_REG_TAGS_<name>; per tag ACORE_REG_TAGGED_<tag> (the names
         carrying it)
       registry.py synth [--names N[,N...]] [--flows F[,F...]]
         the designs scripts/synth.sh builds, one per line:
         "design top source flows [PARAM=value ...]" (source: the synth/ file defining top, '-' for
         a module of rtl/files.f; flows: the families and devices of synth/devices.toml it is
         synthesized for or placed on, comma-separated)
       registry.py synth-tasks [--names N[,N...]] [--flows F[,F...]]
         scripts/synth.sh's runs of those designs, tab-separated, one per line:
           yosys FAMILY DESIGN REPORT NETLIST TOP SOURCE SYNTH_COMMAND PARAMS
             (NETLIST '-': area only)
           place DEVICE DESIGN LOG SHORT_NAME
         (exit 2 when a device's place-and-route program is not installed)
       registry.py pnr-command DEVICE DESIGN
         the place-and-route command of the design's netlist (synth/build/DESIGN.json), one word per
         line; the device's first constraint file placing every port of the netlist, else none
         (or, where the program needs every pin placed, synth/build/DESIGN.pins from the device's
         free pins); exit 3 when the ports outnumber those pins (the log says so: does not fit)
Exit 2 on a malformed registry line (file, line and field named), a malformed devices table or an
unknown name.

Synthesis rules (scripts/synth.sh; the registry's header states them for its readers):
  FAMILY (generic, ice40, xilinx, ...)  the line's module with the line's parameters: design <name>,
                          report synth/reports/<family>_<name>.txt.
  DEVICE (hx8k, up5k, ...)  the module in the device's pin wrapper (its `wrapper`, e.g.
                          <module>_pinwrap, a module of synth/*.v given the line's parameters; of a
                          list of patterns, the first whose module synth/*.v defines),
                          synthesized for the device's family and placed and routed on it: design
                          <name><suffix>, reports <family>_<name><suffix>.txt,
                          nextpnr_<name><suffix>.log. A module without that wrapper is placed as it
                          is (an error where the device requires its wrapper): design
                          <name><bare_suffix>. Pins: the device's first constraint file that places
                          every port of the placed design, unconstrained otherwise.
"""

import functools
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import devices

# The flows that are not synthesis (those are the families and devices of synth/devices.toml).
BASE_FLOWS = ("sim", "lint", "icarus", "formal")
# The tags a line may carry (rtl/configs.txt's header says the same): what CMake and the scripts
# select builds by, instead of their names. A tag test_<bench> links the line's Verilated build into
# the stand-alone bench tb/*/test_<bench>.cpp.
TAGS = {
    "demo": "sim",  # built with the anglecore command: `anglecore demo`'s RTL rows, tb/bench
    "fast-sim": "sim",  # Verilated with -O3 (the long regressions run it)
    # a 10^7-sample co-sim of its own, CTest cosim_long.<name> (configuration Long)
    "long-cosim": "sim",
    "long-proof": "formal",  # its formal proof runs long: CTest configuration Long, label long
    # Verilated only in a build configured with -DACORE_RTL_LONG=ON; its co-sim cosim_config.<name>
    # is then a CTest of configuration Long (label long): the default build and run leave it out
    "long-sim": "sim",
}
BENCH_TAG = r"test_[a-z0-9_]+"


class RegistryError(Exception):
    pass


class Line:
    """One registry line: name, module, flows (tuple, canonical names), params (list of (NAME, int)
    in line order), tags (tuple)."""

    def __init__(self, where, name, module, flows, params, tags=()):
        self.where, self.name, self.module, self.flows, self.params = (
            where,
            name,
            module,
            flows,
            params,
        )
        self.tags = tags

    def param_text(self):
        return " ".join(f"{k}={v}" for k, v in self.params)

    def __str__(self):
        return " ".join(
            x for x in (self.name, self.module, ",".join(self.flows) or "-", self.param_text()) if x
        )


def registry_path(root):
    return os.path.join(root, "rtl", "configs.txt")


def table(root):
    """The devices table (a RegistryError when it is malformed)."""
    try:
        return devices.load(root)
    except devices.DevicesError as e:
        raise RegistryError(str(e))


def flow_names(root):
    """Every flow name a registry line may carry (aliases included)."""
    return list(BASE_FLOWS) + table(root).flows()


def _tag_ok(root, where, tag, fl):
    if tag in TAGS:
        need = TAGS[tag]
    elif re.fullmatch(BENCH_TAG, tag):
        if not glob.glob(os.path.join(root, "tb", "*", tag + ".cpp")):
            raise RegistryError(
                f"{where}: tags: '{tag}': no bench tb/*/{tag}.cpp (a test_<bench> tag links "
                "the line's Verilated build into that bench)"
            )
        need = "sim"
    else:
        raise RegistryError(
            f"{where}: tags: '{tag}' is not a tag (known: {', '.join(TAGS)}, and test_<bench> "
            "for a bench tb/*/test_<bench>.cpp)"
        )
    if need not in fl:
        raise RegistryError(f"{where}: tags: '{tag}' needs the {need} flow")


@functools.cache
def _load(root):
    path = registry_path(root)
    rel = os.path.relpath(path, root)
    t = table(root)
    known = flow_names(root)
    suffixes = sorted({s for d in t.devices.values() for s in (d.suffix, d.bare_suffix) if s})
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
            raise RegistryError(
                f"{where}: expected 'name module flows [tags=T,...] [PARAM=value ...]' starting "
                "in column 1"
            )
        name, module, flow_text = f[0], f[1], f[2]
        if not re.fullmatch(r"[a-z][a-z0-9_]*", name):
            raise RegistryError(
                f"{where}: name '{name}': lower case letters, digits and '_', "
                "starting with a letter"
            )
        for s in suffixes:
            if name.endswith(s):
                raise RegistryError(
                    f"{where}: name '{name}': '{s}' ends the placed designs' report names "
                    f"(synth/devices.toml suffixes: {', '.join(suffixes)})"
                )
        if name in seen:
            raise RegistryError(f"{where}: name '{name}': already on line {seen[name]}")
        seen[name] = n
        if not re.fullmatch(r"[a-z][a-z0-9_]*", module):
            raise RegistryError(f"{where}: module '{module}' is not a Verilog module name")
        fl = [] if flow_text == "-" else flow_text.split(",")
        for x in fl:
            if x not in known:
                raise RegistryError(
                    f"{where}: flows: '{x}' is not a flow (known: {', '.join(known)}; '-' for none)"
                )
        fl = [t.canonical(x) for x in fl]
        for x in set(fl):
            if fl.count(x) > 1:
                raise RegistryError(f"{where}: flows: '{x}' named twice (aliases included)")
        rest, tags = f[3:], []
        if rest and rest[0].startswith("tags="):
            tags = rest[0][5:].split(",")
            rest = rest[1:]
            for x in tags:
                _tag_ok(root, where, x, fl)
                if tags.count(x) > 1:
                    raise RegistryError(f"{where}: tags: '{x}' named twice")
        params, pn = [], set()
        for tok in rest:
            if tok.startswith("tags="):
                raise RegistryError(f"{where}: tags: 'tags=...' comes right after the flows")
            m = re.fullmatch(r"([A-Z][A-Z0-9_]*)=(-?\d+)", tok)
            if not m:
                raise RegistryError(f"{where}: parameter '{tok}' is not PARAM=integer")
            if m.group(1) in pn:
                raise RegistryError(f"{where}: parameter {m.group(1)} set twice")
            pn.add(m.group(1))
            params.append((m.group(1), int(m.group(2))))
        lines.append(Line(where, name, module, tuple(fl), params, tuple(tags)))
    if not lines or lines[0].name != "default" or lines[0].module != "acore_top" or lines[0].params:
        where = lines[0].where if lines else rel
        raise RegistryError(
            f"{where}: the first line must be 'default acore_top FLOWS' (no parameters: the "
            "model's and the RTL's defaults)"
        )
    return tuple(lines)


def load(root):
    """Every registry line, in file order (RegistryError on a malformed line)."""
    return list(_load(os.path.abspath(root)))


def select(root, flows=None, module=None, names=None, tag=None):
    """The lines with any of the flows (any line when None; aliases allowed), of that module, among
    those names, with that tag (in file order; RegistryError on an unknown name or flow)."""
    lines = load(root)
    if names:
        known = {l.name for l in lines}
        for n in names:
            if n not in known:
                raise RegistryError(
                    f"unknown configuration '{n}' (rtl/configs.txt names: "
                    f"{', '.join(sorted(known))})"
                )
    if flows:
        t = table(root)
        for f in flows:
            if f not in BASE_FLOWS and t.target(f) is None:
                raise RegistryError(f"'{f}' is not a flow (known: {', '.join(flow_names(root))})")
        flows = {t.canonical(f) for f in flows}
    return [
        l
        for l in lines
        if (not flows or flows & set(l.flows))
        and (not module or l.module == module)
        and (not names or l.name in names)
        and (not tag or tag in l.tags)
    ]


def get(root, name):
    return select(root, names=[name])[0]


def cmake_text(root):
    """The CMake file `registry.py cmake` writes (see the usage)."""
    lines = load(root)
    q = lambda items: '"' + ";".join(items) + '"'
    out = [
        "# Generated by scripts/registry.py from rtl/configs.txt at configure time: do not edit.",
        f"set(ACORE_REG_NAMES {q(l.name for l in lines)})",
    ]
    tagged = {t: [] for t in TAGS}
    for l in lines:
        out += [
            f"set(ACORE_REG_MODULE_{l.name} {l.module})",
            f"set(ACORE_REG_FLOWS_{l.name} {q(l.flows)})",
            f"set(ACORE_REG_PARAMS_{l.name} {q(f'{k}={v}' for k, v in l.params)})",
            f"set(ACORE_REG_TAGS_{l.name} {q(l.tags)})",
        ]
        for t in l.tags:
            tagged.setdefault(t, []).append(l.name)
    out += [f"set(ACORE_REG_TAGGED_{t} {q(n)})" for t, n in tagged.items()]
    return "\n".join(out) + "\n"


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


def _xml_tree(root, module, params):
    """The elaborated module as `verilator --xml-only` writes it (parsed; not kept: its users keep
    what they read of it)."""
    rtl = os.path.join(root, "rtl")
    with tempfile.TemporaryDirectory(prefix="acore_xml_") as tmp:
        xml = os.path.join(tmp, "top.xml")
        r = subprocess.run(
            [
                "verilator",
                "--xml-only",
                "--xml-output",
                xml,
                "--Mdir",
                tmp,
                "verilator.vlt",
                *rtl_files(root),
                "--top-module",
                module,
                *[f"-G{k}={v}" for k, v in params],
            ],
            cwd=rtl,
            capture_output=True,
            text=True,
        )
        if r.returncode != 0:
            raise RegistryError(
                f"verilator --xml-only {module} {' '.join(f'{k}={v}' for k, v in params)}: "
                f"{r.stderr.strip()[:500]}"
            )
        return ET.parse(xml)


@functools.cache
def _elaborate(root, module, params):
    tree = _xml_tree(root, module, params)
    subs = frozenset(m.get("origName") for m in tree.iter("module") if m.get("topModule") != "1")
    mod = next(m for m in tree.iter("module") if m.get("topModule") == "1")
    header, local = _module_constants(mod)
    return header, local, subs


def _module_constants(mod, nested=False):
    """(header parameters, localparams) of a module of Verilator's XML, integers only (nested: with
    those of its generate blocks)."""
    header, local = {}, {}
    for var in mod.iter("var") if nested else mod.findall("var"):
        const = var.find("const")
        if var.get("vartype") != "integer" or const is None:
            continue
        value = _const(const.get("name"))
        if var.get("param") == "true":
            header[var.get("name")] = value
        elif var.get("localparam") == "true":
            local[var.get("name")] = value
    return header, local


@functools.cache
def _instances(root, module, params):
    """{hierarchical instance path below the top ("u_track", "u_shell.u_top"): its elaborated
    module's constants}."""
    tree = _xml_tree(root, module, params)
    mods = {m.get("name"): m for m in tree.iter("module")}
    out = {}
    for cell in tree.iter("cell"):
        path = cell.get("hier", "").split(".", 1)
        if len(path) == 2 and cell.get("submodname") in mods:
            header, local = _module_constants(mods[cell.get("submodname")], nested=True)
            out[path[1]] = dict(header, **local)
    return out


def rtl_parameters(root, module, params=()):
    """The integer parameters of the module's header (declaration order) at their elaborated values
    with these overrides: `verilator --xml-only` of rtl/files.f (defaults: no overrides)."""
    return dict(_elaborate(os.path.abspath(root), module, tuple(params))[0])


def rtl_constants(root, module, params=()):
    """Every integer parameter and localparam of the elaborated module
    (WORDS, LATENCY, CYCLES, ...)."""
    header, local, _ = _elaborate(os.path.abspath(root), module, tuple(params))
    return dict(header, **local)


def rtl_instance_constants(root, module, instance, params=()):
    """Every integer parameter and localparam of one instance inside the elaborated module, named by
    its hierarchical path below it ("u_track"): the values the module gives it (with the
    localparams of its elaborated generate blocks)."""
    inst = _instances(os.path.abspath(root), module, tuple(params))
    if instance not in inst:
        raise RegistryError(
            f"{module}: no instance {instance} (instances: {', '.join(sorted(inst))})"
        )
    return inst[instance]


def rtl_submodules(root, module, params=()):
    """The modules the elaborated module instantiates, at any depth (their names in rtl/)."""
    return set(_elaborate(os.path.abspath(root), module, tuple(params))[2])


# --- Synthesis ----------------------------------------------------------------------------------


def _defines(path, module):
    return re.search(rf"^module {re.escape(module)}\b", open(path).read(), re.MULTILINE) is not None


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
    """The file's text with each `include "X" replaced by X's text (searched beside the file, then
    in rtl/: the tops and the pin wrappers declare the datapath parameters with
    rtl/acore_datapath_params.vh)."""
    text = open(path).read()
    rtl = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(path))), "rtl")

    def expand(m):
        for d in (os.path.dirname(path), rtl):
            f = os.path.join(d, m.group(1))
            if os.path.isfile(f) and f not in seen:
                return with_includes(f, (*seen, f))
        return ""

    return re.sub(r'^\s*`include\s+"([^"]+)"', expand, text, flags=re.MULTILINE)


def module_parameter_names(path, module):
    """The parameter names of a module in a Verilog file (comments stripped, includes read; the pin
    wrappers' check)."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", "", with_includes(path), flags=re.DOTALL)
    m = re.search(
        rf"^\s*module\s+{re.escape(module)}\b(.*?)\bendmodule\b",
        text,
        re.MULTILINE | re.DOTALL,
    )
    body = m.group(1) if m else ""
    return set(re.findall(r"\bparameter\s+(?:integer\s+|signed\s+|\[[^\]]*\]\s*)*(\w+)", body))


def device(root, flow=None):
    """The Device a flow names (the default device when None)."""
    t = table(root)
    if flow is None:
        return t.default
    d = t.devices.get(t.canonical(flow))
    if d is None:
        raise RegistryError(
            f"'{flow}' is not a device of synth/devices.toml (devices: {', '.join(t.devices)})"
        )
    return d


def pin_wrapper(root, module, flow=None):
    """(wrapper module, its synth/ file) of the module on the device (default: the default device):
    the first of the device's wrapper patterns whose module synth/*.v defines, or (None, None):
    placed as it is."""
    return device(root, flow).wrapper_module(module, lambda w: synth_source(root, w))


def placed_design(root, line, flow=None):
    """The design name whose netlist the device's flow places (its nextpnr_<design>.log)."""
    d = device(root, flow)
    return line.name + (d.suffix if pin_wrapper(root, line.module, flow)[0] else d.bare_suffix)


class Design:
    def __init__(self, name, top, source, flows, params):
        self.name, self.top, self.source, self.flows, self.params = name, top, source, flows, params


def synth_designs(root, names=None, flows=None):
    """The designs of scripts/synth.sh for the registry lines with a synthesis flow (those names and
    flows only, when given; aliases allowed), in registry order."""
    t = table(root)
    synth_flows = list(t.families) + list(t.devices)
    want = []
    for f in flows or synth_flows:
        if t.target(f) is None:
            raise RegistryError(f"'{f}' is not a synthesis flow (known: {', '.join(t.flows())})")
        want.append(t.canonical(f))
    out = []
    for l in select(root, flows=[f for f in synth_flows if f in want], names=names):
        area = [f for f in t.families if f in l.flows and f in want]
        placed = [t.devices[f] for f in t.devices if f in l.flows and f in want]
        src = synth_source(root, l.module)
        msrc = module_source(root, l.module)
        if not msrc:
            raise RegistryError(
                f"{l.where}: module {l.module}: defined neither in rtl/files.f nor in synth/*.v"
            )
        check_params(root, l, l.module, msrc, "the line's module")
        bare = [d for d in placed if not pin_wrapper(root, l.module, d.name)[0]]
        for d in bare:
            if d.wrapper_required:
                raise RegistryError(
                    f"{l.where}: flow {d.name}: no module {' or '.join(d.wrapper_names(l.module))} "
                    f"in synth/*.v (the {d.title} in {d.package} has {d.capacity['user_io']} user "
                    "pins: the design is placed in that wrapper)"
                )
        own = [d.name for d in bare if not d.bare_suffix]
        if area or own:
            out.append(Design(l.name, l.module, src, area + own, l.params))
        for d in placed:
            if d in bare:
                if d.bare_suffix:
                    out.append(Design(l.name + d.bare_suffix, l.module, src, [d.name], l.params))
                continue
            w, wsrc = pin_wrapper(root, l.module, d.name)
            check_params(root, l, w, wsrc, f"its pin wrapper for the {d.name} flow")
            out.append(Design(l.name + d.suffix, w, wsrc, [d.name], l.params))
    return out


def check_params(root, line, module, path, what):
    """Every parameter the line sets is one of the module's (Yosys would stop on the first that is
    not, with a message that names neither the line nor the module)."""
    have = module_parameter_names(path, module)
    for k, _ in line.params:
        if k not in have:
            raise RegistryError(
                f"{line.where}: parameter {k}: {module} ({os.path.relpath(path, root)}), {what}, "
                f"has no parameter {k} (it has: {', '.join(sorted(have)) or 'none'})"
            )


def synth_tasks(root, names=None, flows=None):
    """scripts/synth.sh's runs (see the usage): Yosys runs, the netlists to place first, then the
    placements (RegistryError when a device's program is missing)."""
    t = table(root)
    netlists, places, areas = [], [], []
    for d in synth_designs(root, names, flows):
        params = " ".join(f"{k}={v}" for k, v in d.params)
        placed = [t.devices[f] for f in d.flows if f in t.devices]
        for dev in placed:
            why = dev.tool_missing(root)
            if why:
                raise RegistryError(
                    f"{why}: cannot place {d.name} (scripts/synth.sh -f selects other flows)"
                )
        nl_families = {dev.family.name for dev in placed}
        for f in d.flows:
            fam = t.families.get(f)
            if fam is None or f in nl_families:
                continue
            areas.append(
                (
                    "yosys",
                    f,
                    d.name,
                    report(root, f, d.name),
                    "-",
                    d.top,
                    d.source or "-",
                    fam.yosys_command(d.top),
                    params,
                )
            )
        for dev in placed:
            fam = dev.family
            nl = netlist(root, d.name)
            netlists.append(
                (
                    "yosys",
                    fam.name,
                    d.name,
                    report(root, fam.name, d.name),
                    nl,
                    d.top,
                    d.source or "-",
                    fam.yosys_command(d.top, nl, dev),
                    params,
                )
            )
            places.append(("place", dev.name, d.name, report(root, dev.name, d.name), dev.short))
    return netlists + places + areas


def netlist(root, design):
    """The Yosys netlist of a placed design (synth/build/<design>.json, not committed)."""
    return os.path.join(root, "synth", "build", design + ".json")


def netlist_ports(path):
    """Every port bit of the netlist's top module, as a constraint file names it (name, name[i])."""
    mods = json.load(open(path))["modules"]
    top = next(m for m in mods.values() if int(m.get("attributes", {}).get("top", "0"), 2))
    out = set()
    for name, p in top["ports"].items():
        n, off = len(p["bits"]), p.get("offset", 0)
        out |= {name} if n == 1 else {f"{name}[{off + i}]" for i in range(n)}
    return out


def pnr_command(root, flow, design):
    """The place-and-route command (list of words) of the design's netlist on the device: pins from
    the device's first constraint file (name order) that places every port, else unconstrained."""
    dev = device(root, flow)
    nl = netlist(root, design)
    try:
        ports = netlist_ports(nl)
    except (OSError, ValueError, KeyError, StopIteration) as e:
        raise RegistryError(f"{os.path.relpath(nl, root)}: not a Yosys netlist ({e})")
    constraint = next(
        (c for c in dev.constraint_files(root) if ports <= dev.constraint_ports(c)), None
    )
    stem = os.path.join(root, "synth", "build", design)
    if constraint is None and not dev.family.unconstrained:
        # The program places no unconstrained port: the device's free pins, in a file of its own
        # (devices.PinsError when the ports outnumber them).
        constraint = dev.pin_constraints(ports, stem + ".pins")
    t = table(root)
    log = report(root, dev.name, design)
    return dev.pnr_command(nl, stem, log, constraint, t.freq, t.seed, root)


def pins_log(root, flow, design, why):
    """The place-and-route log of a design whose ports outnumber the device's pins: the count as
    nextpnr's utilisation lines give theirs (pnr_result reads "does not fit")."""
    dev = device(root, flow)
    used, have = re.match(r"(\d+) port bits, (\d+) ", why).groups()
    with open(report(root, dev.name, design), "w") as f:
        f.write(
            f"Info: not placed: {why}\nInfo: Device utilisation:\n"
            f"Info: \t{'USER_IO':>20}: {int(used):>7}/{int(have):>7} "
            f"{100 * int(used) // int(have):>5}%\n"
        )


# --- Reports (synth/reports/, written by scripts/synth.sh) -------------------------------------


def report(root, flow, design):
    """synth/reports/<family>_<design>.txt for a family (generic, ice40, xilinx, ...), or the
    place-and-route log nextpnr_<design>.log for a device (hx8k, up5k, ...; aliases allowed)."""
    t = table(root)
    flow = t.canonical(flow)
    if t.target(flow) is None:
        raise RegistryError(f"'{flow}' is not a synthesis flow (known: {', '.join(t.flows())})")
    name = f"nextpnr_{design}.log" if flow in t.devices else f"{flow}_{design}.txt"
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
    for m in re.finditer(r"^\s+(\S+)\s+(\d+)\s*$", blocks[-1], re.MULTILINE):
        out[m.group(1)] = int(m.group(2))
    return out


def pnr_result(path, dev):
    """(Fmax MHz or None, (used, total) logic cells or None, why there is no Fmax: "not run",
    "does not fit", "failed" or "") of a nextpnr log of the device (a devices.Device)."""
    if not os.path.exists(path):
        return None, None, "not run"
    text = open(path).read()
    # The design's one clock: nextpnr also times its constant nets when a DSP block's clock pin is
    # tied low (the UP5K's SB_MAC16 with MULT = 1: '$PACKER_GND_NET...'), which is no clock.
    fmax = [
        f
        for name, f in re.findall(r"Max frequency for clock\s+'([^']*)':\s+([\d.]+) MHz", text)
        if not name.startswith("$PACKER_")
    ]
    lc = re.findall(rf"{re.escape(dev.family.pnr_cell)}:\s+(\d+)/\s*(\d+)", text)
    lc = (int(lc[-1][0]), int(lc[-1][1])) if lc else None
    if not fmax:
        # Larger than the device: a utilisation line over its total, or the placer's own words;
        # any other stop (a program's error) is a failure.
        counts = re.findall(r"^Info:\s+\w+:\s+(\d+)/\s*(\d+)", text, re.MULTILINE)
        over = any(int(u) > int(n) for u, n in counts)
        why = (
            "does not fit"
            if over or re.search(r"(Unable to place|too many)", text, re.IGNORECASE)
            else "failed"
        )
        return None, lc, why
    return float(fmax[-1]), lc, ""


def pnr_count(path, name):
    """(used, available) of one utilisation line of a nextpnr log (ICESTORM_DSP, MULT18X18D, ...),
    or None."""
    if not name or not os.path.exists(path):
        return None
    m = re.findall(
        rf"^Info:\s+{re.escape(name)}:\s+(\d+)/\s*(\d+)", open(path).read(), re.MULTILINE
    )
    return (int(m[-1][0]), int(m[-1][1])) if m else None


def pnr_constrained(path, dev):
    """True when the log's run had a constraint file, False when not, None when the log does not
    say."""
    if not dev.family.unconstrained_log or not os.path.exists(path):
        return None
    return re.search(dev.family.unconstrained_log, open(path).read()) is None


def default_top_stages(root):
    """The registry lines that bound the default acore_top's clock on the default device, which it
    does not fit: the lines placed there without parameters of a module the default top instantiates
    (each stage at its defaults is the top's)."""
    subs = rtl_submodules(root, "acore_top")
    dev = device(root).name
    return [l for l in load(root) if dev in l.flows and not l.params and l.module in subs]


# --- Command line -------------------------------------------------------------------------------


def write_if_changed(path, text):
    """Writes the file unless it holds that text already (CMake then keeps its time stamp)."""
    try:
        if open(path).read() == text:
            return
    except OSError:
        pass
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def main(argv):
    import argparse

    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--root", default=root)
    sub = ap.add_subparsers(dest="cmd", required=True)
    a = sub.add_parser("lines")
    a.add_argument("--flow", default="")
    a.add_argument("--module", default="")
    a.add_argument("--names", default="")
    a.add_argument("--tag", default="")
    p = sub.add_parser("params")
    p.add_argument("name")
    c = sub.add_parser("cmake")
    c.add_argument("out")
    for cmd in ("synth", "synth-tasks"):
        s = sub.add_parser(cmd)
        s.add_argument("--names", default="")
        s.add_argument("--flows", default="")
    r = sub.add_parser("pnr-command")
    r.add_argument("device")
    r.add_argument("design")
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    split = lambda x: [v for v in x.split(",") if v]
    try:
        if args.cmd == "lines":
            for l in select(
                args.root,
                split(args.flow),
                args.module or None,
                split(args.names),
                args.tag or None,
            ):
                print(l)
        elif args.cmd == "params":
            print(get(args.root, args.name).param_text())
        elif args.cmd == "cmake":
            write_if_changed(args.out, cmake_text(args.root))
        elif args.cmd == "synth":
            for d in synth_designs(args.root, split(args.names), split(args.flows)):
                params = " ".join(f"{k}={v}" for k, v in d.params)
                print(
                    " ".join(
                        x for x in (d.name, d.top, d.source or "-", ",".join(d.flows), params) if x
                    )
                )
        elif args.cmd == "synth-tasks":
            for task in synth_tasks(args.root, split(args.names), split(args.flows)):
                print("\t".join(task))
        else:
            try:
                print("\n".join(pnr_command(args.root, args.device, args.design)))
            except devices.PinsError as e:
                # Not an error of the flow: a measurement (scripts/synth.sh: "does not fit").
                pins_log(args.root, args.device, args.design, str(e))
                print(f"registry: {args.design}: does not fit the pins: {e}", file=sys.stderr)
                return 3
    except RegistryError as e:
        print(f"registry: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
