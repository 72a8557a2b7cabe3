#!/usr/bin/env python3
"""Writes the synthesized seeds of fuzz/corpus/ (the others are copies of
test/data and tools/relgeo/testdata files): small meshes in every format the
mesh readers take, ASCII and binary, and the structured inputs of the harnesses
that decode bytes (layouts in each harness's file comment).

Run from the repository root: python3 fuzz/make_seeds.py
"""
import os
import struct

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

TETRA_V = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
OCTA_V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
OCTA_F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]


def write(harness, name, data):
    d = os.path.join(ROOT, harness)
    os.makedirs(d, exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(d, name), mode) as f:
        f.write(data)


def off_ascii(v, f):
    s = "OFF\n%d %d 0\n" % (len(v), len(f))
    s += "".join("%r %r %r\n" % tuple(map(float, p)) for p in v)
    s += "".join("3 %d %d %d\n" % t for t in f)
    return s


def off_binary(v, f):
    b = b"OFF BINARY\n" + struct.pack(">iii", len(v), len(f), 0)
    for p in v:
        b += struct.pack(">fff", *p)
    for t in f:
        b += struct.pack(">iiiii", 3, *t, 0)
    return b


def obj(v, f, style):
    s = "# %s\n" % style
    s += "".join("v %r %r %r\n" % tuple(map(float, p)) for p in v)
    n = len(v)
    for t in f:
        if style == "plain":
            s += "f %d %d %d\n" % tuple(i + 1 for i in t)
        elif style == "slashes":
            s += "f %d/%d/%d %d//%d %d/%d\n" % (t[0] + 1, 1, 1, t[1] + 1, 1, t[2] + 1, 1)
        else:  # negative (relative) indices
            s += "f %d %d %d\n" % tuple(i - n for i in t)
    return s


def ply(v, f, fmt):
    head = "ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" \
           "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (fmt, len(v), len(f))
    if fmt == "ascii":
        return head + "".join("%r %r %r\n" % tuple(map(float, p)) for p in v) + \
            "".join("3 %d %d %d\n" % t for t in f)
    e = "<" if fmt == "binary_little_endian" else ">"
    b = head.encode()
    for p in v:
        b += struct.pack(e + "fff", *p)
    for t in f:
        b += struct.pack(e + "Biii", 3, *t)
    return b


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def stl_ascii(v, f):
    s = "solid tetra\n"
    for t in f:
        a, b, c = (v[i] for i in t)
        s += " facet normal %r %r %r\n  outer loop\n" % normal(a, b, c)
        for p in (a, b, c):
            s += "   vertex %r %r %r\n" % tuple(map(float, p))
        s += "  endloop\n endfacet\n"
    return s + "endsolid tetra\n"


def stl_binary(v, f):
    b = b"relgeo fuzz seed: binary STL".ljust(80, b" ") + struct.pack("<I", len(f))
    for t in f:
        a, c, d = (v[i] for i in t)
        b += struct.pack("<fff", *normal(a, c, d))
        for p in (a, c, d):
            b += struct.pack("<fff", *p)
        b += struct.pack("<H", 0)
    return b


def meshes():
    write("mesh_off", "tetra.off", off_ascii(TETRA_V, TETRA_F))
    write("mesh_off", "octa_binary.off", off_binary(OCTA_V, OCTA_F))
    write("mesh_off", "huge_header.off", "OFF\n4 10000000 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n")
    for style in ("plain", "slashes", "negative"):
        write("mesh_obj", "tetra_%s.obj" % style, obj(TETRA_V, TETRA_F, style))
    write("mesh_obj", "octa.obj", obj(OCTA_V, OCTA_F, "plain"))
    for fmt in ("ascii", "binary_little_endian", "binary_big_endian"):
        write("mesh_ply", "octa_%s.ply" % fmt, ply(OCTA_V, OCTA_F, fmt))
    write("mesh_stl", "tetra_ascii.stl", stl_ascii(TETRA_V, TETRA_F))
    write("mesh_stl", "octa_binary.stl", stl_binary(OCTA_V, OCTA_F))
    write("mesh_tags", "octa.tags", "# relgeo feature tags\ncrease 0 2\ncrease 2 1\ncorner 4\n")


def read_points(name):
    pts = []
    with open(os.path.join(os.path.dirname(ROOT), "..", "tools", "relgeo", "testdata", name)) as f:
        for line in f:
            line = line.split("#")[0].replace(",", " ").split()
            if len(line) == 2:
                pts.append((float(line[0]), float(line[1])))
    return pts


def coordinate(x):
    """fuzz_support.h Input::coordinate(): tag 0 = the raw bits that follow."""
    return b"\x00" + struct.pack("<d", x)


