#!/usr/bin/env python3
"""Prints the C compiler's view of every struct in NavLink's public headers.

The struct and field names come from the headers themselves (a small parser of `typedef struct`), and
sizes, alignments and offsets from a C program compiled with the system `cc` and run: the reference a
binding's layout test compares its own structs with. Output, one item per line:

    struct <name> <size> <align>
    field <struct> <field> <offset> <size>

Usage: c_layout.py -I DIR [-I DIR ...] [-o FILE]   (DIRs: capi/include, plugins/include and the build's
capi/include with the generated navlink/version.h)
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HEADERS = ["navlink/navlink.h", "navlink/recast.h", "navlink/plugin.h"]


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


def find_header(include_dirs, header):
    for d in include_dirs:
        path = os.path.join(d, header)
        if os.path.isfile(path):
            return path
    raise SystemExit("c_layout.py: %s is in none of %s" % (header, include_dirs))


def probe_program(structs):
    lines = ["#include <%s>" % h for h in HEADERS]
    lines += ["#include <stddef.h>", "#include <stdio.h>", "int main(void) {"]
    for name, fields in structs:
        lines.append('    printf("struct %s %%zu %%zu\\n", sizeof(%s), _Alignof(%s));' % (name, name, name))
        for f in fields:
            lines.append('    printf("field %s %s %%zu %%zu\\n", offsetof(%s, %s), sizeof(((%s*)0)->%s));'
                         % (name, f, name, f, name, f))
    lines += ["    return 0;", "}"]
    return "\n".join(lines) + "\n"


def layout_lines(include_dirs, compiler="cc"):
    structs = []
    for header in HEADERS:
        with open(find_header(include_dirs, header), encoding="utf-8") as f:
            structs += parse_structs(f.read())
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, "layout.c")
        exe = os.path.join(tmp, "layout")
        with open(source, "w", encoding="utf-8") as f:
            f.write(probe_program(structs))
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
