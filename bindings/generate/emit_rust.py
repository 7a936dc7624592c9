"""navlink-sys's declarations (bindings/rust/navlink-sys/src/*_generated.rs) from the header model: the
kinds as type aliases and every NL_* constant (constants_generated.rs), the opaque handles, callback types
and `#[repr(C)]` structs with their derives, `Default`s and the header's inline initialisers
(types_generated.rs), and every exported function in an `extern "C"` block (functions_generated.rs).

Names are the C names (a field that is a Rust keyword becomes `r#name`). Types: `uint32_t` is `u32`,
`T*` `*mut T`, `const T*` `*const T`, a callback typedef `nl_X_fn` (used as `nl_X_fn*`) the type
`Option<unsafe extern "C" fn ...>` (`None` is NULL), a kind its `u32` alias. A constant has its kind's type,
else its literal's (`1u` u32, `1` i32, `1.0f` f32, a string NUL-terminated `&[u8]`), except that a constant
an array field's length is written as is a `usize`.

What is derived, by the fields' types (tests/layout.rs checks the result against the C compiler):
- every struct: `Clone, Copy`; `Debug`, except ids (`index1` and `revision`), whose `Debug` lib.rs's
  `id_debug!` writes by what they mean; ids also `Default, PartialEq, Eq, Hash`;
- `PartialEq` unless a field is (or holds) a function pointer; `Eq` too unless one is a float;
- `Default`: a struct the header defines an initialiser for (NL_DEFINE_OUTPUT_INIT) gets that function,
  under its C name, and it is its `Default`; so is a struct that starts with `size` that no function
  returns (zeroed, `size` set: what the caller must pass); any other derives `Default` when every field
  has one (no raw pointer: those have no default).

lib.rs and status.rs hold what is not mechanical: the crate's documentation, `output_init`, the ids'
`Debug`, and NL_SUCCEEDED / NL_FAILED (function-like macros) as `nl_succeeded` / `nl_failed`.
"""
import re
import textwrap

from names import camel, generated_notice, is_id, ordered_items

SRC = "bindings/rust/navlink-sys/src/"
WIDTH = 120

SCALARS = {"uint8_t": "u8", "uint16_t": "u16", "uint32_t": "u32", "uint64_t": "u64", "int8_t": "i8",
           "int16_t": "i16", "int32_t": "i32", "int64_t": "i64", "float": "f32", "double": "f64",
           "size_t": "usize", "char": "c_char", "int": "c_int", "unsigned int": "c_uint", "void": "c_void"}
RAW = {"c_char", "c_void", "c_int", "c_uint"}  # std::os::raw
FLOATS = {"float", "double"}
CONSTANT_TYPES = {"int": "i32", "unsigned int": "u32", "long long": "i64", "unsigned long long": "u64",
                  "float": "f32", "double": "f64"}
KEYWORDS = {"as", "break", "const", "continue", "else", "enum", "extern", "false", "fn", "for", "if", "impl", "in",
            "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return", "static", "struct", "trait",
            "true", "type", "unsafe", "use", "where", "while", "async", "await", "dyn", "abstract", "become", "box",
            "do", "final", "macro", "override", "priv", "typeof", "unsized", "virtual", "yield", "try", "gen"}
NOT_RAW = {"self", "Self", "super", "crate"}  # no r# form


def ident(name):
    if name in NOT_RAW:
        raise SystemExit("emit_rust.py: '%s' is no Rust identifier, even raw" % name)
    return "r#" + name if name in KEYWORDS else name


def _base(spelling):
    """A C type's name without qualifiers, pointers or array brackets: `const nl_ray *` -> nl_ray."""
    s = re.sub(r"\[\d+\]", "", spelling).replace("*", " ")
    return " ".join(w for w in s.split() if w not in ("const", "struct", "volatile"))