def hull_input(kernel, algorithm, points, extra=b""):
    """hull_fuzzer.cpp: kernel byte, mode byte (algorithm, bit 7 = no
    prefilter), then records; op 0 = a new point."""
    b = bytes([kernel, algorithm])
    for x, y in points:
        b += b"\x00" + coordinate(x) + coordinate(y)
    return b + extra


def hulls():
    a1 = read_points("classroom_a1.txt")
    for kernel in range(16):  # every kernel of hull_fuzzer.cpp, algorithms in turn
        write("hull", "a1_kernel%02d" % kernel, hull_input(kernel, kernel % 3, a1))
    for name in ("kettner_loop.txt", "kettner_wrong_order.txt"):
        pts = read_points(name)
        for kernel in (1, 4, 7):  # double, failsafe<double>, filtered
            write("hull", "%s_kernel%02d" % (name[:-4], kernel), hull_input(kernel, 0, pts))
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    # op 3: a run of collinear points between earlier points 0 and 2 (the diagonal)
    write("hull", "collinear_run", hull_input(4, 1, square, b"\x03\x00\x02\x10"))
    # op 5: a cloud of 1100 points (the prefilter runs)
    write("hull", "cloud", hull_input(7, 2, square, b"\x05\x00\x02\x01\x02\x03\x04"))
    write("hull", "nan", hull_input(4, 1, square + [(float("nan"), 1.0)]))


def linear():
    """linear_fuzzer.cpp: n - 1, scalar, solver, then A by rows and b."""
    def system(n, scalar, solver, a, b):
        out = bytes([n - 1, scalar, solver])
        for v in a + b:
            out += coordinate(v)
        return out
    rho = 0.1
    phi = rho * rho - 0.01
    thesis = ([phi, 1.0, 1.0, 0.0], [1.0, 1.0])  # SPEC 3.2: no pivoting fails in double
    three = ([2.0, 1.0, -1.0, -3.0, -1.0, 2.0, -2.0, 1.0, 2.0], [-3.0, 7.0, 2.0])
    singular = ([1.0, 2.0, 2.0, 4.0], [1.0, 2.0])
    hilbert = ([1.0 / (i + j + 1) for i in range(4) for j in range(4)], [1.0, 0.0, 0.0, 0.0])
    for scalar in range(7):
        write("linear", "thesis_scalar%d" % scalar, system(2, scalar, scalar % 5, *thesis))
        write("linear", "three_scalar%d" % scalar, system(3, scalar, (scalar + 1) % 5, *three))
    write("linear", "singular_rational", system(2, 6, 1, *singular))
    write("linear", "singular_double", system(2, 1, 4, *singular))
    write("linear", "hilbert4_double", system(4, 1, 2, *hilbert))
    write("linear", "zero_pivot_rational", system(2, 6, 0, [0.0, 1.0, 1.0, 0.0], [1.0, 1.0]))


def chain_input(kernel, mode, degree, delta, points):
    """extrusion_fuzzer.cpp: kernel, mode, degree - 1, uncertainty, points."""
    b = bytes([kernel, mode, degree - 1, delta])
    for x, y in points:
        b += b"\x00" + coordinate(x) + coordinate(y)
    return b


def extrusions():
    import json
    import math
    td = os.path.join(os.path.dirname(ROOT), "..", "tools", "relgeo", "testdata")
    for name in ("extrusion_bow_tie.json", "extrusion_thin.json", "extrusion_folded.json"):
        with open(os.path.join(td, name)) as f:
            c = json.load(f)
        if "points" in c:
            pts, degree = [tuple(p[:2]) for p in c["points"]], c["degree"]
        else:  # curves sharing their ends: the chain without the repeated ends
            pts = [tuple(p) for curve in c["curves"] for p in curve[:-1]]
            degree = len(c["curves"][0]) - 1
        for kernel in (1, 3, 5):
            write("extrusion", "%s_kernel%d" % (name[10:-5], kernel), chain_input(kernel, kernel % 3, degree, 0, pts))
    circle = [(math.cos(2 * math.pi * i / 24), math.sin(2 * math.pi * i / 24)) for i in range(24)]
    for kernel in range(7):
        write("extrusion", "circle8_kernel%d" % kernel, chain_input(kernel, kernel % 3, 3, kernel % 5, circle))


