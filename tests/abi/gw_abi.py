#!/usr/bin/python3
"""The ABI record of libgranwave: the layout of every struct of the installed
headers, the value of every constant of their enums and (with GCC) the
declaration of every function they declare, as the compiler sees them,
compared with the committed record tests/abi/gw_abi.txt.

Why: the library writes a caller's struct whole (a result, a gw_err, a
gw_layer_sample). A caller compiled against an older header, or a hand-made
mirror, that is shorter is overrun (session 29: a stale ctypes mirror of
gw_layer_sample, 96 bytes for 168, wrote 72 bytes past its end). The soname is
libgranwave.so.GW_ABI_VERSION, so a program linked against another ABI is
refused by the dynamic linker; this script makes sure the number changes when
a layout (or a constant, or a declaration) does.

The layout comes from the compiler, not from parsing C here: a translation
unit that includes every installed header is compiled with
-g -fno-eliminate-unused-debug-types (so every type is described, used or
not), and its DWARF, printed by readelf, gives each struct's size and each
member's offset, size and type. A struct counts as public when the DWARF says
it is declared in one of the installed headers (the install rule's list,
app/lib/CMakeLists.txt), so a new struct in any of them is in the record, and
the check fails until the record has it. DWARF describes no function that
is only declared, so the functions come from GCC's -aux-info listing of the
same compilation (--aux; with another compiler they are not compared).
The exported variables (the solver types' tables gw_solver_*, the sweep models,
gw_stats_table_required) come from the library's dynamic symbol table (--library:
every defined global data symbol gw_*, with its size, the size a program's copy
relocation takes) and their types from the same DWARF (GCC describes each
extern declaration; with a compiler that does not, the types are not compared).

  gw_abi.py check ARGS   exit 0 when the record matches, 1 with the differences
  gw_abi.py write ARGS   rewrite the record; refused (exit 1) when what the
                         record holds changed and GW_ABI_VERSION did not
ARGS: --object O --readelf R --headers "h1,h2,..." --record F --abi N
      [--aux O.aux] [--library LIB] [--sizes PROG] [--soname-of LIB] [--python-lib python/granwave/_lib.py]
Regenerate after a change: cmake --build build --target gw_abi_record
"""
import argparse
import os
import re
import subprocess
import sys

REGENERATE = "cmake --build build --target gw_abi_record"

DIE = re.compile(r"^\s*<(\d+)><([0-9a-f]+)>: Abbrev Number: (\d+)(?: \((DW_TAG_\w+)\))?")
ATTR = re.compile(r"^\s*<[0-9a-f]+>\s+(DW_AT_\w+)\s*:\s?(.*)$")


def _value(text):
    """An attribute's value as readelf prints it: strings may be indirect."""
    m = re.match(r"\((?:indirect|indexed) (?:line )?string[,:] [^)]*\): (.*)$", text)  # GCC's, Clang's
    if m:
        return m.group(1)
    return text.strip()


def read_dies(readelf, obj):
    """Every DIE of obj's .debug_info, {offset: die} (each a dict of its tag,
    attrs, children's offsets and own offset), and the CU's pointer size."""
    out = subprocess.run([readelf, "--debug-dump=info", obj], check=True,
                         capture_output=True, text=True).stdout
    dies, stack, cur, pointer_size = {}, [], None, 0
    for line in out.splitlines():
        m = re.match(r"\s*Pointer Size:\s*(\d+)", line)  # the CU's: Clang gives pointers no byte size
        if m:
            pointer_size = int(m.group(1))
            continue
        m = DIE.match(line)
        if m:
            depth, off, tag = int(m.group(1)), int(m.group(2), 16), m.group(4)
            del stack[depth:]
            if tag is None:  # Abbrev Number: 0, the end of a list of children
                cur = None
                continue
            cur = {"tag": tag, "attrs": {}, "children": [], "off": off}
            dies[off] = cur
            if stack:
                dies[stack[-1]]["children"].append(off)
            stack.append(off)
            continue
        m = ATTR.match(line)
        if m and cur is not None:
            cur["attrs"][m.group(1)] = _value(m.group(2))
    return dies, pointer_size