class Types:
    """C type spellings to Rust types; remembers which std::os::raw names and which files' items it used."""

    def __init__(self, model):
        self.structs = {s["name"]: s for s in model["structs"]}
        self.kinds = {k["name"] for k in model["kinds"]}
        self.handles = {h["name"] for h in model["handles"]}
        self.callbacks = {c["name"]: c for c in model["callbacks"]}
        self.array_lengths = {f["length_name"] for s in model["structs"] for f in s["fields"] if f["length_name"]}
        self.returned = {_base(f["returns"]) for f in model["functions"]}
        self.reset()

    def reset(self):
        self.raw = set()
        self.uses_constants = False  # a kind or an NL_ constant (constants_generated.rs)
        self.uses_types = False  # a struct, handle or callback (types_generated.rs)

    def of(self, spelling):
        """The Rust type of a C type spelling (a parameter's, a return type, an array field's element)."""
        s = spelling.strip()
        array = re.match(r"^(.*)\[(\d+)\]$", s)
        if array:  # a row of a two-dimensional array field
            return "[%s; %s]" % (self.of(array.group(1)), array.group(2))
        parts = s.split("*")
        words = parts[0].split()
        const = "const" in words
        base = " ".join(w for w in words if w not in ("const", "struct", "volatile"))
        stars = parts[1:]
        if base in self.callbacks:
            if not self.callbacks[base]["pointer"]:  # `typedef void nl_log_fn(...)`, used as nl_log_fn*
                if not stars:
                    raise SystemExit("emit_rust.py: the function type '%s' not behind a pointer" % spelling)
                const = "const" in stars[0]
                stars = stars[1:]
            t = base
            self.uses_types = True
        elif base in self.structs or base in self.handles:
            t = base
            self.uses_types = True
        elif base in self.kinds:
            t = base
            self.uses_constants = True
        elif base in SCALARS:
            t = SCALARS[base]
            if t in RAW:
                self.raw.add(t)
        else:
            raise SystemExit("emit_rust.py: no Rust type for '%s'" % spelling)
        if t == "c_void" and not stars:
            raise SystemExit("emit_rust.py: void is no value type ('%s')" % spelling)
        for part in stars:
            t = "%s %s" % ("*const" if const else "*mut", t)
            const = "const" in part
        return t

    def field(self, f):
        """A field's Rust type, or (head, params, tail) for a function pointer (see fn_pointer)."""
        if f["function"]:
            fn = f["function"]
            return self.fn_pointer(fn["returns"], list(zip(fn["names"], fn["params"])))
        t = self.of(f["type"])
        if f["length"]:
            length = f["length_name"] or str(f["length"])
            if f["length_name"]:
                self.uses_constants = True
            t = "[%s; %s]" % (t, length)
        return t

    def params(self, params, unnamed):
        return ["%s: %s" % (ident(n) if n else unnamed(i), self.of(t)) for i, (n, t) in enumerate(params)]

    def returns(self, spelling):
        return "" if spelling.strip() == "void" else " -> " + self.of(spelling)

    def fn_pointer(self, returns, params):
        """(head, params, tail) of `Option<unsafe extern "C" fn(...) -> R>`."""
        return ('Option<unsafe extern "C" fn(', self.params(params, lambda i: "_"), ")%s>" % self.returns(returns))

    def _any(self, struct, test):
        """Whether `test(field, C type name)` holds for a field of `struct`, or of a struct it holds by value."""
        for f in struct["fields"]:
            base = None if f["function"] else _base(f["type"])
            if test(f, base) or base in self.structs and self._any(self.structs[base], test):
                return True
        return False

    def has_function(self, struct):
        return self._any(struct, lambda f, base: bool(f["function"]) or base in self.callbacks)

    def has_float(self, struct):
        return self._any(struct, lambda f, base: base in FLOATS)

    def default(self, struct):
        """How `Default` comes: "init" (the header's initialiser), "size" (zeroed with size set), "derive" or None."""
        if struct["output_init"]:
            return "init"
        if struct["fields"] and struct["fields"][0]["name"] == "size" and struct["name"] not in self.returned:
            return "size"
        return "derive" if self.derives_default(struct) else None

    def derives_default(self, struct):
        for f in struct["fields"]:
            if f["function"] or _base(f["type"]) in self.callbacks:
                continue  # Option<fn>: None
            lengths = [f["length"] or 0] + [int(n) for n in re.findall(r"\[(\d+)\]", f["type"])]
            if "*" in f["type"] or max(lengths) > 32:
                return False  # raw pointers have no Default, nor arrays longer than 32
            nested = self.structs.get(_base(f["type"]))
            if nested and not self.default(nested):
                return False
        return True


