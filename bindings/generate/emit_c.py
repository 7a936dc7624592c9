"""The C layer's field lists (capi/src/generated_fields.h) from the header model: for each struct the C layer
copies to or from a core struct of the same field names, an X-macro listing its plain number fields, so a
copy is one line (`NL_LINK_SETTINGS_FIELDS(COPY)`) and a field added to the header is copied without an
edit there (the core struct must have it: the build says so if not).

A struct's plain fields are those of number types, but `size`, `reserved*`, arrays, pointers, and the count
or length of an array or pointer field (`drop_angle_count`, `plugin_settings_json_length`), which the C
layer reads with a check of its own.
"""

import textwrap

from names import generated_notice

# The structs the C layer copies field by field (capi/src/*_api.cpp).
COPIED = ["nl_link_settings", "nl_link_generation_report", "nl_agent_capabilities"]
NUMBERS = {"uint8_t", "uint32_t", "int32_t", "uint64_t", "float", "double"}


def plain_fields(struct):
    names = {f["name"] for f in struct["fields"]}
    out = []
    for f in struct["fields"]:
        stems = {n for n in names} | {n[:-1] for n in names if n.endswith("s")}  # drop_angles: drop_angle_count
        paired = any(f["name"] == stem + suffix for stem in stems for suffix in ("_count", "_length"))
        if f["name"] == "size" or f["name"].startswith("reserved") or f["length"] or paired:
            continue
        if f["type"] not in NUMBERS:
            continue
        out.append(f["name"])
    return out


def outputs(model, sources):
    structs = {s["name"]: s for s in model["structs"]}
    notice = textwrap.wrap(generated_notice(sources), 100)
    lines = ["/* " + "\n * ".join(notice) + " */"] + [
             "/* The plain number fields of the C structs the C layer copies to or from core structs of the same",
             " * field names, as X-macros: X(field) for each, in header order. */",
             "#pragma once"]
    for name in COPIED:
        fields = plain_fields(structs[name])
        lines += ["", "#define %s_FIELDS(X) \\" % name.upper()]
        lines += ["    X(%s) \\" % f for f in fields[:-1]] + ["    X(%s)" % fields[-1]]
    return {"capi/src/generated_fields.h": "\n".join(lines) + "\n"}