def read_files(readelf, obj):
    """The line table's file names: {index: basename} (DWARF 4 and 5 forms)."""
    out = subprocess.run([readelf, "--debug-dump=line", obj], check=True,
                         capture_output=True, text=True).stdout
    files, inside = {}, False
    for line in out.splitlines():
        if "The File Name Table" in line:
            inside = True
            continue
        if inside:
            s = line.strip()
            if not s:
                if files:
                    inside = False
                continue
            if s.startswith("Entry"):
                continue
            parts = s.split()
            if not parts[0].isdigit():
                inside = False
                continue
            files[int(parts[0])] = os.path.basename(parts[-1])  # the name is the last column
    return files


AUX = re.compile(r"^/\* (.+):\d+:\w+ \*/ extern (.*\b(gw_\w+) \(.*\));")


def read_functions(aux, public, header):
    """The functions the installed headers declare, {name: declaration}, from
    GCC's -aux-info listing of the same file (every prototype it saw, with
    its types spelt out: "int gw_chain_collide (const gw_chain *, ...)").
    DWARF describes no function a file only declares."""
    fns = {}
    with open(aux, encoding="utf-8") as f:
        for line in f:
            m = AUX.match(line.strip())
            if m and os.path.basename(m.group(1)) in public:
                fns[m.group(3)] = " ".join(m.group(2).split())
                header[("fn", m.group(3))] = os.path.basename(m.group(1))
    return fns


def read_data_symbols(readelf, lib):
    """The library's exported variables, {name: size}: every defined GLOBAL
    OBJECT symbol of its dynamic symbol table named gw_*. The size is what a
    program linked against the library copies (a copy relocation): a table
    grown under the same soname is cut short in such a program."""
    out = subprocess.run([readelf, "--dyn-syms", "-W", lib], check=True, capture_output=True, text=True).stdout
    syms = {}
    for line in out.splitlines():
        w = line.split()
        # Num: Value Size Type Bind Vis Ndx Name
        if len(w) >= 8 and w[3] == "OBJECT" and w[4] == "GLOBAL" and w[6] != "UND" and w[7].startswith("gw_"):
            syms[w[7].split("@")[0]] = int(w[2], 0)
    return syms


def _ref(text):
    m = re.match(r"<0x([0-9a-f]+)>", text)
    return int(m.group(1), 16) if m else None


def _int(text):
    m = re.match(r"-?\d+", text)
    if m:
        return int(m.group(0))
    m = re.search(r"DW_OP_plus_uconst: (\d+)", text)  # DWARF 2 member locations
    if m:
        return int(m.group(1))
    raise ValueError(f"no number in {text!r}")


