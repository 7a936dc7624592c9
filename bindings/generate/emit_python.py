"""The Python binding's raw layer (bindings/python/_navlink_abi.py) from the header model: constants, the
header's kinds as IntEnums, a ctypes class per struct with its fields, the callback types, the inline
output initialisers and every function's prototype. navlink.py builds the idiomatic layer on top.

Names: a struct nl_link_settings is the class LinkSettings, a callback nl_log_fn the type LogFn, a kind
nl_agent_state the IntEnum AgentState whose members drop the kind's common prefix (NL_AGENT_IDLE is
AgentState.IDLE; the module constant AGENT_IDLE is that member); every other NL_NAME is the constant NAME.
"""
import re
import textwrap

from names import camel, enum_prefix, generated_notice, is_id, ordered_items

# Classes whose plain name the idiomatic layer gives to a friendlier class.
CLASS_NAMES = {"nl_path_result": "PathResultInfo", "nl_path_shortfall": "PathShortfallInfo",
               "nl_query_filter": "QueryFilterDef"}
# Function pointer fields of plugin.h's structs are typed PREFIX + Field + Fn.
FIELD_FUNCTION_PREFIXES = {"nl_plugin_host": "Host", "nl_navmesh_builder": "Navmesh", "nl_link_kind_provider": "Link",
                           "nl_plugin_info": "Plugin"}
# Kinds that are bits or numbers to combine, not one of a set: constants only.
NOT_ENUMS = {"nl_status"}

SCALARS = {"uint8_t": "c_uint8", "uint32_t": "c_uint32", "int32_t": "c_int32", "uint64_t": "c_uint64",
           "float": "c_float", "double": "c_double", "size_t": "c_size_t", "char": "c_char", "int": "c_int",
           "void": "None"}


def class_name(c_name):
    return CLASS_NAMES.get(c_name, camel(c_name))


def callback_name(c_name):
    return camel(re.sub(r"_fn$", "", c_name)) + ("Fn" if c_name.endswith("_fn") else "")


class Types:
    """C type spellings to ctypes expressions."""

    def __init__(self, model):
        self.structs = {s["name"] for s in model["structs"]}
        self.kinds = {k["name"] for k in model["kinds"]}
        self.handles = {h["name"] for h in model["handles"]}
        self.callbacks = {c["name"]: c for c in model["callbacks"]}

    def of(self, spelling):
        array = re.match(r"^(.*)\[(\d+)\]$", spelling.strip())
        if array:  # a row of a two-dimensional array field
            return "(%s * %s)" % (self.of(array.group(1)), array.group(2))
        t = " ".join(spelling.replace("*", " * ").split())
        t = re.sub(r"\bconst\b\s*", "", t).strip()
        stars = t.count("*")
        base = t.replace("*", "").strip()
        if base in self.callbacks:
            cb = self.callbacks[base]
            stars -= 0 if cb["pointer"] else 1
            expr = callback_name(base)
        elif base == "char" and stars >= 1:
            stars -= 1
            expr = "c_char_p"
        elif base == "void" and stars >= 1:
            stars -= 1
            expr = "c_void_p"
        elif base in self.handles and stars >= 1:
            stars -= 1
            expr = "c_void_p"
        elif base in self.structs:
            expr = class_name(base)
        elif base in self.kinds:
            expr = "c_uint32"
        elif base in SCALARS:
            expr = SCALARS[base]
        else:
            raise SystemExit("emit_python.py: no ctypes type for '%s'" % spelling)
        for _ in range(stars):
            expr = "POINTER(%s)" % expr
        return expr

    def function(self, returns, params):
        return "CFUNCTYPE(%s)" % ", ".join([self.of(returns)] + [self.of(p) for p in params])


def _wrap(items, indent, width=116):
    """Items joined with ", " over lines of at most `width` characters, continuation lines at `indent`."""
    lines, line = [], ""
    for item in items:
        piece = item if not line else ", " + item
        if line and len(indent) + len(line) + len(piece) > width:
            lines.append(line + ",")
            line = item
        else:
            line += piece
    lines.append(line)
    return ("\n" + indent).join(lines)


def _doc(text):
    text = " ".join(text.split()).replace("\\", "\\\\").replace('"""', "'''")
    return text


