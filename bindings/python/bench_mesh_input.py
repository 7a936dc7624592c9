#!/usr/bin/env python3
"""How long World.add_mesh takes for one large mesh given as lists and as buffers, in the same run.

A flat grid of TRIANGLES triangles (default 500,000), added to a fresh world each time; the best of
--repeat runs. Prints each input kind's whole add_mesh and, apart, the binding's own part (turning the
input into what C reads), with their ratios to lists. The library's part (copying and indexing the
mesh) is the same for every kind; "x lists" is how many times faster than lists.

Usage: NAVLINK_LIBRARY=build/capi/libnavlink.so python3 bindings/python/bench_mesh_input.py [--triangles N]
"""
import argparse
import array
import ctypes
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import navlink as nl  # noqa: E402


def grid(triangles):
    """A square grid of about `triangles` triangles in the y = 0 plane: (flat x y z list, flat index list)."""
    side = max(1, int(math.sqrt(triangles / 2)))
    vertices = [c for z in range(side + 1) for x in range(side + 1) for c in (float(x), 0.0, float(z))]
    indices = []
    for z in range(side):
        for x in range(side):
            corner = z * (side + 1) + x
            indices += [corner, corner + side + 1, corner + 1, corner + 1, corner + side + 1, corner + side + 2]
    return vertices, indices


def best_of(repeat, call):
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        call()
        times.append(time.perf_counter() - started)
    return min(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--triangles", type=int, default=500_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()

    vertices, indices = grid(args.triangles)
    floats, uints = array.array("f", vertices), array.array("I", indices)
    inputs = {
        "lists": (vertices, indices),
        "array.array": (floats, uints),
        "memoryview (n, 3)": (memoryview(floats).cast("B").cast("f", (len(floats) // 3, 3)), memoryview(uints)),
        "bytes (read-only: copied once)": (floats.tobytes(), uints.tobytes()),
        "array d/q (converted once)": (array.array("d", vertices), array.array("q", indices)),
        "lists of (x, y, z) and triangles": ([tuple(vertices[k:k + 3]) for k in range(0, len(vertices), 3)],
                                             [indices[k:k + 3] for k in range(0, len(indices), 3)]),
    }
    try:
        import numpy
        inputs["numpy float32/uint32"] = (numpy.asarray(floats).reshape(-1, 3), numpy.asarray(uints))
        inputs["numpy float64/int64 (converted)"] = (numpy.asarray(vertices).reshape(-1, 3),
                                                     numpy.asarray(indices).reshape(-1, 3))
    except ImportError:
        print("(numpy is not installed for %s: no numpy row)" % sys.executable)

    print("%d triangles, %d vertices; best of %d; library %s" % (
        len(indices) // 3, len(vertices) // 3, args.repeat, nl.library_path))
    print("%-32s %12s %9s %14s %11s" % ("input", "add_mesh s", "x lists", "binding's s", "x lists"))
    baseline = None
    for kind, (v, i) in inputs.items():
        def add():
            with nl.World() as world:
                world.add_mesh(v, i)

        def convert():
            nl._c_array("vertices", v, ctypes.c_float, group=3, wider_rows=True)
            nl._c_array("indices", i, ctypes.c_uint32, group=3)
        whole, own = best_of(args.repeat, add), best_of(args.repeat, convert)
        baseline = baseline or (whole, own)
        print("%-32s %12.4f %9.1f %14.6f %11.0f" % (kind, whole, baseline[0] / whole, own, baseline[1] / own))


if __name__ == "__main__":
    main()