class Layout:
    def __init__(self, dies_ptr, files, public):
        self.dies, self.pointer_size = dies_ptr
        self.files, self.public = files, public
        self.structs = {}   # name -> size
        self.members = {}   # (struct, member) -> (offset, size, type)
        self.consts = {}    # enumerator -> value
        self.fns = {}       # function -> declaration (with --aux only)
        self.vars = {}      # exported variable -> [size, type] (size from --library; type "" unknown)
        self.header = {}    # (kind, name) -> the header declaring it
        self.typedef_of = {}  # off of a struct/enum/union -> its typedef's name
        for d in self.dies.values():
            if d["tag"] == "DW_TAG_typedef" and "DW_AT_type" in d["attrs"]:
                self.typedef_of.setdefault(_ref(d["attrs"]["DW_AT_type"]), d["attrs"].get("DW_AT_name"))

    def name_of(self, d):
        return d["attrs"].get("DW_AT_name") or self.typedef_of.get(d["off"])

    def header_of(self, d):
        f = d["attrs"].get("DW_AT_decl_file")
        return self.files.get(_int(f)) if f is not None else None

    def is_public(self, d):
        return self.header_of(d) in self.public

    def strip(self, off):
        """Past const, volatile and typedefs of non-aggregates."""
        while off is not None:
            d = self.dies[off]
            if d["tag"] in ("DW_TAG_const_type", "DW_TAG_volatile_type", "DW_TAG_restrict_type",
                            "DW_TAG_atomic_type"):
                off = _ref(d["attrs"].get("DW_AT_type", ""))
            elif d["tag"] == "DW_TAG_typedef":
                t = _ref(d["attrs"].get("DW_AT_type", ""))
                if t is None:
                    return off
                off = t
            else:
                return off
        return None

    def size(self, off):
        off = self.strip(off)
        if off is None:
            return 0
        d = self.dies[off]
        if "DW_AT_byte_size" in d["attrs"]:
            return _int(d["attrs"]["DW_AT_byte_size"])
        if d["tag"] == "DW_TAG_pointer_type":
            return self.pointer_size
        if d["tag"] == "DW_TAG_array_type":
            n = 1
            for c in d["children"]:
                n *= self.count(self.dies[c])
            return n * self.size(_ref(d["attrs"]["DW_AT_type"]))
        return 0

    def count(self, sub):
        a = sub["attrs"]
        if "DW_AT_count" in a:
            return _int(a["DW_AT_count"])
        if "DW_AT_upper_bound" in a:
            return _int(a["DW_AT_upper_bound"]) + 1 - _int(a.get("DW_AT_lower_bound", "0"))
        return 0  # a flexible array member

    def type_text(self, off):
        """A type as compiler-independent text: base types by kind and size
        (int32, uint64, float64, char8), pointers, arrays, aggregates by name,
        function pointers by their parameters."""
        off = self.strip(off)
        if off is None:
            return "void"
        d = self.dies[off]
        t, a = d["tag"], d["attrs"]
        if t == "DW_TAG_base_type":
            enc = a.get("DW_AT_encoding", "")
            bits = 8 * _int(a["DW_AT_byte_size"])
            for key, kind in (("boolean", "bool"), ("float", "float"), ("unsigned char", "uchar"),
                              ("signed char", "char"), ("unsigned", "uint"), ("signed", "int")):
                if key in enc:
                    return f"{kind}{bits}"
            return f"base{bits}"
        if t == "DW_TAG_pointer_type":
            return self.type_text(_ref(a.get("DW_AT_type", ""))) + "*"
        if t == "DW_TAG_array_type":
            dims = "".join(f"[{self.count(self.dies[c])}]" for c in d["children"])
            return self.type_text(_ref(a["DW_AT_type"])) + dims
        if t in ("DW_TAG_structure_type", "DW_TAG_union_type", "DW_TAG_enumeration_type"):
            kind = {"DW_TAG_structure_type": "struct", "DW_TAG_union_type": "union",
                    "DW_TAG_enumeration_type": "enum"}[t]
            return f"{kind} {self.name_of(d) or '<anonymous>'}"
        if t == "DW_TAG_subroutine_type":
            params = [self.type_text(_ref(self.dies[c]["attrs"].get("DW_AT_type", "")))
                      for c in d["children"] if self.dies[c]["tag"] == "DW_TAG_formal_parameter"]
            if any(self.dies[c]["tag"] == "DW_TAG_unspecified_parameters" for c in d["children"]):
                params.append("...")
            return f"fn({','.join(params)})->{self.type_text(_ref(a.get('DW_AT_type', '')))}"
        return t

    def add_members(self, struct, d, base, prefix):
        for c in d["children"]:
            m = self.dies[c]
            if m["tag"] != "DW_TAG_member":
                continue
            a = m["attrs"]
            off = base + _int(a.get("DW_AT_data_member_location", "0"))
            tref = _ref(a["DW_AT_type"])
            name = a.get("DW_AT_name")
            inner = self.dies.get(self.strip(tref))
            anon = inner is not None and inner["tag"] in ("DW_TAG_structure_type", "DW_TAG_union_type") \
                and not self.name_of(inner)
            if anon:  # members of a nested anonymous struct or union, by their path
                self.add_members(struct, inner, off, prefix + (name + "." if name else ""))
                continue
            where = str(off)
            if "DW_AT_bit_size" in a:
                bit = _int(a.get("DW_AT_data_bit_offset", "0"))
                where = f"{off}+bit{bit}:{_int(a['DW_AT_bit_size'])}"
            self.members[(struct, prefix + name)] = (where, self.size(tref), self.type_text(tref))

    def collect(self):
        for d in self.dies.values():
            if not self.is_public(d) or ("DW_AT_declaration" in d["attrs"] and d["tag"] != "DW_TAG_variable"):
                continue
            if d["tag"] in ("DW_TAG_structure_type", "DW_TAG_union_type"):
                name = self.name_of(d)
                if not name:
                    continue  # anonymous, inside another: recorded by its members' paths
                self.structs[name] = _int(d["attrs"]["DW_AT_byte_size"])
                self.header[("struct", name)] = self.header_of(d)
                self.add_members(name, d, 0, "")
            elif d["tag"] == "DW_TAG_variable" and "DW_AT_external" in d["attrs"] and "DW_AT_name" in d["attrs"]:
                tref = _ref(d["attrs"].get("DW_AT_type", ""))
                self.vars[d["attrs"]["DW_AT_name"]] = [self.size(tref), self.type_text(tref)]
                self.header[("var", d["attrs"]["DW_AT_name"])] = self.header_of(d)
            elif d["tag"] == "DW_TAG_enumeration_type":
                for c in d["children"]:
                    e = self.dies[c]
                    if e["tag"] == "DW_TAG_enumerator":
                        self.consts[e["attrs"]["DW_AT_name"]] = _int(e["attrs"]["DW_AT_const_value"])
                        self.header[("const", e["attrs"]["DW_AT_name"])] = self.header_of(d)
        return self


