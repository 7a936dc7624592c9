#!/usr/bin/env python3
"""Fails on code that reads through a temporary owner: a range-for over `*call(...)`, or a reference
bound to `*call(...)` where `call` returns a shared_ptr, unique_ptr or HeldPtr by value.

C++17 destroys such a temporary at the end of the full expression that made it: a range-for's body, or
the reference's later uses, read an object that only some other owner keeps alive (a registry's cached
snapshot, which another thread may replace at any moment). nl::HeldPtr makes the compiler refuse this
for the navmesh registry's getters; this check covers every other function in the tree.

Usage: dangling_owners.py ROOT [--self-test]. Prints each place as FILE:LINE and exits 1 if any.
"""
import pathlib
import re
import sys

FOLDERS = ("sdk", "capi", "plugins", "samples", "tests", "bindings")
SUFFIXES = {".c", ".cc", ".cpp", ".cxx", ".h", ".hpp"}

# A declaration or definition returning an owner by value: `std::shared_ptr<const X> name(`.
OWNER_RETURN = re.compile(r"\b(?:std::)?(?:shared_ptr|unique_ptr|HeldPtr)<[^;{}()]*>\s+(?:[A-Za-z_]\w*::)*([A-Za-z_]\w*)\s*\(")
# `for (decl : *expression(...))`: the range is a dereferenced call result.
RANGE_OVER_CALL = re.compile(r"\bfor\s*\([^;()]*(?:\([^()]*\)[^;()]*)*[^:]:\s*\*\s*([A-Za-z_][\w.>\-:]*(?:\([^()]*\)[\w.>\-:]*)*)\(")
# `T& name = *...call(` or `T&& name = *...call(`.
REFERENCE_TO_CALL = re.compile(r"&&?\s*[A-Za-z_]\w*\s*=\s*\*\s*((?:[A-Za-z_][\w]*(?:\([^()]*\))?(?:\.|->|::))*)([A-Za-z_]\w*)\s*\(")


def sources(root):
    for folder in FOLDERS:
        base = root / folder
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            if path.suffix in SUFFIXES and path.is_file() and "target" not in path.parts:
                yield path


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def find(files):
    """files: [(name, text)]. Returns ["name:line: what"]."""
    owners = set()
    for _, text in files:
        owners.update(OWNER_RETURN.findall(strip_comments(text)))
    problems = []
    for name, text in files:
        for number, line in enumerate(strip_comments(text).splitlines(), 1):
            if RANGE_OVER_CALL.search(line):
                problems.append(f"{name}:{number}: a range-for over a dereferenced call's result: hold the owner in a variable first")
            for match in REFERENCE_TO_CALL.finditer(line):
                if match.group(2) in owners:
                    problems.append(f"{name}:{number}: a reference to what the temporary owner {match.group(2)}() returns: hold the owner in a variable first")
    return problems


def self_test():
    files = [("a.h", "std::shared_ptr<const Snap> links(Handle h) const;\nHeldPtr<const Mesh> Registry::navmesh(Handle h) const {\nX* find(int);\n"),
             ("bad.cpp", "for (const L& s : *registry.links(h)) use(s);\nconst Mesh& m = *world->registry().navmesh(h);\n"
                         "for (auto& s : *n.graph->links_ptr()) {}\n"),
             ("good.cpp", "const auto links = registry.links(h);\nfor (const L& s : *links) use(s);\nconst X& x = *find(3);\n"
                          "for (const auto& [a, b] : joins) {}\nuse(*registry.links(h));\n")]
    got = find(files)
    want = ["bad.cpp:1", "bad.cpp:2", "bad.cpp:3"]
    if [g.split(": ")[0] for g in got] != want:
        print("self-test failed:", got)
        return 1
    return 0


def main():
    if "--self-test" in sys.argv:
        return self_test()
    root = pathlib.Path(sys.argv[1])
    files = [(str(p.relative_to(root)), p.read_text(errors="replace")) for p in sources(root)]
    problems = find(files)
    for p in problems:
        print(p)
    print(f"{len(files)} files read, {len(problems)} places that read through a temporary owner")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
