"""The C# binding's raw layer (bindings/csharp/com.navlink.sdk/Runtime/Generated/*.g.cs) from the header model:
the #defines as enums and constants (Constants.g.cs); the structs, as partial structs (Ids.g.cs; Defs.g.cs, those
an nl_default_* function returns; Outputs.g.cs, those with an output initialiser; Structs.g.cs, the other ones
of navlink.h and recast.h; Plugin.g.cs, plugin.h's); the callback delegate types (NativeCallbacks.g.cs); every
exported function as a [DllImport] of the class Native (Native.g.cs) and the header's inline initialisers
(Native.Init.g.cs). The idiomatic layer (World and the rest of Runtime/) builds on top; Runtime/Native/ has
Native.Library, Runtime/Types/ what is not mechanical (Vec3, the members some structs have besides their fields).

Names: a struct nl_link_settings is LinkSettings, its field max_jump_gap MaxJumpGap (the layout test finds
each C field so); a kind nl_agent_state the enum AgentState, whose members drop the kind's common prefix
(NL_AGENT_IDLE is AgentState.Idle); a callback nl_log_fn the delegate NativeCallbacks.LogFn, and a function
pointer field PREFIX + Field + Fn (nl_plugin_host.log: HostLogFn); a parameter out_id outId. The headers'
#defines that are no kind's members go to the enum of their prefix (CONSTANT_GROUPS: NL_MESH_MOVABLE is
MeshFlags.Movable) or else to the class Limits (NL_NO_POLYGON is Limits.NoPolygon). The tables below name
what no rule gives (the names the binding had before it was generated).

Types: the fields are blittable, as the header's: a pointer (data, string or function) is IntPtr, size_t
UIntPtr, float[3] Vec3, any other array a fixed buffer (float[4][3]: fixed float[12]), a kind its enum. In
[DllImport]s a pointer to a struct or number is typed (AgentDef*, uint*), a string or buffer byte*, the
world and callbacks IntPtr, a returned string IntPtr. In delegates, pointers to numbers are typed, other
pointers IntPtr.
"""
import re
import textwrap

from names import camel, enum_prefix, generated_notice, is_id, ordered_items

PACKAGE = "bindings/csharp/com.navlink.sdk/Runtime/Generated/"
WIDTH = 120

# Structs whose plain name the idiomatic layer gives to a friendlier type (System.Version; the PathResult and
# PathShortfall classes that carry points and text; the QueryFilter class that carries its area costs).
STRUCT_NAMES = {"nl_version": "NavLinkVersion", "nl_path_result": "PathResultInfo",
                "nl_path_shortfall": "PathShortfallInfo", "nl_query_filter": "QueryFilterDef"}