def record_lines(abi, plat, lay):
    out = ["# libgranwave's ABI record (tests/abi/gw_abi.py): the size of every struct of the",
           "# installed headers, each member's offset, size and type, every enum constant",
           "# and every function's declaration (GCC's -aux-info), as the compiler sees",
           "# them, and every exported variable's size (the library's dynamic symbol",
           "# table) and type. test_abi compares the build's with this file; after a change,",
           "# regenerate it with",
           f"#   {REGENERATE}",
           "# (refused while what this record holds changed and GW_ABI_VERSION did not).",
           "# The layouts are those of one platform (the ELF class and machine below);",
           "# another platform's build is not compared with them.",
           f"abi {abi}",
           f"platform {plat}"]
    for s in sorted(lay.structs):
        out.append(f"struct {s} {lay.structs[s]} {lay.header[('struct', s)]}")
        ms = [(k[1], v) for k, v in lay.members.items() if k[0] == s]
        ms.sort(key=lambda kv: (int(kv[1][0].split("+")[0]), kv[0]))
        for name, (where, size, typ) in ms:
            out.append(f"member {s} {name} {where} {size} {typ}")
    for c in sorted(lay.consts):
        out.append(f"const {c} {lay.consts[c]} {lay.header[('const', c)]}")
    for fn in sorted(lay.fns):
        out.append(f"fn {fn} {lay.header[('fn', fn)]} {lay.fns[fn]}")
    for v in sorted(lay.vars):
        out.append(f"var {v} {lay.vars[v][0]} {lay.header[('var', v)]} {lay.vars[v][1]}")
    return out


def parse_record(path):
    rec = {"abi": None, "platform": None, "structs": {}, "members": {}, "consts": {}, "fns": {}, "vars": {},
           "header": {}}
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            w = line.split(" ", 5)
            if w[0] == "abi" and len(w) == 2:
                rec["abi"] = int(w[1])
            elif w[0] == "platform":
                rec["platform"] = line.split(" ", 1)[1]
            elif w[0] == "struct" and len(w) == 4:
                rec["structs"][w[1]] = int(w[2])
                rec["header"][("struct", w[1])] = w[3]
            elif w[0] == "member" and len(w) == 6:
                rec["members"][(w[1], w[2])] = (w[3], int(w[4]), w[5])
            elif w[0] == "const" and len(w) == 4:
                rec["consts"][w[1]] = int(w[2])
                rec["header"][("const", w[1])] = w[3]
            elif w[0] == "var" and len(w) >= 5:
                v = line.split(" ", 4)
                rec["vars"][v[1]] = [int(v[2]), v[4]]
                rec["header"][("var", v[1])] = v[3]
            elif w[0] == "fn" and len(w) >= 4:
                rec["fns"][w[1]] = line.split(" ", 3)[3]
                rec["header"][("fn", w[1])] = w[2]
            else:
                raise ValueError(f"{path}:{n}: not a record line: {line!r}")
    if rec["abi"] is None or rec["platform"] is None:
        raise ValueError(f"{path}: no 'abi N' or 'platform ...' line")
    return rec


