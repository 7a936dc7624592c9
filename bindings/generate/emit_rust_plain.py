"""The safe Rust crate's plain structs (bindings/rust/navlink/src/plain_generated.rs) from the header model:
a `plain_struct!` invocation (plain.rs) for each header struct the crate mirrors, and navlink-sys's structs
that carry neither `size` nor `reserved` under Rust names (`pub type LinkId = sys::nl_link_id;`).

A plain struct has its C struct's fields in header order, with the header's field comments as their docs,
but `size`, `reserved*`, and a pointer with its `<name>_length` (a borrowed pointer has no place in a plain
`Copy` value: `nl_link_settings.plugin_settings_json`, which `World::generate_links` takes apart). Each
field's Rust type is decided by what the header says, in this order:
- the FIELD_TYPES table (fields the header says nothing of);
- a kind (`nl_agent_state`, a `typedef uint32_t` the headers follow with its `#define`s) is the crate's enum
  of the kind's name in CamelCase (`AgentState`; KIND_TYPES where it is another), `nl_status` is `Status`;
- a struct is its plain struct if the crate mirrors it, else its Rust name (the aliases here);
- a yes/no field is `bool`: every `uint8_t` field (the headers' flags are `uint8_t`, and the headers use
  `uint8_t` for nothing else but padding) and a wider integer whose comment opens as a flag's does
  ("1 if ...", "1: ...", "1 for ...", "1 (default) ...");
- a `uint32_t` whose comment names constants `NL_PREFIX_*` holds one of them: the crate's enum named after
  the prefix in CamelCase (`NL_UP_AXIS_*` is `UpAxis`); `NL_PREFIX_* bits`: a flag word, the FLAG_WORDS
  table's bit set (`NL_BUILD_WARNING_* bits` is `BuildWarnings`);
- any other number is its Rust number (`uint32_t` `u32`, `float` `f32`...), a fixed array a Rust array of
  the same length (`[u32; sys::NL_MAX_POLYGON_VERTICES]` when the header writes it so).

`Default` is the header's: the function that takes nothing and returns the struct (`nl_default_agent_def()`),
else its inline initialiser (`nl_link_init()`), else navlink-sys's `Default` (zeroed). Derives: `PartialEq`,
and `Eq` when no field is (or holds) a float. plain.rs's `FromC`/`IntoC` convert each field's value; every
enum of kinds.rs has them, the flag words and `Status` by hand there.
"""
import re
import textwrap

from emit_rust import SCALARS, WIDTH, Types, _doc, _header
from names import camel

PATH = "bindings/rust/navlink/src/plain_generated.rs"

# The header structs the crate mirrors as plain structs. Which ones is the crate's choice, not the header's:
# the header's other structs with `size` or `reserved` are inputs the crate builds from option types of its
# own (`WorldOptions`, `MeshOptions`, `NavmeshInput`, `NavmeshBuild`, `PathQuery`, `QueryFilter`...: they
# hold borrowed pointers, slices, closures) or outputs it reads into richer types (`PathShortfall`,
# `FinishedPath`, `PluginSummary`), and the plugin ABI's are navlink-sys's alone.
PLAIN = ["nl_mesh_info", "nl_ray_hit", "nl_navmesh_info", "nl_nav_polygon", "nl_nav_point",
         "nl_link_requirements", "nl_link", "nl_link_def", "nl_link_settings", "nl_link_generation_report",
         "nl_navmesh_file_info", "nl_path_point", "nl_path_result", "nl_path_queue_stats",
         "nl_navmesh_raycast_hit", "nl_agent_def", "nl_agent_info", "nl_agent_trajectory", "nl_agent_event",
         "nl_recast_settings"]

# Rust names that are not the C name in CamelCase (one line each, with why).
NAMES = {
    "nl_path_result": "PathSummary",  # the crate's PathResult (paths.rs) is this summary with the path's points
}

# Kinds whose crate enum is not named after the kind.
KIND_TYPES = {
    # one enum for a path point's segment and a link's kind (NL_SEGMENT_JUMP == NL_LINK_JUMP...)
    "nl_segment_kind": "LinkKind",
}