# Kinds named otherwise. A path point's nl_segment_kind is walking or the kind of the link taken: one enum
# with nl_link_kind (LinkKind.Walk is NL_SEGMENT_WALK; NL_SEGMENT_JUMP is LinkKind.Jump, of the same value).
KIND_NAMES = {"nl_status": "StatusCode", "nl_segment_kind": "LinkKind"}
# Enums that are bit sets ([Flags]); the constant groups say so themselves.
FLAG_KINDS = {"StatusCode"}
# What the C# enum says beyond the header's brief comment.
ENUM_NOTES = {
    "StatusCode": "An nl_status: one kind bit at the top (Failure, Success or InProgress) and detail bits below; a "
                  "failure may carry several details, so this is a [Flags] enum: `StatusCode.Failure | "
                  "StatusCode.InvalidHandle` prints as \"Failure, InvalidHandle\". Test it with Status.Failed and "
                  "Status.Has.",
    "LinkKind": "In C# also how a path goes on from a point (nl_segment_kind, PathPoint.Segment): Walk, or the kind "
                "of the link taken. A plugin's kind: `(LinkKind)(LinkKind.FirstPluginKind + n)`.",
}
# #defines no kind holds, grouped into enums by prefix: (prefix, enum, [Flags], summary).
CONSTANT_GROUPS = [
    ("NL_MESH_", "MeshFlags", True, "nl_mesh_def.flags (World.AddMesh's flags, MeshInfo.Flags)."),
    ("NL_UP_AXIS_", "UpAxis", False, "nl_mesh_def.up_axis (World.AddMesh's upAxis, MeshInfo.UpAxis). NavLink's "
                                     "own frame is right-handed with y up."),
    ("NL_BUILD_WARNING_", "BuildWarnings", True, "nl_navmesh_info.build_warnings (NavmeshInfo.BuildWarnings): a "
                                                 "build succeeded on a level that looks given wrong."),
    ("NL_LINKS_LOAD_", "LinksLoadFlags", True, "nl_navmesh_load_links_json's flags (World.LoadLinksJson's anyBody)."),
    ("NL_NAVMESH_LOAD_", "NavmeshLoadFlags", True, "nl_navmesh_load_def.flags (World.LoadNavmesh's sameLevel)."),
    ("NL_PLUGIN_", "PluginKinds", True, "What a plugin provides (PluginSummary.Kinds, nl_plugin_info.kinds)."),
    ("NL_RECAST_PARTITION_", "RecastPartition", False, "How Recast partitions the walkable area into regions "
                                                       "(RecastSettings.Partition)."),
]
# #defines in a static class of constants: (prefix, class, summary); the rest go to Limits.
CONSTANT_CLASSES = [
    ("NL_VERSION_", "HeaderVersion", "The header version this binding was generated from (navlink/version.h); "
                                     "World.LibraryVersion is the loaded library's."),
    ("NL_PLUGIN_ABI_", "PluginAbi", "navlink/plugin.h's version and entry point, for plugins written in C#."),
    ("NL_", "Limits", "The headers' limits and special values."),
]
# #defines placed apart from their prefix's group: C name -> (enum or class, member or None for the rule's).
CONSTANT_PLACES = {"NL_MESH_MAX_AREA": ("Limits", None), "NL_PLUGIN_ENTRY_SYMBOL": ("PluginAbi", "EntrySymbol"),
                   "NL_LINK_FIRST_PLUGIN_KIND": ("LinkKind", "FirstPluginKind")}
# uint32_t fields and parameters that hold a constant group's values: typed as its enum.
FIELD_TYPES = {("nl_mesh_def", "flags"): "MeshFlags", ("nl_mesh_info", "flags"): "MeshFlags",
               ("nl_mesh_def", "up_axis"): "UpAxis", ("nl_mesh_info", "up_axis"): "UpAxis",
               ("nl_navmesh_info", "build_warnings"): "BuildWarnings",
               ("nl_navmesh_load_def", "flags"): "NavmeshLoadFlags",
               ("nl_plugin_description", "kinds"): "PluginKinds", ("nl_plugin_info", "kinds"): "PluginKinds",
               ("nl_recast_settings", "partition"): "RecastPartition",
               ("nl_navmesh_load_links_json", "flags"): "LinksLoadFlags"}
# Parameters whose C name is a C# keyword, named as before the layer was generated (else: @name).
PARAMETER_NAMES = {("nl_navmesh_find_nearest", "out"): "outPoints",
                   ("nl_plugin_host.navmesh_find_nearest", "out"): "outPoints"}
# Function pointer fields of plugin.h's structs are delegates named PREFIX + Field + Fn.
FIELD_FUNCTION_PREFIXES = {"nl_plugin_host": "Host", "nl_navmesh_builder": "Navmesh",
                           "nl_link_kind_provider": "Link", "nl_plugin_info": "Plugin"}

SCALARS = {"uint8_t": "byte", "int8_t": "sbyte", "uint16_t": "ushort", "int16_t": "short", "uint32_t": "uint",
           "int32_t": "int", "uint64_t": "ulong", "int64_t": "long", "float": "float", "double": "double",
           "size_t": "UIntPtr", "char": "byte", "int": "int", "unsigned int": "uint", "void": "void"}