def restrict(rec, public):
    """The record without what headers this build does not install declare
    (gw_layer.h and gw_layer_study.h in a build with GW_BUILD_LAYER=OFF), and
    the names of those headers."""
    out = {**rec, "structs": {}, "members": {}, "consts": {}, "fns": {}, "vars": {}}
    left = set()
    for kind, key in (("struct", "structs"), ("const", "consts"), ("fn", "fns"), ("var", "vars")):
        for name, v in rec[key].items():
            h = rec["header"][(kind, name)]
            if h in public:
                out[key][name] = v
            else:
                left.add(h)
    out["members"] = {k: v for k, v in rec["members"].items() if k[0] in out["structs"]}
    return out, sorted(left)


def compare(rec, lay):
    """(breaking, additions): lists of lines. Breaking: a struct of the record
    gone or resized, a member gone, moved, resized or retyped, a member added
    to a struct (the overrun of an older caller), an enum constant gone or
    changed, a function gone or its declaration changed. Additions: a new
    struct, constant or function (old callers never see them), which need the
    record regenerated but no new ABI number."""
    brk, add = [], []
    for s, size in sorted(rec["structs"].items()):
        if s not in lay.structs:
            brk.append(f"struct {s}: gone from the headers")
        elif lay.structs[s] != size:
            brk.append(f"struct {s}: {size} bytes in the record, {lay.structs[s]} now")
    for (s, m), v in sorted(rec["members"].items()):
        if s not in lay.structs:
            continue
        now = lay.members.get((s, m))
        if now is None:
            brk.append(f"struct {s}: member {m} gone (was at offset {v[0]})")
        elif tuple(now) != v:
            brk.append(f"struct {s}: member {m}: offset {v[0]} size {v[1]} {v[2]} in the record, "
                       f"offset {now[0]} size {now[1]} {now[2]} now")
    for (s, m), now in sorted(lay.members.items()):
        if s in rec["structs"] and (s, m) not in rec["members"]:
            brk.append(f"struct {s}: member {m} added (offset {now[0]}, {now[1]} bytes)")
    for c, v in sorted(rec["consts"].items()):
        if c not in lay.consts:
            brk.append(f"constant {c}: gone (was {v})")
        elif lay.consts[c] != v:
            brk.append(f"constant {c}: {v} in the record, {lay.consts[c]} now")
    if lay.fns:  # GCC's -aux-info: otherwise the functions are not compared
        for fn, decl in sorted(rec["fns"].items()):
            if fn not in lay.fns:
                brk.append(f"function {fn}: gone (was {decl})")
            elif lay.fns[fn] != decl:
                brk.append(f"function {fn}: {decl} in the record, {lay.fns[fn]} now")
        for fn in sorted(set(lay.fns) - set(rec["fns"])):
            add.append(f"function {fn}: new ({lay.fns[fn]}), not in the record")
    # the exported variables (their sizes from the library's symbol table;
    # the types where the DWARF described them, "" otherwise)
    for v, (size, typ) in sorted(rec.get("vars", {}).items() if lay.vars else ()):
        if v not in lay.vars:
            brk.append(f"variable {v}: gone (was {size} bytes, {typ})")
            continue
        now_size, now_typ = lay.vars[v]
        if now_size != size:
            brk.append(f"variable {v}: {size} bytes in the record, {now_size} now (a program's copy of it is cut "
                       f"short)")
        if now_typ and now_typ != typ:
            brk.append(f"variable {v}: type {typ} in the record, {now_typ} now")
    for v in sorted(set(lay.vars) - set(rec.get("vars", {}))):
        add.append(f"variable {v}: new ({lay.vars[v][0]} bytes, {lay.vars[v][1] or 'type unknown'}), not in the "
                   f"record")
    for s in sorted(set(lay.structs) - set(rec["structs"])):
        add.append(f"struct {s}: new ({lay.structs[s]} bytes), not in the record")
    for c in sorted(set(lay.consts) - set(rec["consts"])):
        add.append(f"constant {c}: new ({lay.consts[c]}), not in the record")
    return brk, add


def platform(readelf, obj):
    """The object's ELF class and machine ("ELF64 Advanced Micro Devices X86-64"):
    sizes of long and pointers, alignment and FILE differ between them."""
    out = subprocess.run([readelf, "-h", obj], check=True, capture_output=True, text=True).stdout
    get = {k.strip(): v.strip() for k, _, v in (line.partition(":") for line in out.splitlines())}
    return f"{get.get('Class', '?')} {get.get('Machine', '?')}"


