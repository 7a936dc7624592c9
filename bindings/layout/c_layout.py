#!/usr/bin/env python3
"""Prints the C compiler's view of every struct in NavLink's public headers.

The struct and field names come from the headers themselves (a small parser of `typedef struct`), and
sizes, alignments and offsets from a C program compiled with the system `cc` and run: the reference a
binding's layout test compares its own structs with. Output, one item per line:

    struct <name> <size> <align>
    field <struct> <field> <offset> <size>
    init <struct> <function> <size>      (NL_DEFINE_OUTPUT_INIT: a static inline initialiser, not exported;
                                          <size> is the `size` it sets, from calling it)
    const <name> <value>                 (each `#define NL_... <integer>`, value in decimal)

Usage: c_layout.py -I DIR [-I DIR ...] [-o FILE]   (DIRs: capi/include and the build's
capi/include with the generated navlink/version.h)
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HEADERS = ["navlink/navlink.h", "navlink/recast.h", "navlink/plugin.h"]
# Constants only: the generated version header (NL_VERSION_MAJOR...).
CONSTANT_HEADERS = ["navlink/version.h"]


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def parse_structs(text):
    """[(struct name, [field names])] of every `typedef struct NAME { ... } NAME;` in order."""
    structs = []
    for match in re.finditer(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", strip_comments(text), flags=re.S):
        name, body, alias = match.group(1), match.group(2), match.group(3)
        if name != alias:
            raise SystemExit("c_layout.py: struct %s is typedef'd as %s" % (name, alias))
        fields = []
        for decl in body.split(";"):
            decl = " ".join(decl.split())
            if not decl:
                continue
            pointer_to_function = re.search(r"\(\s*\*\s*(\w+)\s*\)", decl)
            if pointer_to_function:
                fields.append(pointer_to_function.group(1))
                continue
            decl = re.sub(r"\[[^\]]*\]", "", decl)
            if "," in decl:
                raise SystemExit("c_layout.py: several fields in one declaration: " + decl)
            fields.append(re.findall(r"\w+", decl)[-1])
        structs.append((name, fields))
    return structs


def parse_output_inits(text):
    """[(struct name, function name)] of every NL_DEFINE_OUTPUT_INIT(T, name) use, in order."""
    text = strip_comments(text)
    return [(m.group(1), m.group(2)) for m in re.finditer(r"^\s*NL_DEFINE_OUTPUT_INIT\(\s*(\w+)\s*,\s*(\w+)\s*\)",
                                                          text, flags=re.M)]


def parse_integer_constants(text):
    """Names of `#define NL_NAME <integer>` (maybe negative, suffixed u, parenthesised), in order."""
    names = []
    for line in strip_comments(text).splitlines():
        m = re.match(r"^\s*#\s*define\s+(NL_\w+)\s+\(?-?(0x[0-9a-fA-F]+|[0-9]+)u?\)?\s*$", line)
        if m:
            names.append(m.group(1))
    return names


def header_parts(text):
    """The parts an umbrella header includes (`#include "navlink/X.h"`, in order), but export.h and version.h."""
    names = re.findall(r'^\s*#\s*include\s+"(navlink/\w+\.h)"', text, flags=re.M)
    return [n for n in names if n not in ("navlink/export.h", "navlink/version.h")]


def expanded_headers(include_dirs, headers):
    """`headers` with each one's parts (header_parts) inserted after it, each header once."""
    out = []
    for header in headers:
        if header in out:
            continue
        out.append(header)
        with open(find_header(include_dirs, header), encoding="utf-8") as f:
            out += [p for p in expanded_headers(include_dirs, header_parts(f.read())) if p not in out]
    return out


def find_header(include_dirs, header):
    for d in include_dirs:
        path = os.path.join(d, header)
        if os.path.isfile(path):
            return path
    raise SystemExit("c_layout.py: %s is in none of %s" % (header, include_dirs))


def probe_program(structs, inits=(), constants=()):
    lines = ["#include <%s>" % h for h in CONSTANT_HEADERS + HEADERS]
    lines += ["#include <stddef.h>", "#include <stdio.h>", "int main(void) {"]
    for name, fields in structs:
        lines.append('    printf("struct %s %%zu %%zu\\n", sizeof(%s), _Alignof(%s));' % (name, name, name))
        for f in fields:
            lines.append('    printf("field %s %s %%zu %%zu\\n", offsetof(%s, %s), sizeof(((%s*)0)->%s));'
                         % (name, f, name, f, name, f))
    for struct, function in inits:
        lines.append('    printf("init %s %s %%u\\n", (unsigned)%s().size);' % (struct, function, function))
    for name in constants:
        lines.append('    printf("const %s %%lld\\n", (long long)(%s));' % (name, name))
    lines += ["    return 0;", "}"]
    return "\n".join(lines) + "\n"


def layout_lines(include_dirs, compiler="cc"):
    structs, inits, constants = [], [], []
    headers = expanded_headers(include_dirs, HEADERS)
    for header in CONSTANT_HEADERS + headers:
        with open(find_header(include_dirs, header), encoding="utf-8") as f:
            text = f.read()
        if header in headers:
            structs += parse_structs(text)
            inits += parse_output_inits(text)
        constants += parse_integer_constants(text)
    known = {name for name, _ in structs}
    for struct, function in inits:
        if struct not in known:
            raise SystemExit("c_layout.py: %s initialises %s, which is no struct of the headers" % (function, struct))
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, "layout.c")
        exe = os.path.join(tmp, "layout")
        with open(source, "w", encoding="utf-8") as f:
            f.write(probe_program(structs, inits, constants))
        command = [compiler, "-std=c11", "-Wall", "-Werror", source, "-o", exe] + ["-I" + d for d in include_dirs]
        subprocess.run(command, check=True)
        return subprocess.run([exe], check=True, capture_output=True, text=True).stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-I", dest="include_dirs", action="append", required=True)
    parser.add_argument("-o", dest="output")
    args = parser.parse_args()
    text = layout_lines(args.include_dirs)
    if args.output:
        with open(args.output, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