CONSTANT_TYPES = {"int": "int", "unsigned int": "uint", "long long": "long", "unsigned long long": "ulong",
                  "float": "float", "double": "double", "const char *": "string"}
KEYWORDS = {"abstract", "as", "base", "bool", "break", "byte", "case", "catch", "char", "checked", "class", "const",
            "continue", "decimal", "default", "delegate", "do", "double", "else", "enum", "event", "explicit",
            "extern", "false", "finally", "fixed", "float", "for", "foreach", "goto", "if", "implicit", "in", "int",
            "interface", "internal", "is", "lock", "long", "namespace", "new", "null", "object", "operator", "out",
            "override", "params", "private", "protected", "public", "readonly", "ref", "return", "sbyte", "sealed",
            "short", "sizeof", "stackalloc", "static", "string", "struct", "switch", "this", "throw", "true", "try",
            "typeof", "uint", "ulong", "unchecked", "unsafe", "ushort", "using", "virtual", "void", "volatile",
            "while"}


def struct_name(c_name):
    return STRUCT_NAMES.get(c_name, camel(c_name))


def kind_name(c_name):
    return KIND_NAMES.get(c_name, camel(c_name))


def parameter_name(c_name, function=None):
    if (function, c_name) in PARAMETER_NAMES:
        return PARAMETER_NAMES[(function, c_name)]
    name = camel(c_name)
    name = name[:1].lower() + name[1:]
    return "@" + name if name in KEYWORDS else name


def _split(spelling):
    """(base type, pointer depth) of a C type spelling: `const nl_ray *` -> ("nl_ray", 1)."""
    words = [w for w in spelling.replace("*", " * ").split() if w not in ("const", "struct", "volatile")]
    return " ".join(w for w in words if w != "*"), words.count("*")


class Types:
    """C type spellings to C# types, as a struct field, a [DllImport]'s parameter or return, or a delegate's."""

    def __init__(self, model):
        self.structs = {s["name"]: s for s in model["structs"]}
        self.kinds = {k["name"] for k in model["kinds"]}
        self.handles = {h["name"] for h in model["handles"]}
        self.callbacks = {c["name"] for c in model["callbacks"]}

    def value(self, base):
        """A type passed by value."""
        if base in self.structs:
            return struct_name(base)
        if base in self.kinds:
            return kind_name(base)
        if base in SCALARS:
            return SCALARS[base]
        raise SystemExit("emit_csharp.py: no C# type for '%s'" % base)

    def field(self, f, struct):
        if f["function"]:
            return "IntPtr"
        base, stars = _split(f["type"])
        if stars:
            return "IntPtr"
        return FIELD_TYPES.get((struct, f["name"])) or self.value(base)

    def param(self, spelling, function=None, name=None, after_callback=False):
        override = FIELD_TYPES.get((function, name))
        if override:
            return override
        base, stars = _split(spelling)
        if not stars:
            return self.value(base)
        if base in self.handles or base in self.callbacks:
            return "IntPtr" + "*" * (stars - 1)
        if base == "void" and stars == 1:
            return "IntPtr" if after_callback or name in ("user", "context") else "byte*"  # a context, or a buffer
        return self.value(base) + "*" * stars

    def returned(self, spelling):
        base, stars = _split(spelling)
        if stars:
            return "IntPtr"  # a borrowed string (nl_status_string)
        return self.value(base)

    def delegate(self, spelling):
        base, stars = _split(spelling)
        if not stars:
            return self.value(base)
        if stars == 1 and base in SCALARS and base not in ("void", "char"):
            return SCALARS[base] + "*"
        return "IntPtr"

    def function_parameters(self, params, function=None):
        """[(C# type, name)] of [{name, type}] parameters."""
        out = []
        previous = None
        for p in params:
            after = previous is not None and _split(previous)[0] in self.callbacks
            out.append((self.param(p["type"], function, p["name"], after), parameter_name(p["name"], function)))
            previous = p["type"]
        return out