def subdivisions():
    """loop_*_fuzzer.cpp: kernel, mode, then mesh_builder.h: base, edit count, edits."""
    for base in range(5):
        for kernel in range(6):
            write("loop_subdivision", "base%d_kernel%d" % (base, kernel), bytes([kernel, kernel % 3 + 4, base, 0]))
        # creases and corners on the base: edit 8 (crease on an edge of a face), 9 (corner)
        write("loop_subdivision", "base%d_tags" % base, bytes([0, 4, base, 3, 0, 8, 1, 0, 1, 2, 8, 1, 1, 2, 3, 9, 0]))
        # a flipped face (edit 0) and a pillow (edit 4): refused
        write("loop_subdivision", "base%d_flipped" % base, bytes([1, 4, base, 1, 0, 0]))
        write("loop_subdivision", "base%d_pillow" % base, bytes([2, 1, base, 1, 0, 4]))
        # near overflow (edit 7, scale 1e300)
        write("loop_subdivision", "base%d_huge" % base, bytes([0, 4, base, 1, 0, 7, 0]))
        for kernel in range(5):  # evaluation at the centre and near a corner of face 0
            write("loop_limit", "eval_base%d_kernel%d" % (base, kernel),
                  bytes([kernel, 0, base, 0, 0, 0, 85, 170, 0, 0, 8, 8]))
        for kernel in range(4):
            write("loop_limit", "bounds_base%d_kernel%d" % (base, kernel), bytes([kernel, 1 + 2 * (base % 2), base, 0]))


def pools(kernel, points, tail):
    b = bytes([kernel, len(points) - 3])
    for p in points:
        b += b"\x00" + b"".join(coordinate(x) for x in p)
    return b + tail


def intersections():
    crossing = [(0, 0, 0), (4, 0, 0), (0, 4, 0), (1, 1, -1), (1, 1, 1), (3, 3, 1)]
    touching = [(0, 0, 0), (4, 0, 0), (0, 4, 0), (4, 0, 0), (5, 0, 2), (5, 1, 0)]
    coplanar = [(0, 0, 0), (4, 0, 0), (0, 4, 0), (1, 1, 0), (5, 1, 0), (1, 5, 0)]
    near = [(0.5, 0.5, 0.5), (12, 12, 12), (24, 24, 24.000000000000004), (0, 0, 1), (1, 0, 1), (0, 1, 1)]
    for name, pts in (("crossing", crossing), ("touching", touching), ("coplanar", coplanar), ("near", near)):
        for kernel in range(5):
            write("triangle_intersection", "%s_kernel%d" % (name, kernel), pools(kernel, pts, bytes(range(6))))
    # implicit points: an LPI of the line 0-1 and the plane 3,4,5; a TPI; predicates
    pts = [(0, 0, -1), (0, 0, 1), (0.1, 0.2, 0.3), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 0), (1, 2, 3)]
    defs = bytes([1, 0, 1, 3, 4, 5, 0, 0, 0, 0]) + bytes([2, 3, 4, 5, 0, 1, 2, 6, 7, 2]) + \
        bytes([0, 2, 0, 0, 0, 0, 0, 0, 0, 0]) + bytes([0, 6, 0, 0, 0, 0, 0, 0, 0, 0])
    cases = bytes([0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 3, 2, 1, 0, 2])
    for kernel in range(6):
        write("implicit_point", "lpi_tpi_kernel%d" % kernel, pools(kernel, pts, defs + cases))


def booleans():
    # head byte: op (0 union, 1 intersection, 2 difference, 3 xor) + 4 * mode
    # (0 mesh Boolean with the exact checks, 1 without, 2 and 3 subdivision
    # Boolean at level 0 and 1); shape bytes (5 cube, 6 icosahedron, 1
    # octahedron); per operand a motion: kind byte (0 none, 1 quarter turns,
    # 2 free angle), its angle byte, then per axis a flag byte (even: a
    # multiple of 1/8 from the next byte) and the byte.
    def motion(kind, angle, t):
        b = bytes([kind, angle])
        for x in t:
            b += bytes([0, x % 256])
        return b
    cases = {
        "cubes_coplanar": (1, 5, 5, motion(0, 0, (0, 0, 0)), motion(0, 0, (4, 2, 0))),
        "cubes_touching": (0, 5, 5, motion(0, 0, (0, 0, 0)), motion(0, 0, (8, 0, 0))),
        "cubes_identical": (0, 5, 5, motion(0, 0, (0, 0, 0)), motion(1, 1, (8, 0, 0))),
        "ico_crossing": (2, 6, 6, motion(0, 0, (0, 0, 0)), motion(2, 30, (3, 2, 1))),
        "octa_cube": (1, 1, 5, motion(0, 0, (0, 0, 0)), motion(2, 17, (1, 1, 1))),
        "subdivision_level1": (0 + 4 * 3, 6, 6, motion(0, 0, (0, 0, 0)), motion(2, 30, (3, 2, 1))),
        "subdivision_level0_creased": (2 + 4 * 2, 5, 1, motion(0, 0, (0, 0, 0)), motion(2, 9, (2, 3, 4))),
    }
    for name, (head, sa, sb, ma, mb) in cases.items():
        write("mesh_boolean", name, bytes([head, sa, sb]) + ma + mb + b"\x01")


if __name__ == "__main__":
    meshes()
    hulls()
    linear()
    extrusions()
    subdivisions()
    intersections()
    booleans()