# Flag words: the header declares no type for a set of bits (a kind is one value of a set), so the crate's bit
# set over `NL_PREFIX_*` constants is named here.
FLAG_WORDS = {
    "NL_MESH_": "MeshFlags",  # level.rs
    "NL_BUILD_WARNING_": "BuildWarnings",  # navmesh.rs
}

# Fields whose type the header does not say (each a header comment away from a rule above).
FIELD_TYPES = {
    ("nl_mesh_info", "flags"): "MeshFlags",  # no comment in level.h; "NL_MESH_* bits" would say it
}

FLAG_DOC = re.compile(r"^1(?: if |: | for | \(default\))")
NAMED_CONSTANTS = re.compile(r"\b(NL_[A-Z0-9_]*_)\*( bits\b)?")
SENTENCE_END = re.compile(r"(?<=[.!?])\s+(?=[A-Z(`\"])")
NUMBERS = {"uint8_t", "uint16_t", "uint32_t", "uint64_t", "int8_t", "int16_t", "int32_t", "int64_t", "size_t",
           "float", "double"}


def _fail(struct, field, why):
    raise SystemExit("emit_rust_plain.py: %s.%s: %s (bindings/generate/emit_rust_plain.py says how a field's "
                     "Rust type is found)" % (struct["name"], field["name"], why))


def _bookkeeping(name):
    """`size` and `reserved*`: the fields that version a struct or pad it, not its content."""
    return name == "size" or name.startswith("reserved")


def _is_alias(struct, types):
    """A header struct the crate uses as navlink-sys's under a Rust name: no `size`, no `reserved`, no function."""
    return not any(_bookkeeping(f["name"]) for f in struct["fields"]) and not types.has_function(struct)


class Plain:
    def __init__(self, model):
        self.model = model
        self.types = Types(model)
        self.structs = {s["name"]: s for s in model["structs"]}
        self.kinds = {k["name"] for k in model["kinds"]}
        self.prefixes = {c["name"] for c in model["constants"]}
        for name in PLAIN:
            if name not in self.structs:
                raise SystemExit("emit_rust_plain.py: PLAIN names %s, which is no struct of the headers" % name)
        self.used = set()  # the crate's types the file uses (enums, flag words, Status)

    def name(self, c_name):
        return NAMES.get(c_name, camel(c_name))

    def _crate(self, rust):
        self.used.add(rust)
        return rust

    def left_out(self, struct):
        """The fields a plain struct does not have: `size`, `reserved*`, a pointer and its `_length`."""
        pointers = {f["name"] for f in struct["fields"] if "*" in f["type"] and not f["function"]}
        return [f["name"] for f in struct["fields"]
                if _bookkeeping(f["name"]) or f["name"] in pointers
                or any(f["name"] == p + "_length" for p in pointers)]

    def _element(self, struct, field, c_type):
        """The Rust type of one value of C type `c_type` (a scalar field, or an array's element)."""
        if c_type in self.kinds:
            return self._crate(KIND_TYPES.get(c_type, camel(c_type)))
        if c_type in self.structs:
            if c_type in PLAIN:
                return self.name(c_type)
            if _is_alias(self.structs[c_type], self.types):
                return camel(c_type)
            _fail(struct, field, "%s is neither a plain struct (PLAIN) nor one without size and reserved" % c_type)
        if c_type not in NUMBERS:
            _fail(struct, field, "no plain Rust type for %s" % c_type)
        return SCALARS[c_type]

    def field_type(self, struct, field):
        key = (struct["name"], field["name"])
        if key in FIELD_TYPES:
            return self._crate(FIELD_TYPES[key])
        if field["function"]:
            _fail(struct, field, "a function pointer in a plain struct")
        c_type, doc = field["type"], field["doc"]
        if not field["length"]:
            integer = c_type in NUMBERS and c_type not in ("float", "double")
            if c_type == "uint8_t" or integer and FLAG_DOC.match(doc):
                return "bool"
            named = NAMED_CONSTANTS.search(doc)
            if c_type == "uint32_t" and named:
                prefix, bits = named.group(1), named.group(2)
                if not any(c.startswith(prefix) for c in self.prefixes):
                    _fail(struct, field, "its comment names %s*, and no constant starts so" % prefix)
                if bits:
                    if prefix not in FLAG_WORDS:
                        _fail(struct, field, "%s* bits: a flag word FLAG_WORDS has no Rust type for" % prefix)
                    return self._crate(FLAG_WORDS[prefix])
                return self._crate(camel(prefix.rstrip("_")))
            return self._element(struct, field, c_type)
        row = re.match(r"^(.*)\[(\d+)\]$", c_type)  # float points[4][3]: rows of float[3]
        element = "[%s; %s]" % (self._element(struct, field, row.group(1).strip()), row.group(2)) if row \
            else self._element(struct, field, c_type)
        return "[%s; %s]" % (element, "sys::" + field["length_name"] if field["length_name"] else field["length"])

    def default(self, struct):
        """(Rust expression, what the doc says) of a plain struct's `Default`."""
        makers = [f["name"] for f in self.model["functions"] if not f["params"] and f["returns"] == struct["name"]]
        if makers:
            return "unsafe { sys::%s() }" % makers[0], "`%s()`" % makers[0]
        if struct["output_init"]:
            return "sys::%s()" % struct["output_init"], "all zero (`%s()`)" % struct["output_init"]
        if self.types.default(struct):
            return "sys::%s::default()" % struct["name"], "all zero"
        raise SystemExit("emit_rust_plain.py: %s has no default in the header nor in navlink-sys" % struct["name"])