def _escape(text):
    text = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return re.sub(r"`([^`]+)`", r"<c>\1</c>", text)


def _doc(text, indent):
    """A /// <summary> of a brief comment, wrapped."""
    text = _escape(" ".join((text or "").split()))
    if not text:
        return []
    one = "%s/// <summary>%s</summary>" % (indent, text)
    if len(one) <= WIDTH:
        return [one]
    lines = textwrap.wrap("<summary>" + text + "</summary>", width=WIDTH - len(indent) - 4,
                          break_long_words=False, break_on_hyphens=False)
    return ["%s/// %s" % (indent, line) for line in lines]


def _signature(head, items, tail):
    """`head(items)tail` on one line when it fits in WIDTH, else the items wrapped under the parenthesis."""
    one = head + "(" + ", ".join(items) + ")" + tail
    if len(one) <= WIDTH:
        return [one]
    indent = " " * (len(head) + 1)
    lines, line = [], head + "("
    for i, item in enumerate(items):
        piece = item + ("," if i + 1 < len(items) else ")" + tail)
        if line.endswith("(") or len(line) + 1 + len(piece) <= WIDTH:
            line += ("" if line.endswith("(") else " ") + piece
        else:
            lines.append(line)
            line = indent + piece
    return lines + [line]


def _file(sources, what, usings, body):
    head = ["// " + line for line in textwrap.wrap(generated_notice(sources), WIDTH - 3)]
    head += ["// " + line for line in textwrap.wrap(what, WIDTH - 3)]
    head += [""] + ["using %s;" % u for u in usings] + ([""] if usings else []) + ["namespace NavLink", "{"]
    while body and body[-1] == "":
        body = body[:-1]
    return "\n".join(head + body + ["}"]) + "\n"


# ---------------------------------------------------------------------------------------------------------------
# Constants and enums


def enums_and_classes(model):
    """Where each #define goes: ({enum: {flags, none, doc, members: [(member, value, doc, literal)]}},
    {class: {doc, members: [(C# type, member, constant, doc)]}}), in header order."""
    enums, classes = {}, {}
    constants = {c["name"]: c for c in model["constants"]}

    def enum(name, flags, doc, none=False):
        if name not in enums:
            enums[name] = {"flags": flags, "none": none, "doc": doc, "members": []}
        return enums[name]

    def member_doc(c, group):
        # A group's first #define may carry the group's block comment only: that is the enum's, not the member's.
        if c["doc"] and c["doc"] == c["block_doc"] and len(group) > 1 and c["name"] == group[0]:
            return ""
        return c["doc"]

    def add(e, member, c, group):
        for m in e["members"]:
            if m[0] == member:
                if m[1] != c["value"]:
                    raise SystemExit("emit_csharp.py: %s = %s, but %s is already %s"
                                     % (c["name"], c["value"], member, m[1]))
                return
        e["members"].append((member, c["value"], member_doc(c, group), c["literal"]))

    for kind in model["kinds"]:
        if not kind["values"]:
            continue
        name = kind_name(kind["name"])
        e = enum(name, name in FLAG_KINDS, kind["doc"])
        prefix = enum_prefix(kind["values"])
        for c in kind["values"]:
            add(e, camel(c[len(prefix):]), constants[c], kind["values"])

    # Each other #define to the group or class of the longest prefix it has (Limits: NL_, the shortest).
    groups, placed = {}, []
    for c in model["constants"]:
        if c["kind"]:
            continue
        place, member = CONSTANT_PLACES.get(c["name"], (None, None))
        if not place:
            prefixes = [(g[0], g) for g in CONSTANT_GROUPS if c["type"] == "unsigned int"] + \
                       [(k[0], k) for k in CONSTANT_CLASSES]
            prefix, where = max((p for p in prefixes if c["name"].startswith(p[0])), key=lambda p: len(p[0]))
            if where in CONSTANT_GROUPS:
                groups.setdefault(where, []).append(c["name"])
                continue
            place, member = where[1], camel(c["name"][len(prefix):])
        placed.append((c, place, member or camel(c["name"][3:])))
    for group in CONSTANT_GROUPS:
        prefix, name, flags, doc = group
        if group not in groups:
            raise SystemExit("emit_csharp.py: no #define starts with %s (CONSTANT_GROUPS)" % prefix)
        e = enum(name, flags, doc, none=flags)  # C#'s convention: a [Flags] enum names no bit set None
        for c in groups[group]:
            add(e, camel(c[len(prefix):]), constants[c], groups[group])
    class_docs = {k[1]: k[2] for k in CONSTANT_CLASSES}
    for c, place, member in placed:
        if place in enums:
            add(enums[place], member, c, [c["name"]])
            continue
        if c["type"] not in CONSTANT_TYPES:
            raise SystemExit("emit_csharp.py: no C# type for %s's literal (%s)" % (c["name"], c["type"]))
        classes.setdefault(place, {"doc": class_docs[place], "members": []})["members"].append(
            (CONSTANT_TYPES[c["type"]], member, c, c["doc"]))
    return enums, classes