def _markdown(text):
    """A C comment as rustdoc Markdown: brackets outside `code` escaped, or `out[0]` would be a link."""
    parts = text.split("`")
    for i in range(0, len(parts), 2):
        parts[i] = parts[i].replace("[", "\\[").replace("]", "\\]")
    return "`".join(parts)


def _doc(text, indent, extra=None):
    """`///` lines of a brief comment, wrapped."""
    text = _markdown(" ".join((text or "").split()))
    if extra:
        text = (text + " " + extra).strip()
    if not text:
        return []
    lines = textwrap.wrap(text, width=WIDTH - len(indent) - 4, break_long_words=False, break_on_hyphens=False)
    return ["%s/// %s" % (indent, line) for line in lines]


def _signature(indent, head, items, tail):
    """`head` items `tail` on one line when it fits in WIDTH, else one item a line."""
    one = indent + head + ", ".join(items) + tail
    if len(one) <= WIDTH or not items:
        return [one]
    return [indent + head] + ["%s    %s," % (indent, item) for item in items] + [indent + tail.lstrip()]


def _header(sources, what):
    return ["// " + line for line in textwrap.wrap(generated_notice(sources), WIDTH - 3)] + ["//! " + line for line in textwrap.wrap(what, WIDTH - 4)]


def _imports(types, here):
    lines = []
    if types.uses_constants and here != "constants":
        lines.append("use crate::constants_generated::*;")
    if types.uses_types and here != "types":
        lines.append("use crate::types_generated::*;")
    if types.raw:
        raw = sorted(types.raw)
        lines.append("use std::os::raw::%s;" % (raw[0] if len(raw) == 1 else "{%s}" % ", ".join(raw)))
    return lines


def _literal(c):
    literal = c["literal"]
    digits = literal.lstrip("-")
    if digits.lower().startswith("0x") and len(digits) > 6:
        hexdigits = digits[2:]
        groups = []
        while hexdigits:
            groups.insert(0, hexdigits[-4:])
            hexdigits = hexdigits[:-4]
        literal = literal[:len(literal) - len(digits)] + "0x" + "_".join(groups)
    return literal


def constants(model, types, sources):
    types.reset()
    kinds = {k["name"]: k for k in model["kinds"]}
    out = []
    done = set()
    group = None  # a blank line between kinds, and between other constants by their first word (NL_MESH_...)
    for c in model["constants"]:
        kind = c["kind"]
        if (kind or c["name"].split("_")[1]) != group:
            group = kind or c["name"].split("_")[1]
            out.append("")
        if kind and kind not in done:
            done.add(kind)
            k = kinds[kind]
            out += _doc(k["doc"], "") + ["pub type %s = %s;" % (kind, SCALARS[k["type"]])]
        if c["type"] == "const char *":
            rust, value = "&[u8]", "b%s\\0\"" % c["literal"][:-1]
            extra = "As NUL-terminated bytes."
        else:
            if kind:
                rust = kind
            elif c["name"] in types.array_lengths:
                rust = "usize"
            elif c["type"] in CONSTANT_TYPES:
                rust = CONSTANT_TYPES[c["type"]]
            else:
                raise SystemExit("emit_rust.py: no Rust type for %s (%s)" % (c["name"], c["type"]))
            value, extra = _literal(c), None
        if c["block_doc"] and c["block_doc"] != c["doc"]:  # what a group of #defines shares
            out += [line.replace("///", "//", 1) for line in _doc(c["block_doc"], "")]
        out += _doc(c["doc"], "", extra) + ["pub const %s: %s = %s;" % (c["name"], rust, value)]
    for k in model["kinds"]:
        if k["name"] not in done:
            out += [""] + _doc(k["doc"], "") + ["pub type %s = %s;" % (k["name"], SCALARS[k["type"]])]
    head = _header(sources, "The headers' kinds (`typedef uint32_t nl_KIND;`) as type aliases, and every NL_* constant.")
    return "\n".join(head + _imports(types, "constants") + out) + "\n"


