#!/usr/bin/python3
"""Writes the bindings' generated layers from NavLink's public headers (header_model.py reads them).

Usage: generate.py -I DIR [-I DIR ...] [--check]
  DIRs: capi/include and a build's capi/include (the generated navlink/version.h).
  --check: write nothing; exit 1 naming every generated file that differs from what the headers give
           (the test suite's bindings_generated runs this).

Run with Debian's /usr/bin/python3, which has python3-clang (scripts/setup.sh installs it).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import emit_c  # noqa: E402
import emit_csharp  # noqa: E402
import emit_python  # noqa: E402
import emit_rust  # noqa: E402
import emit_rust_plain  # noqa: E402
import header_model  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def outputs(model):
    """Every generated file: its path from the repository's root, and its text."""
    # How the generated files name their sources: navlink.h stands for the parts it includes.
    sources = [h + " (with its parts)" if h == "navlink/navlink.h" else h
               for h in header_model.CONSTANT_HEADERS + header_model.HEADERS]
    files = {}
    for emitter in (emit_c, emit_python, emit_csharp, emit_rust, emit_rust_plain):
        files.update(emitter.outputs(model, sources))
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-I", dest="include_dirs", action="append", required=True)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    model = header_model.read(args.include_dirs)
    stale = []
    for path, text in outputs(model).items():
        full = os.path.join(ROOT, path)
        try:
            with open(full, encoding="utf-8") as f:
                current = f.read()
        except FileNotFoundError:
            current = None
        if current == text:
            continue
        if args.check:
            stale.append(path)
        else:
            with open(full, "w", encoding="utf-8") as f:
                f.write(text)
            print("generate.py: wrote %s" % path)
    if stale:
        print("generate.py: these generated files are not what the headers give: %s\n"
              "Run /usr/bin/python3 bindings/generate/generate.py -I capi/include "
              "-I BUILD/capi/include, and commit the result." % ", ".join(stale))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