def constants_file(model, sources):
    enums, classes = enums_and_classes(model)
    out = []
    for name in [k[1] for k in CONSTANT_CLASSES]:
        if name not in classes:
            continue
        cls = classes[name]
        out += _doc(cls["doc"], "    ") + ["    public static partial class %s" % name, "    {"]
        for cs_type, member, c, doc in cls["members"]:
            suffix = {"uint": "u", "long": "L", "ulong": "UL", "float": "f"}.get(cs_type, "")
            value = c["literal"] + suffix  # a string's literal has its quotes
            out += _doc(doc + " (%s)" % c["name"] if doc else c["name"] + ".", "        ")
            out.append("        public const %s %s = %s;" % (cs_type, member, value))
        out += ["    }", ""]
    for name, e in enums.items():
        doc = " ".join(x for x in (e["doc"], ENUM_NOTES.get(name, "")) if x)
        out += _doc(doc, "    ")
        if e["flags"]:
            out.append("    [Flags]")
        out += ["    public enum %s : uint" % name, "    {"]
        members = e["members"] if e["flags"] else sorted(e["members"], key=lambda m: m[1])
        if e["none"] and not any(m[1] == 0 for m in members):
            out.append("        None = 0u,")  # the layout test allows it
        for member, value, doc, literal in members:
            out += _doc(doc, "        ")
            out.append("        %s = %su," % (member, literal))
        out += ["    }", ""]
    return _file(sources, "The headers' #defines: the kinds and groups of flags as enums, the rest as constants.",
                 ["System"], out)


# ---------------------------------------------------------------------------------------------------------------
# Structs


def function_field_type(struct, field):
    """The delegate type of a function pointer field: nl_plugin_host.log is NativeCallbacks.HostLogFn."""
    return FIELD_FUNCTION_PREFIXES[struct] + camel(field) + "Fn"


def _fields(s, t):
    out, fixed = [], False
    for f in s["fields"]:
        name = camel(f["name"])
        doc = f["doc"]
        base, stars = _split(f["type"])
        if f["function"] or (base in t.callbacks and stars == 1):
            delegate = function_field_type(s["name"], f["name"]) if f["function"] else camel(base)
            doc = ("%s (NativeCallbacks.%s)" % (doc, delegate)).strip()
        out += _doc(doc, "        ")
        length = f["length"]
        if length:
            inner = re.match(r"^(.*?)\s*\[(\d+)\]$", f["type"])  # float[4][3]: a row type float[3]
            element, count = (inner.group(1), length * int(inner.group(2))) if inner else (f["type"], length)
            if element == "float" and count == 3 and not inner:
                out.append("        public Vec3 %s;" % name)
                continue
            cs = t.value(element)
            if cs not in SCALARS.values() or cs in ("UIntPtr", "void"):
                raise SystemExit("emit_csharp.py: %s.%s: no fixed buffer of %s" % (s["name"], f["name"], element))
            out.append("        public fixed %s %s[%d];" % (cs, name, count))
            fixed = True
        else:
            out.append("        public %s %s;" % (t.field(f, s["name"]), name))
    return out, fixed