def self_test(lay):
    """compare() on records altered as a change of the headers would alter
    them, so that a compare that can no longer fail fails here: the session-29
    case (gw_layer_sample without its settled record: 96 bytes for 168), a
    member moved, a constant changed, a struct the record lacks."""
    base = {"abi": 0, "structs": dict(lay.structs), "members": dict(lay.members), "consts": dict(lay.consts),
            "fns": {}, "vars": {v: list(t) for v, t in lay.vars.items()}}
    fails = []

    def expect(what, rec, kind, needle):
        brk, add = compare(rec, lay)
        got = brk if kind == "breaking" else add
        if not any(needle in line for line in got) or (kind == "addition" and brk):
            fails.append(f"self-test: {what} not reported as {kind} ({needle!r}): {brk + add}")

    if "gw_layer_sample" in lay.structs and ("gw_layer_sample", "settled") in lay.members:
        rec = {**base, "structs": {**base["structs"], "gw_layer_sample": 96},
               "members": {k: v for k, v in base["members"].items() if k != ("gw_layer_sample", "settled")}}
        expect("gw_layer_sample appended to", rec, "breaking", "gw_layer_sample: member settled added")
        expect("gw_layer_sample grown", rec, "breaking",
               f"gw_layer_sample: 96 bytes in the record, {lay.structs['gw_layer_sample']} now")
    k = ("gw_err", "msg")
    moved = (str(int(lay.members[k][0]) + 8),) + tuple(lay.members[k][1:])
    expect("gw_err.msg moved", {**base, "members": {**base["members"], k: moved}}, "breaking", "member msg: offset")
    c = sorted(lay.consts)[0]
    expect(f"{c} changed", {**base, "consts": {**base["consts"], c: lay.consts[c] + 1}}, "breaking", f"constant {c}")
    expect("a new struct", {**base, "structs": {n: v for n, v in base["structs"].items() if n != "gw_err"},
                            "members": {m: v for m, v in base["members"].items() if m[0] != "gw_err"}},
           "addition", "struct gw_err: new")
    if lay.fns:
        base["fns"] = dict(lay.fns)
        fn = "gw_chain_collide" if "gw_chain_collide" in lay.fns else sorted(lay.fns)[0]
        changed = lay.fns[fn].replace(", gw_err *)", ", int, gw_err *)") if ", gw_err *)" in lay.fns[fn] \
            else lay.fns[fn] + " "
        expect(f"{fn} given a parameter", {**base, "fns": {**base["fns"], fn: changed}}, "breaking",
               f"function {fn}:")
        expect("a new function", {**base, "fns": {f: d for f, d in base["fns"].items() if f != fn}}, "addition",
               f"function {fn}: new")
    if lay.vars:  # a table grown or retyped, a variable gone or new (session 30: not recorded before)
        v = "gw_solver_cvode" if "gw_solver_cvode" in lay.vars else sorted(lay.vars)[0]
        size, typ = lay.vars[v]
        expect(f"{v} resized", {**base, "vars": {**base["vars"], v: [size + 8, typ]}}, "breaking",
               f"variable {v}: {size + 8} bytes in the record, {size} now")
        if typ:
            expect(f"{v} retyped", {**base, "vars": {**base["vars"], v: [size, "int32"]}}, "breaking",
                   f"variable {v}: type int32 in the record")
        expect(f"{v} gone", {**base, "vars": {**base["vars"], "gw_no_such_variable": [8, "int64"]}}, "breaking",
               "variable gw_no_such_variable: gone")
        expect("a new variable", {**base, "vars": {n: t for n, t in base["vars"].items() if n != v}}, "addition",
               f"variable {v}: new")
    if compare(base, lay) != ([], []):
        fails.append(f"self-test: the build's own layout differs from itself: {compare(base, lay)}")
    return fails


def soname(readelf, lib):
    out = subprocess.run([readelf, "-d", lib], check=True, capture_output=True, text=True).stdout
    m = re.search(r"\(SONAME\).*\[(.*)\]", out)
    return m.group(1) if m else None


