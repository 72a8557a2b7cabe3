#!/usr/bin/env python3
"""Writes the bad-input catalogue of test/data/bad/ (doc/reliability.md lists
each file with the defect it has and what relgeo does with it;
test/reliability/bad_input_catalogue_test.cpp checks that behaviour).
The files named fuzz_* are inputs the fuzzers found; they are kept as they
were found, not generated here. Run from the repository root:
    python3 test/data/bad/make_bad_files.py
"""
import os
import struct

DIR = os.path.dirname(os.path.abspath(__file__))

TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write(name, data):
    with open(os.path.join(DIR, name), "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


def off(v, f, header=None):
    s = header if header is not None else "OFF\n%d %d 0\n" % (len(v), len(f))
    s += "".join("%r %r %r\n" % tuple(float(c) for c in p) for p in v)
    s += "".join(("%d " % len(t)) + " ".join(str(i) for i in t) + "\n" for t in f)
    return s


def scaled(v, k):
    return [tuple(c * k for c in p) for p in v]


def ply_binary(v, f, face_count=None, vertex_type="float"):
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty %s x\nproperty %s y\n"
            "property %s z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
            % (len(v), vertex_type, vertex_type, vertex_type, len(f) if face_count is None else face_count))
    code = "<fff" if vertex_type == "float" else "<ddd"
    b = head.encode()
    for p in v:
        b += struct.pack(code, *p)
    for t in f:
        b += struct.pack("<B" + "i" * len(t), len(t), *t)
    return b


def stl_binary(triangles, count=None):
    b = b"relgeo bad-input catalogue".ljust(80, b" ") + struct.pack("<I", len(triangles) if count is None else count)
    for t in triangles:
        b += struct.pack("<fff", 0, 0, 0)
        for p in t:
            b += struct.pack("<fff", *p)
        b += struct.pack("<H", 0)
    return b