def _struct_doc(s):
    return "%s (%s)" % (s["doc"], s["name"]) if s["doc"] else s["name"] + "."


def _id(s, t):
    name = struct_name(s["name"])
    short = re.sub(r"_id$", "", s["name"][3:]).split("_")[-1]  # nl_mesh_id: mesh; nl_path_ticket: ticket
    fields, _ = _fields(s, t)
    return (_doc(_struct_doc(s), "    ") +
            ["    [StructLayout(LayoutKind.Sequential)]",
             "    public partial struct %s : IEquatable<%s>" % (name, name), "    {"] + fields + [
             "",
             "        public bool IsNull { get { return Index1 == 0u; } }",
             "        public bool Equals(%s o) { return Index1 == o.Index1 && Revision == o.Revision; }" % name,
             "        public override bool Equals(object o) { return o is %s && Equals((%s)o); }" % (name, name),
             "        public override int GetHashCode() { return (int)(Index1 * 31u + Revision); }",
             "        public override string ToString() { return \"%s{\" + Index1 + \",\" + Revision + \"}\"; }"
             % short,
             "    }", ""])


def _struct(s, t):
    fields, fixed = _fields(s, t)
    return (_doc(_struct_doc(s), "    ") +
            ["    [StructLayout(LayoutKind.Sequential)]",
             "    public %spartial struct %s" % ("unsafe " if fixed else "", struct_name(s["name"])), "    {"] +
            fields + ["    }", ""])


STRUCT_FILES = [
    ("Ids.g.cs", "The ids: {index1, revision} passed by value, all zero the null id; each its own type, so that a "
                 "mesh id cannot be passed where a link id is expected."),
    ("Defs.g.cs", "The structs a caller fills for the library (defs and settings): each from the nl_default_* "
                  "function that returns it, whose values are the defaults."),
    ("Outputs.g.cs", "The structs the library writes that may grow: each from its initialiser (Native.nl_*_init: "
                     "Size set); of an output array, the first element's Size gives the element size."),
    ("Structs.g.cs", "The other structs of navlink/navlink.h's parts and navlink/recast.h."),
    ("Plugin.g.cs", "The structs of navlink/plugin.h, for plugins written in C# (registered with "
                    "Native.nl_plugin_register): a function pointer is IntPtr; NativeCallbacks has its delegate type "
                    "(Marshal.GetDelegateForFunctionPointer turns the host's into delegates; fill the plugin's from "
                    "static delegates kept alive for as long as the world lives)."),
]


def struct_file(s, model):
    """Which of STRUCT_FILES a struct is in."""
    if is_id(s):
        return "Ids.g.cs"
    if s["header"] == "navlink/plugin.h":
        return "Plugin.g.cs"
    if any(f["returns"] == s["name"] and not f["params"] and f["name"].startswith("nl_default_")
           for f in model["functions"]):
        return "Defs.g.cs"
    if s["output_init"]:
        return "Outputs.g.cs"
    return "Structs.g.cs"


def structs_files(model, sources, t):
    bodies = {name: [] for name, _ in STRUCT_FILES}
    for s in model["structs"]:
        where = struct_file(s, model)
        bodies[where] += _id(s, t) if where == "Ids.g.cs" else _struct(s, t)
    usings = ["System", "System.Runtime.InteropServices"]
    return {name: _file(sources, what, usings, bodies[name]) for name, what in STRUCT_FILES}


# ---------------------------------------------------------------------------------------------------------------
# Callbacks, functions, initialisers