def _struct_doc(struct):
    """The header's comment on a struct without its sentences on `size` (a plain struct has none)."""
    sentences = SENTENCE_END.split(" ".join(struct["doc"].split()))
    return " ".join(s for s in sentences if s and not re.search(r"\bsize\b", s))


def _names(items):
    items = ["`%s`" % i for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def _plain_struct(plain, struct):
    name = plain.name(struct["name"])
    left_out = plain.left_out(struct)
    fields = []
    for f in struct["fields"]:
        if f["name"] in left_out:
            continue
        fields += _doc(f["doc"], "        ") + ["        %s: %s," % (f["name"], plain.field_type(struct, f))]
    default, default_doc = plain.default(struct)
    derives = ["PartialEq"] + ([] if plain.types.has_float(struct) else ["Eq"])
    summary = _struct_doc(struct)
    mirror = "`%s`'s fields but %s, as plain Rust. `Default`: %s." % (struct["name"], _names(left_out), default_doc)
    doc = _doc(summary, "    ") + (["    ///"] if summary else []) + _doc(mirror, "    ")
    head = "    pub struct %s mirrors sys::%s," % (name, struct["name"])
    tail = " default %s, derives (%s) {" % (default, ", ".join(derives))
    head = [head + tail] if len(head + tail) <= WIDTH else [head, "       " + tail]
    return ["", "plain_struct! {"] + doc + head + fields + ["    }", "}"]


def _alias(struct):
    what = "navlink-sys's `%s` (no `size`, no `reserved`: nothing to leave out)." % struct["name"]
    doc = _doc(struct["doc"], "") + (["///"] if struct["doc"] else []) + _doc(what, "")
    return [""] + doc + ["pub type %s = sys::%s;" % (camel(struct["name"]), struct["name"])]


def outputs(model, sources):
    plain = Plain(model)
    out = []
    for s in model["structs"]:
        if s["name"] in PLAIN:
            out += _plain_struct(plain, s)
        elif _is_alias(s, plain.types):
            out += _alias(s)
    head = _header(sources, "The plain structs (plain.rs's `plain_struct!`) over the header structs the crate mirrors, "
                            "and navlink-sys's structs that carry neither `size` nor `reserved` under Rust names; "
                            "types.rs re-exports them. bindings/generate/emit_rust_plain.py says how each field's "
                            "Rust type is found.")
    used = sorted(plain.used)
    imports = ["use crate::plain::plain_struct;"]
    if used:
        imports += textwrap.wrap("use crate::{%s};" % ", ".join(used), WIDTH, subsequent_indent="    ")
    imports.append("use navlink_sys as sys;")
    return {PATH: "\n".join(head + imports + out) + "\n"}