def main():
    # empty and truncated files
    for ext in ("off", "obj", "ply", "stl"):
        write("empty." + ext, "")
    write("blank_lines.off", "\n\n   \n")
    write("truncated.off", off(TETRA_V, TETRA_F)[:-16])             # ends inside the faces
    write("truncated_header.off", "OFF\n4\n")                         # the face count is missing
    write("truncated.ply", ply_binary(TETRA_V, TETRA_F)[:-7])         # ends inside the last face
    tri = [tuple(TETRA_V[i] for i in t) for t in TETRA_F]
    write("truncated.stl", stl_binary(tri)[:-20])                     # ends inside the last triangle
    # garbage
    write("garbage.obj", "hello world\nthis is not a mesh\n")
    write("garbage.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                         "property float z\nend_header\nzero one two\n1 0 0\n0 1 0\n")
    write("garbage.stl", bytes(range(60)))                            # shorter than a binary STL header
    write("not_off_keyword.off", "MESH\n4 4 0\n" + off(TETRA_V, TETRA_F).split("\n", 2)[2])
    # a vertex coordinate declared as a list (CGAL's reader dereferences a
    # null cast; found by fuzz/mesh_ply, reduced)
    write("list_coordinate.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property list uchar float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 1 0\n1 0 1 0\n0 1 1 0\n3 0 1 2\n")
    # a token CGAL's reader takes in two reads ("1..0" as "1." and ".0"): the
    # stream falls out of step and reads the next number, 2^32 - 1, as a list
    # count, which it allocates (found by fuzz/mesh_ply, reduced)
    write("misread_number.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uint int vertex_indices\n"
                                "end_header\n1..0 0 4294967295\n1 0\n")
    # a signed 8-bit list count of 200, which CGAL's reader wraps to -56 and
    # then to a size_t near 2^64
    write("signed_count_overflow.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                       "property float z\nelement face 1\nproperty list char int vertex_indices\n"
                                       "end_header\n0 0 0\n1 0 0\n0 1 0\n200" + " 0" * 200 + "\n")
    # wrong counts
    write("wrong_counts_fewer.off", off(TETRA_V, TETRA_F, "OFF\n4 3 0\n"))   # 4 faces follow
    write("wrong_counts_more.ply", ply_binary(TETRA_V, TETRA_F, face_count=5))
    write("huge_face_count.off", off(TETRA_V, TETRA_F, "OFF\n4 10000000 0\n"))
    write("huge_face_count.ply", ply_binary(TETRA_V, TETRA_F, face_count=10000000))
    write("huge_triangle_count.stl", stl_binary(tri, count=10000000))
    write("huge_corner_count.off", off(TETRA_V, [], "OFF\n4 1 0\n") + "1000000000 0 1 2\n")
    # indices
    write("negative_index.off", off(TETRA_V, [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, -3)]))
    write("index_out_of_range.off", off(TETRA_V, [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 7)]))
    write("index_out_of_range.ply", ply_binary(TETRA_V, [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 9)]))
    write("relative_index_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n")
    write("two_corners.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n")
    # NaN and infinity
    write("nan.off", off(TETRA_V, TETRA_F).replace("1.0 0.0 0.0", "1.0 nan 0.0"))
    write("inf.ply", ply_binary([(0, 0, 0), (float("inf"), 0, 0), (0, 1, 0), (0, 0, 1)], TETRA_F))
    write("beyond_double.off", off(TETRA_V, TETRA_F).replace("1.0 0.0 0.0", "1e999 0.0 0.0"))
    # geometric and topological defects (read fine; check_mesh / check_solid / Loop judge them)
    write("duplicated_vertex.off", off(TETRA_V + [(0, 0, 1)], [(0, 2, 1), (0, 1, 3), (0, 4, 2), (1, 2, 3)]))
    # vertex 3 on the edge 1-2: face 3 = (1, 2, 3) has zero area (the solid is flat)
    write("zero_area_face.off", off(TETRA_V[:3] + [(0.5, 0.5, 0)], TETRA_F))
    write("repeated_face.off", off(TETRA_V, TETRA_F + [TETRA_F[0]]))
    write("flipped_face.off", off(TETRA_V, TETRA_F[:3] + [(1, 3, 2)]))
    write("inside_out.off", off(TETRA_V, [(t[0], t[2], t[1]) for t in TETRA_F]))
    two = TETRA_V + [(-1, 0, 0), (0, -1, 0), (0, 0, -1)]
    write("non_manifold_vertex.off", off(two, TETRA_F + [(0, 4, 5), (0, 5, 6), (0, 6, 4), (4, 6, 5)]))
    write("non_manifold_edge.off", off(TETRA_V + [(1, 1, 0)], TETRA_F[:3] + [(1, 2, 3), (1, 4, 2)]))
    write("two_faces_two_edges.off", off(TETRA_V[:3], [(0, 1, 2), (0, 2, 1)]))
    write("open.off", off(TETRA_V, TETRA_F[:3]))
    write("self_intersecting.off", off(TETRA_V + [(0.2, 0.2, -0.5), (0.3, 0.2, 2.0), (0.2, 0.3, 2.0), (0.25, 0.25, 3.0)],
                                       TETRA_F + [(4, 5, 6), (4, 6, 7), (4, 7, 5), (5, 7, 6)]))
    write("coordinates_1e300.off", off(scaled(TETRA_V, 1e300), TETRA_F))
    write("coordinates_1e-300.off", off(scaled(TETRA_V, 1e-300), TETRA_F))
    # every coordinate in [0.75, 1] x the largest double: sums of neighbours overflow
    big = 1.7976931348623157e308
    write("coordinates_max.off", off([tuple(0.75 * big + 0.25 * big * c for c in p) for p in TETRA_V], TETRA_F))
    # feature tags (for tetrahedron.off)
    write("tetrahedron.off", off(TETRA_V, TETRA_F))
    write("tag_negative_index.tags", "corner -1\n")
    write("tag_self_edge.tags", "crease 2 2\n")
    write("tag_missing_index.tags", "crease 1\n")
    write("tag_not_an_edge.tags", "crease 0 1\ncrease 1 2\n")  # valid edges ...
    with open(os.path.join(DIR, "tag_not_an_edge.tags"), "a") as f:
        f.write("crease 0 7\n")                                 # ... and one that is not
    write("tag_corner_out_of_range.tags", "corner 99\n")
    # point files
    write("points_one_number.txt", "0 0\n1\n")
    write("points_nan.txt", "0 0\nnan 1\n")
    write("points_beyond_double.txt", "0 0\n1e999 1\n")
    write("points_garbage.txt", "0 0\nzero one\n")
    write("points_duplicates.txt", "0 0\n1 0\n1 0\n0 1\n0 0\n1 1\n1 1\n")
    write("points_near_1e300.txt", "1e300 1e300\n-1e300 1e300\n1e300 -1e300\n0 0\n-1e300 -1e300\n")
    write("points_near_1e-300.txt", "1e-300 1e-300\n-1e-300 1e-300\n1e-300 -1e-300\n0 0\n-1e-300 -1e-300\n")


if __name__ == "__main__":
    main()