def _struct(s, types):
    name = s["name"]
    fields = []
    for f in s["fields"]:
        t = types.field(f)
        fields += _doc(f["doc"], "    ")
        if isinstance(t, tuple):
            head, items, tail = t
            fields += _signature("    ", "pub %s: %s" % (ident(f["name"]), head), items, tail + ",")
        else:
            fields.append("    pub %s: %s," % (ident(f["name"]), t))
    default = types.default(s)
    if is_id(s):
        derives = ["Clone", "Copy", "Default", "PartialEq", "Eq", "Hash"]
    else:
        derives = ["Clone", "Copy", "Debug"]
        if default == "derive":
            derives.append("Default")
        if not types.has_function(s):
            derives.append("PartialEq")
            if not types.has_float(s):
                derives.append("Eq")
    out = [""] + _doc(s["doc"], "") + ["#[repr(C)]", "#[derive(%s)]" % ", ".join(derives), "pub struct %s {" % name]
    out += fields + ["}"]
    if is_id(s):
        out.append('id_debug!(%s, "%s");' % (name, camel(name)))
    if default == "init":
        init = s["output_init"]
        out += ["",
                "/// The header's inline initialiser (NL_DEFINE_OUTPUT_INIT; the library does not export it): a",
                "/// zeroed `%s` with `size` set. It is also its `Default`." % name,
                "pub fn %s() -> %s {" % (init, name),
                "    // SAFETY: a plain C struct that starts with `uint32_t size`; all zero bytes are a valid value.",
                "    unsafe { output_init() }",
                "}",
                "",
                "impl Default for %s {" % name,
                "    /// `%s()`." % init,
                "    fn default() -> Self {",
                "        %s()" % init,
                "    }",
                "}"]
    elif default == "size":
        out += ["",
                "impl Default for %s {" % name,
                "    /// Zeroed, with `size` set, as the caller passes it (the header defines no initialiser for it).",
                "    fn default() -> Self {",
                "        // SAFETY: a plain C struct that starts with `uint32_t size`; all zero bytes are a valid value.",
                "        unsafe { output_init() }",
                "    }",
                "}"]
    return out


def type_items(model, types, sources):
    types.reset()
    out = []
    for h in model["handles"]:
        out += [""] + (_doc(h["doc"], "") or ["/// Opaque: used through pointers only."])
        out += ["#[repr(C)]", "pub struct %s {" % h["name"], "    _private: [u8; 0],", "}"]
    inits = False
    for what, item in ordered_items(model):
        if what == "callback":
            head, items, tail = types.fn_pointer(item["returns"], [(p["name"], p["type"]) for p in item["params"]])
            out += [""] + _doc(item["doc"], "", "(`%s*`; `None` is NULL.)" % item["name"] if not item["pointer"] else None)
            out += _signature("", "pub type %s = %s" % (item["name"], head), items, tail + ";")
        else:
            out += _struct(item, types)
            inits = inits or types.default(item) in ("init", "size")
    head = _header(sources, "The headers' opaque handles, callback types and structs (`#[repr(C)]`, C field names), "
                            "with the inline initialisers (NL_DEFINE_OUTPUT_INIT).")
    imports = (["use crate::output_init;"] if inits else []) + _imports(types, "types")
    return "\n".join(head + imports + out) + "\n"


def functions(model, types, sources):
    types.reset()
    out = ['extern "C" {']
    for i, f in enumerate(model["functions"]):
        if i:
            out.append("")
        params = types.params([(p["name"], p["type"]) for p in f["params"]], lambda n: "arg%d" % n)
        out += _doc(f["doc"], "    ")
        out += _signature("    ", "pub fn %s(" % f["name"], params, ")%s;" % types.returns(f["returns"]))
    out.append("}")
    head = _header(sources, "Every function the headers export, with its C signature.")
    return "\n".join(head + _imports(types, "functions") + [""] + out) + "\n"


def outputs(model, sources):
    types = Types(model)
    return {SRC + "constants_generated.rs": constants(model, types, sources),
            SRC + "types_generated.rs": type_items(model, types, sources),
            SRC + "functions_generated.rs": functions(model, types, sources)}