def emit(model, sources):
    t = Types(model)
    out = ['"""The C ABI of libnavlink for ctypes; navlink.py imports everything here and builds the idiomatic',
           "layer on top.",
           ""] + textwrap.wrap(generated_notice(sources), 110) + ['"""',
           "# flake8: noqa",
           "import enum",
           "from ctypes import (CFUNCTYPE, POINTER, c_char, c_char_p, c_double, c_float, c_int, c_int32, c_size_t,",
           "                    c_uint8, c_uint32, c_uint64, c_void_p)",
           "from typing import Any, Dict, List, Tuple",
           "",
           "try:",
           "    from ._navlink_structs import _Growable, _Id, _read_as_enums, _Struct",
           "except ImportError:  # navlink.py run where it is (bindings/python on sys.path)",
           "    from _navlink_structs import _Growable, _Id, _read_as_enums, _Struct  # type: ignore[no-redef]",
           ""]

    # Kinds as IntEnums, then every constant.
    members = {}
    for kind in model["kinds"]:
        if kind["name"] in NOT_ENUMS or not kind["values"]:
            continue
        prefix = enum_prefix(kind["values"])
        name = camel(kind["name"])
        out += ["", "class %s(enum.IntEnum):" % name]
        doc = _doc(kind["doc"]) or "The header's %s." % kind["name"]
        out.append('    """%s (%s)"""' % (doc, kind["name"]))
        values = {c["name"]: c["value"] for c in model["constants"]}
        for c in kind["values"]:
            member = c[len(prefix):]
            members[c] = "%s.%s" % (name, member)
            out.append("    %s = %s" % (member, _literal(values[c])))
        out.append("")
    out += ["", "# Every NL_* constant of the headers, without its NL_ prefix (the kinds' as their IntEnum members)."]
    for c in model["constants"]:
        out.append("%s = %s" % (c["name"][3:], members.get(c["name"], _literal(c["value"]))))

    # Structs: the classes first (callbacks and fields may name any of them), then in header order each
    # callback type and each struct's fields.
    out += ["", "", "# Structs, as ctypes classes (fields under their C names; set below, in header order)."]
    for s in model["structs"]:
        base = "_Id" if is_id(s) else "_Growable" if s["output_init"] else "_Struct"
        out += ["", "", "class %s(%s):" % (class_name(s["name"]), base)]
        out.append('    """%s"""' % ((_doc(s["doc"]) + " " if s["doc"] else "") + "(%s)" % s["name"]))
    out += ["", ""]
    items = ordered_items(model)
    enum_fields = []
    for what, item in items:
        if what == "callback":
            out.append("%s = %s" % (callback_name(item["name"]), t.function(item["returns"], [p["type"] for p in item["params"]])))
            continue
        cls = class_name(item["name"])
        if is_id(item):
            continue  # an id: _Id declares the two fields
        entries = []
        for f in item["fields"]:
            if f["function"]:
                type_name = FIELD_FUNCTION_PREFIXES[item["name"]] + camel(f["name"]) + "Fn"
                out.append("%s = %s" % (type_name, t.function(f["function"]["returns"], f["function"]["params"])))
                expr = type_name
            else:
                expr = t.of(f["type"])
                if f["length"]:
                    expr = "%s * %d" % (expr, f["length"])
            entries.append('("%s", %s)' % (f["name"], expr))
            kind = f["type"]
            if kind in t.kinds and kind not in NOT_ENUMS and any(k["name"] == kind and k["values"] for k in model["kinds"]):
                enum_fields.append((cls, f["name"], camel(kind)))
        out.append("%s._fields_ = [%s]" % (cls, _wrap(entries, " " * (len(cls) + 14))))
    out += ["", "# Fields of the header's kinds read as their IntEnums (AgentInfo.state is an AgentState...)."]
    by_class = {}
    for cls, field, kind in enum_fields:
        by_class.setdefault(cls, []).append("%s=%s" % (field, kind))
    for cls, pairs in by_class.items():
        out.append("_read_as_enums(%s, %s)" % (cls, ", ".join(pairs)))

    out += ["", "# Every C struct by its C name.", "C_STRUCTS = {"]
    out.append("    " + _wrap(['"%s": %s' % (s["name"], class_name(s["name"])) for s in model["structs"]], "    ", 112) + ",")
    out.append("}")

    out += ["", "", "# The header's inline initialisers (NL_DEFINE_OUTPUT_INIT): not exported by the library, so defined",
            "# here under their C names. Each is a new struct of the class, whose constructor sets `size`."]
    for s in model["structs"]:
        if s["output_init"]:
            cls = class_name(s["name"])
            out += ["", "", "def %s() -> %s:" % (s["output_init"], cls), "    return %s()" % cls]

    out += ["", "", "# Every exported function: name -> (return type, [parameter types]).",
            "PROTOTYPES: Dict[str, Tuple[Any, List[Any]]] = {"]
    for f in model["functions"]:
        params = [t.of(p["type"]) for p in f["params"]]
        out.append('    "%s": (%s, [%s]),' % (f["name"], t.of(f["returns"]), _wrap(params, " " * (len(f["name"]) + 12))))
    out.append("}")
    return "\n".join(out) + "\n"


def outputs(model, sources):
    return {"bindings/python/_navlink_abi.py": emit(model, sources)}


def _literal(value):
    if isinstance(value, str):
        return '"%s"' % value
    if isinstance(value, float):
        return repr(value)
    return "0x%X" % value if value > 255 else str(value)