def _delegate(doc, returns, params, name, t, function):
    items = ["%s %s" % (t.delegate(ty), parameter_name(n, function)) for ty, n in params]
    unsafe = any(i.split()[0].endswith("*") for i in items)
    head = "        public %sdelegate %s %s" % ("unsafe " if unsafe else "", t.delegate(returns), name)
    return (_doc(doc, "        ") + ["        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]"] +
            _signature(head, items, ";") + [""])


def callbacks_file(model, sources, t):
    items = ordered_items(model)
    out = ["    // Unity's IL2CPP accepts only delegates made from static methods marked",
           "    // [AOT.MonoPInvokeCallback(typeof(TheDelegate))], with the context passed through the `user`",
           "    // pointer (a GCHandle as IntPtr), as World does. Keep each delegate instance alive (a static field)",
           "    // for as long as native code may call it: the GC does not see native references.",
           "    public static class NativeCallbacks", "    {"]
    for what, item in items:
        if what == "callback":
            out += _delegate(_struct_doc(item), item["returns"], [(p["type"], p["name"]) for p in item["params"]],
                             camel(item["name"]), t, item["name"])
            continue
        for f in item["fields"]:
            proto = f["function"]
            if proto:
                where = "%s.%s" % (item["name"], f["name"])
                doc = "%s (%s)" % (f["doc"], where) if f["doc"] else where + "."
                out += _delegate(doc, proto["returns"], list(zip(proto["params"], proto["names"])),
                                 function_field_type(item["name"], f["name"]), t, where)
    while out[-1] == "":
        out.pop()
    return _file(sources, "The headers' callback types, and the function pointer fields of navlink/plugin.h's structs, "
                          "as Cdecl delegates.", ["System", "System.Runtime.InteropServices"], out + ["    }"])


def native_file(model, sources, t):
    out = ["    // The raw C ABI: one extern per nl_* function, named and typed as in the headers (pointers stay",
           "    // pointers, so NULL can be passed where the header allows it), all through the one library name",
           "    // Native.Library. Prefer World and its methods; this class is for what they do not cover.",
           "    public static unsafe partial class Native", "    {"]
    for f in model["functions"]:
        params = ["%s %s" % p for p in t.function_parameters(f["params"], f["name"])]
        out += _doc(f["doc"], "        ")
        out.append("        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]")
        out += _signature("        public static extern %s %s" % (t.returned(f["returns"]), f["name"]), params, ";")
        out.append("")
    while out[-1] == "":
        out.pop()
    return _file(sources, "Every exported function as a [DllImport] of Native.",
                 ["System", "System.Runtime.InteropServices"], out + ["    }"])


def init_file(model, sources):
    out = ["    // The header's inline initialisers (NL_DEFINE_OUTPUT_INIT): a zeroed output struct with Size set.",
           "    // They are static inline in C, so the library does not export them: these are their C# twins, under",
           "    // the same names. Use them before a raw Native call that fills such a struct; for an output array of",
           "    // growable elements the library reads the element size from the FIRST element:",
           "    // `links[0] = Native.nl_link_init();`. World's methods do this themselves.",
           "    public static unsafe partial class Native", "    {"]
    for s in model["structs"]:
        if s["output_init"]:
            name = struct_name(s["name"])
            out += ["        public static %s %s()" % (name, s["output_init"]), "        {",
                    "            var v = default(%s);" % name, "            v.Size = (uint)sizeof(%s);" % name,
                    "            return v;", "        }", ""]
    while out[-1] == "":
        out.pop()
    return _file(sources, "The header's inline initialisers, which the library does not export.", [], out + ["    }"])


def outputs(model, sources):
    t = Types(model)
    files = {"Constants.g.cs": constants_file(model, sources),
             "NativeCallbacks.g.cs": callbacks_file(model, sources, t),
             "Native.g.cs": native_file(model, sources, t),
             "Native.Init.g.cs": init_file(model, sources)}
    files.update(structs_files(model, sources, t))
    return {PACKAGE + name: text for name, text in files.items()}