def _listed(lines, most=40):
    """Indented, at most `most` of them (a new header can add hundreds)."""
    out = ["  " + line for line in lines[:most]]
    if len(lines) > most:
        out.append(f"  ... and {len(lines) - most} more")
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("mode", choices=("check", "write"))
    ap.add_argument("--object", required=True)
    ap.add_argument("--readelf", required=True)
    ap.add_argument("--headers", required=True, help="the installed headers, ';'-separated")
    ap.add_argument("--record", required=True)
    ap.add_argument("--abi", type=int, required=True, help="GW_ABI_VERSION of the build")
    ap.add_argument("--aux", help="GCC's -aux-info listing of the object's source (the functions)")
    ap.add_argument("--library", help="libgranwave.so: its exported variables (dynamic symbol table)")
    ap.add_argument("--sizes", help="tests/abi/abi_sizes, linked to libgranwave.so")
    ap.add_argument("--soname-of", help="libgranwave.so, whose soname must carry the ABI")
    ap.add_argument("--python-lib", help="python/granwave/_lib.py, written for one ABI")
    a = ap.parse_args(argv)

    public = {os.path.basename(h) for h in re.split("[,;]", a.headers) if h}
    lay = Layout(read_dies(a.readelf, a.object), read_files(a.readelf, a.object), public).collect()
    if a.aux:
        lay.fns = read_functions(a.aux, public, lay.header)
        if "gw_version" not in lay.fns or len(lay.fns) < 100:
            print(f"gw_abi: read {len(lay.fns)} functions from {a.aux} (no gw_version, or under 100): "
                  "the -aux-info listing not understood", file=sys.stderr)
            return 1
    if a.library:
        # the exported variables: names and sizes from the library; their
        # types from the DWARF's declarations (none with Clang: "")
        declared = lay.vars
        lay.vars = {}
        for v, size in read_data_symbols(a.readelf, a.library).items():
            lay.vars[v] = [size, declared[v][1] if v in declared else ""]
            lay.header.setdefault(("var", v), lay.header.get(("var", v)) or "?")
        if declared and set(declared) != set(lay.vars):
            print(f"gw_abi: the headers declare the variables {sorted(declared)} and {a.library} exports "
                  f"{sorted(lay.vars)}", file=sys.stderr)
            return 1
        if not lay.vars:
            print(f"gw_abi: {a.library} exports no variable gw_* (gw_solver_cvode at least): readelf's "
                  "--dyn-syms output not understood", file=sys.stderr)
            return 1
    else:
        lay.vars = {}  # not compared without the library
    # a readelf whose output this script no longer reads gives nothing: never a pass
    if "gw_err" not in lay.structs or lay.members.get(("gw_err", "msg"), (None, 0))[1] != 512 \
            or len(lay.structs) < 10:
        print(f"gw_abi: read {len(lay.structs)} structs from {a.object} (no gw_err of 512 bytes): "
              "readelf's output not understood", file=sys.stderr)
        return 1
    try:
        rec = parse_record(a.record)
    except (OSError, ValueError) as e:
        if a.mode == "check":
            print(f"gw_abi: {e}", file=sys.stderr)
            return 1
        rec = None
    plat = platform(a.readelf, a.object)
    if rec and rec["platform"] != plat:
        if a.mode == "write":
            print(f"gw_abi: not written: {a.record} is of {rec['platform']}, this build of {plat}", file=sys.stderr)
            return 1
        print(f"gw_abi: SKIP: the record is of {rec['platform']}, this build of {plat}: layouts not compared")
        return 77
    left = []
    if rec:
        rec, left = restrict(rec, public)
        if left and a.mode == "write":
            print(f"gw_abi: not written: this build does not install {', '.join(left)}, which the record "
                  "holds (regenerate it from a build of every module)", file=sys.stderr)
            return 1
    brk, add = compare(rec, lay) if rec else ([], [])

    if a.mode == "write":
        if not a.library or any(not t for _, t in lay.vars.values()):
            print("gw_abi: not written: the record's variables need --library and their types from the DWARF "
                  "(build with GCC to regenerate the record)", file=sys.stderr)
            return 1
        if not lay.fns and rec and rec["fns"]:
            print("gw_abi: not written: the record's functions come from GCC's -aux-info, which this build "
                  "lacks (build with GCC to regenerate the record)", file=sys.stderr)
            return 1
        if rec and brk and rec["abi"] == a.abi:
            print(f"gw_abi: not written: ABI {a.abi} changed (a layout, a constant, a declaration or a variable) and "
                  "GW_ABI_VERSION did not:",
                  file=sys.stderr)
            for line in _listed(brk):
                print(line, file=sys.stderr)
            print(f"  bump GW_ABI_VERSION in CMakeLists.txt (to {a.abi + 1}), then run {REGENERATE}",
                  file=sys.stderr)
            return 1
        with open(a.record, "w", encoding="utf-8") as f:
            f.write("\n".join(record_lines(a.abi, plat, lay)) + "\n")
        print(f"gw_abi: wrote {a.record}: ABI {a.abi}, {len(lay.structs)} structs, "
              f"{len(lay.members)} members, {len(lay.consts)} constants, {len(lay.fns)} functions, "
              f"{len(lay.vars)} variables")
        return 0

    fails = self_test(lay)
    if brk and rec["abi"] == a.abi:
        fails.append(f"the ABI (the public structs' layout, enum constants, function declarations, exported variables) changed "
                     f"while GW_ABI_VERSION stayed {a.abi}:")
        fails += _listed(brk)
        fails.append(f"  a caller compiled against the old headers would be overrun or call wrongly: bump GW_ABI_VERSION "
                     f"in CMakeLists.txt (to {a.abi + 1}) and regenerate the record: {REGENERATE}")
    elif brk or rec["abi"] != a.abi:
        fails.append(f"the record is of ABI {rec['abi']} and the headers of ABI {a.abi}"
                     + (" with another layout:" if brk else ":"))
        fails += _listed(brk)
        fails.append(f"  regenerate the record: {REGENERATE}")
    if add:
        fails.append("the record lacks what the headers now have:")
        fails += _listed(add)
        fails.append(f"  an addition needs no new ABI number; regenerate the record: {REGENERATE}")

    if a.sizes:  # the library's own numbers: its ABI and gw_struct_size for each struct
        names = sorted(lay.structs)
        p = subprocess.run([a.sizes], input="\n".join(names + ["gw_no_such_struct", ""]) + "\n",
                           capture_output=True, text=True)
        if p.returncode != 0:
            fails.append(f"{a.sizes} failed ({p.returncode}): {p.stderr.strip()}")
        else:
            got = dict(line.rsplit(" ", 1) for line in p.stdout.splitlines() if " " in line)
            if int(got.get("gw_abi_version()", -1)) != a.abi:
                fails.append(f"gw_abi_version() is {got.get('gw_abi_version()')}, GW_ABI_VERSION {a.abi}")
            for s in names:
                if int(got.get(s, -1)) != lay.structs[s]:
                    fails.append(f"gw_struct_size(\"{s}\") is {got.get(s)}, sizeof {lay.structs[s]}"
                                 + (": add it to app/lib/gw_abi.c" if got.get(s) == "0" else ""))
            for s, shown in (("gw_no_such_struct", '"gw_no_such_struct"'), ("(empty)", '""'), ("(null)", "NULL")):
                if got.get(s) != "0":
                    fails.append(f"gw_struct_size({shown}) is {got.get(s)}, not 0")
    if a.soname_of:
        want = f"libgranwave.so.{a.abi}"
        have = soname(a.readelf, a.soname_of)
        if have != want:
            fails.append(f"{a.soname_of}: soname {have}, expected {want} (the ABI number)")
    if a.python_lib:
        with open(a.python_lib, encoding="utf-8") as f:
            m = re.search(r"^ABI_VERSION = (\d+)$", f.read(), re.M)
        if not m or int(m.group(1)) != a.abi:
            fails.append(f"{a.python_lib}: ABI_VERSION {m.group(1) if m else '(none)'}, the headers' {a.abi}: "
                         "check its mirrors (GwErr, GwParam, GwStudy) against the record, then set it")

    if fails:
        print("gw_abi: FAIL", file=sys.stderr)
        for line in fails:
            print(line, file=sys.stderr)
        return 1
    print(f"gw_abi: PASS: ABI {a.abi}, {len(lay.structs)} structs, {len(lay.members)} members, "
          f"{len(lay.consts)} constants" + (f", {len(lay.vars)} variables" if lay.vars else
                                            " (variables not compared: no --library)")
          + (f", {len(lay.fns)} functions" if lay.fns else
                                            " (functions not compared: no -aux-info, not GCC)") + " as recorded"
          + (f" (not in this build, not compared: what {', '.join(left)} declare)" if left else "") + (", gw_struct_size of each" if a.sizes else "")
          + (f", soname libgranwave.so.{a.abi}" if a.soname_of else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
