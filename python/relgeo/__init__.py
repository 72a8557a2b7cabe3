"""relgeo for Python: relgeo's algorithms on numpy arrays, under kernels named
as the ``relgeo`` tool names them (doc/python.md).

Every function takes ``kernel=`` by name (``relgeo.kernel_names()``; the
default is the tool's default, ``"filtered"``) and raises ``ValueError``
listing the valid names for a wrong one. Signs are int8: ``NEGATIVE`` (-1),
``ZERO`` (0), ``POSITIVE`` (1) and ``UNCERTAIN`` (2), the answer of a kernel
that knows it cannot decide (failsafe, interval). Bad input raises a
``relgeo.Error`` subclass (``relgeo.errors``) carrying relgeo's message.
"""

import collections.abc
import json
import os
import tempfile

import numpy as np

from . import _relgeo, sweep
from .errors import (Error, InvalidCsgNode, InvalidInput, InvalidMesh, InvalidOperand, NonFiniteInput,
                     PreconditionViolation, SingularMatrix, UnreadableFile, UnwritableFile)

NEGATIVE, ZERO, POSITIVE, UNCERTAIN = -1, 0, 1, 2
"""The int8 values of relgeo::Certified_sign."""

DEFAULT_KERNEL = "filtered"
"""Filtered_exact_kernel: the tool's default kernel."""

__all__ = [
    "NEGATIVE", "ZERO", "POSITIVE", "UNCERTAIN", "DEFAULT_KERNEL",
    "kernels", "kernel", "kernel_names", "sweep",
    "orient2d", "orient3d", "orientation_grid", "kettner_triples",
    "convex_hull", "solve",
    "read_mesh", "write_mesh", "validate_solid", "boolean", "csg", "check_extrusion", "loop_subdivide", "limit_mesh",
    "limit_evaluate", "join",
    "Error", "InvalidInput", "NonFiniteInput", "UnreadableFile", "UnwritableFile", "InvalidMesh", "InvalidOperand",
    "InvalidCsgNode", "PreconditionViolation", "SingularMatrix",
]

# ---- kernels ----------------------------------------------------------------------

kernels = _relgeo.kernels
kernel = _relgeo.kernel
kettner_triples = _relgeo.kettner_triples


def kernel_names():
    """The kernel names the tool accepts, in its order (``relgeo --help``)."""
    return [k["name"] for k in _relgeo.kernels()]


# ---- predicates -------------------------------------------------------------------

def _point_array(a, dimension, name):
    a = np.asarray(a, dtype=np.float64)
    if a.ndim not in (1, 2) or a.shape[-1] != dimension:
        raise ValueError(f"{name} must have shape ({dimension},) or (n, {dimension}), not {a.shape}")
    return a


def _orientation(signs, dimension, kernel, **points):
    arrays = [_point_array(a, dimension, name) for name, a in points.items()]
    single = all(a.ndim == 1 for a in arrays)
    # Broadcasting views (stride 0 for a single point): nothing is copied.
    rows = np.broadcast_arrays(*(np.atleast_2d(a) for a in arrays))
    result = signs(*rows, kernel)
    return result[0] if single else result


def orient2d(p, q, r, kernel=DEFAULT_KERNEL):
    """Sign of the orientation of (p, q, r) under ``kernel``: 1 left turn
    (counterclockwise), -1 right turn, 0 collinear, 2 (``UNCERTAIN``) when the
    kernel cannot decide.

    p, q, r: shape (2,) or (n, 2), broadcast against each other. Returns an
    ``np.int8`` for three points, else an int8 array of shape (n,).
    Raises ``NonFiniteInput`` (a ``ValueError``) for NaN or infinite coordinates.
    """
    return _orientation(_relgeo.orient2d, 2, kernel, p=p, q=q, r=r)


def orient3d(p, q, r, s, kernel=DEFAULT_KERNEL):
    """Sign of the orientation of (p, q, r, s) under ``kernel`` (relgeo's
    orientation_3: positive when s lies on the positive side of the plane
    (p, q, r) as CGAL's orientation does), 2 (``UNCERTAIN``) when undecided.

    Shapes (3,) or (n, 3), broadcast; returns ``np.int8`` or an (n,) int8 array.
    """
    return _orientation(_relgeo.orient3d, 3, kernel, p=p, q=q, r=r, s=s)


def orientation_grid(triple="a", p=None, q=None, r=None, size=256, kernel=DEFAULT_KERNEL):
    """Kettner et al.'s orientation grid (``relgeo orient-grid``):
    orientation(p + (X, Y) * 2**-53, q, r) for X, Y < size under ``kernel``,
    against the exact sign.

    Give ``triple`` ("a", "b", "c": ``kettner_triples()``) or all of p, q, r.
    Returns a dict: kernel, size, p, q, r, answers and exact ((size, size)
    int8 arrays, row = Y), cells, correct, uncertain, wrong, plus_to_zero,
    minus_to_zero, zero_to_sign, inversions (the tool's counts).
    """
    if p is None and q is None and r is None:
        triples = _relgeo.kettner_triples()
        if triple not in triples:
            raise ValueError(f"unknown triple {triple!r}; triples: {', '.join(triples)}")
        p, q, r = triples[triple]
    elif p is None or q is None or r is None:
        raise ValueError("orientation_grid: give all of p, q, r (or a triple)")
    return _relgeo.orientation_grid(tuple(p), tuple(q), tuple(r), size, kernel)


# ---- hulls --------------------------------------------------------------------------

def convex_hull(points, algorithm="graham-fortune", kernel=DEFAULT_KERNEL):
    """The planar convex hull of an (n, 2) array (``relgeo hull``).

    algorithm: "graham-incremental", "graham-fortune" (default),
    "monotone-chain", or "cgal" (with a cgal-* kernel). Returns a dict with the
    fields of ``relgeo hull --format json``: hull_indices (int64, CCW into
    ``points``), hull ((h, 2) array), status ("ok" or "failed") and failure,
    convex, error (E of eq. 3.2), backward_error (the certificate), its
    moved_points and worst_point, backward_error_bound (graham-fortune),
    coordinate_bound, uncertain_answers, predicate_calls, time_s, algorithm,
    kernel, kernel_model, certified, n. Infinite measures are ``inf``.
    """
    return _relgeo.convex_hull(points, algorithm, kernel)


# ---- linear systems -------------------------------------------------------------------

def solve(A, b, pivoting="partial", scalar="double", exact_limit=100):
    """Solves A x = b by Gaussian elimination (``relgeo linsolve``).

    pivoting: the tool's --method, "none", "partial" (default), "complete",
    "eigen-partial", "eigen-full". scalar: "float", "double" (default),
    "long-double", "mpfr-BITS", "rational". The solution is measured exactly
    against A and b. Returns a dict with the fields of ``relgeo linsolve
    --format json``: status ("ok" / "failed": a zero pivot of the elimination
    or overflow) and failure, x, normwise_backward_error (Rigal-Gaches),
    componentwise_backward_error (Oettli-Prager), forward_error,
    condition_number(_exact), forward_error_bound, growth_factor,
    residual_norm, exact_solution (n <= exact_limit), time_s.
    Raises ``SingularMatrix`` (a ``ValueError``) when A is exactly singular.
    """
    return _relgeo.solve(A, b, pivoting, scalar, exact_limit)


# ---- meshes ---------------------------------------------------------------------------

def read_mesh(path, triangulate=False):
    """(V, F) of an OFF, OBJ, PLY or STL file: V (n, 3) float64, F (m, 3) int64.

    triangulate: split polygons into fans (else a polygon is an error).
    Raises ``UnreadableFile`` (an ``OSError``) for a missing or malformed file.
    """
    return _relgeo.read_mesh(os.fspath(path), triangulate)


def write_mesh(path, V, F, binary=False):
    """Writes (V, F) in the format of the path's extension (.off, .obj, .ply,
    .stl; ASCII with 17 significant digits unless binary PLY/STL).

    Raises ``InvalidMesh`` for a face index that is not a vertex,
    ``NonFiniteInput`` for NaN coordinates, ``UnwritableFile`` when the file
    cannot be written.
    """
    _relgeo.write_mesh(os.fspath(path), V, F, binary)


def validate_solid(V, F):
    """relgeo::validate_solid of (V, F) under the filtered exact kernel: the
    Solid_report as a dict (the fields of the tool's JSON reports):
    valid_solid, kernel, vertices, faces, edges, checks {name: {status,
    count, where, note}}, components, volume, ... Every defect is reported,
    never raised; only indices that are not vertex indices at all (negative)
    raise ``ValueError``.
    """
    return _relgeo.validate_solid(V, F)


# ---- Booleans -------------------------------------------------------------------------

def boolean(A, B, op="union", kernel=DEFAULT_KERNEL, rounding="repaired", retriangulation="delaunay",
            check_self_intersections=True, levels=0, fit=False):
    """The regularised Boolean of two closed triangle meshes A = (V, F) and
    B = (V, F) (``relgeo boolean``): op "union" (default), "intersection",
    "difference" (A - B) or "xor"; exact under the filtered and exact kernels.

    Returns a dict: the result ``V``, ``F`` and ``provenance`` ((m, 2) int64:
    the operand, 0 = A or 1 = B, and its face each output face comes from),
    and the fields of ``relgeo boolean --format json``: status ("ok" or
    "failed") and failure, undecided_pairs, operands, output, validation
    (the result's Solid_report, as ``validate_solid``), rounding_error,
    rounding, counts, time_s (per phase).
    Raises ``InvalidOperand`` (a ``ValueError``) for an operand that is open,
    non-manifold, misoriented, degenerate or self-intersecting, ``ValueError``
    for a kernel without implicit points (the list is in the message).
    The GIL is released during the computation.

    levels=K (K >= 1): the Boolean of the two Loop subdivision solids whose
    control meshes are A and B (``relgeo boolean --levels K``; their limit
    meshes at level K meet in the polyhedral Boolean, whose intersection
    curves become creases of the result's level-K control mesh). Ops union,
    intersection, difference; ``fit=True`` moves the control points near the
    curves (``--fit``); rounding and retriangulation are not options there.
    Returns the result's control mesh ``V``, ``F``, its crease edges
    ``creases`` ((k, 2) int64) and ``corners`` ((k,) int64), and the fields of
    the tool's JSON record (status, failure, level, fitted, operands, output,
    counts, distance, validation: the certified validation of the
    subdivision solid, polyhedral: the polyhedral Boolean's record with its
    ``V``, ``F``, time_s). Crease tags of the operands are not taken yet.
    """
    (VA, FA), (VB, FB) = A, B
    if levels:
        if (rounding, retriangulation) != ("repaired", "delaunay"):
            raise ValueError("boolean: rounding and retriangulation are not options of the subdivision Boolean "
                             "(levels >= 1)")
        return _relgeo.subdivision_boolean(VA, FA, VB, FB, op, levels, kernel, fit, check_self_intersections)
    if fit:
        raise ValueError("boolean: fit needs levels >= 1 (the tool's --fit needs --levels K)")
    return _relgeo.boolean(VA, FA, VB, FB, op, kernel, rounding, retriangulation, check_self_intersections)


def _csg_document(node, arrays):
    """The tree as JSON data: every (V, F) leaf (a pair of arrays, or a dict
    with "vertices" and "faces") becomes {"mesh": {"arrays": k}} with its
    arrays appended to ``arrays``; file names become strings. Anything else is
    left for the tool's parser to accept or refuse, naming the node."""
    if (isinstance(node, tuple) and len(node) == 2) or (isinstance(node, list) and len(node) == 2 and
                                                        isinstance(node[0], np.ndarray)):
        arrays.append((np.asarray(node[0], dtype=np.float64), np.asarray(node[1], dtype=np.int64)))
        return {"mesh": {"arrays": len(arrays) - 1}}
    if isinstance(node, dict):
        if "vertices" in node and "faces" in node and "mesh" not in node and "op" not in node:
            return _csg_document((node["vertices"], node["faces"]), arrays)
        node = dict(node)
        if isinstance(node.get("mesh"), (str, os.PathLike)):
            node["mesh"] = os.fspath(node["mesh"])
        if isinstance(node.get("args"), (list, tuple)):
            node["args"] = [_csg_document(arg, arrays) for arg in node["args"]]
    return node


def csg(tree, kernel=DEFAULT_KERNEL, rounding="repaired", retriangulation="delaunay", check_self_intersections=True,
        base=None, intermediates="rounded"):
    """Evaluates a CSG tree of closed triangle meshes (``relgeo csg``).

    tree: the path of a TREE.json file (its mesh files relative to its
    folder, as the tool reads it), or the same document as a dict: a node is
    ``{"op": "union" | "intersection" | "difference", "args": [node, ...]}``
    (a difference is its first argument minus all the others) or a leaf:
    ``{"mesh": "file.off"}`` (relative to ``base``, default the current
    folder), a pair ``(V, F)`` of arrays, or ``{"vertices": V, "faces": F}``.
    Kernels: "filtered" (default), "exact", "double". intermediates:
    "rounded" (default: every result rounded to doubles and repaired) or
    "exact" (with kernel="exact": every result kept in exact rationals, the
    root rounded once; slower with every step).

    Returns a dict: the root's solid ``V``, ``F`` (the last valid result when
    a step failed) and the fields of ``relgeo csg --format json``: tree (the
    file; absent for a dict), kernel, intermediates, status ("ok" or
    "failed"), failure, steps [{node, operation, ok, failure, faces, volume,
    validation, rounding, coordinate_bits, seconds}], output {vertices,
    faces, volume, rounding, validation}, seconds, total_seconds. Raises
    ``InvalidCsgNode`` (an ``InvalidInput``, a ``ValueError``) naming the
    node (``e.node``: "root.1") for an unknown
    op, fewer than two arguments, a leaf that cannot be read or is not a
    valid solid; ``UnreadableFile`` for a tree file that cannot be read or
    is not JSON; ``ValueError`` for a bad kernel or option name. The GIL is
    released while the tree is read and evaluated.
    """
    options = (kernel, rounding, retriangulation, check_self_intersections, intermediates)
    if isinstance(tree, (str, os.PathLike)):
        return _relgeo.csg(os.fspath(tree), None, [], "", *options)
    arrays = []
    # What JSON cannot hold (an array outside a leaf) becomes a string, which
    # the parser refuses naming the node.
    text = json.dumps(_csg_document(tree, arrays), default=lambda o: f"<{type(o).__name__}>")
    return _relgeo.csg(None, text, arrays, os.fspath(base) if base is not None else "", *options)


# ---- extrusion ------------------------------------------------------------------------

def check_extrusion(contour, algorithm="graham-fortune", kernel="failsafe", uncertainty=None,
                    absolute_uncertainty=None, prune=True, max_listed=50):
    """Certified well-formedness of an extruded object (thesis Sec. 3.4.1,
    ``relgeo extrusion``): its contour, a path to a contour JSON file or the
    same document as a dict (format: ``relgeo help extrusion``).

    Defaults are the tool's: kernel "failsafe", algorithm "graham-fortune",
    uncertainties from the contour (else 1e-3 relative, 0 absolute).
    Returns the record of ``relgeo extrusion --format json`` as a dict
    (verdict, conditions with their margins, offending problems...).
    Raises ``UnreadableFile`` / ``InvalidInput`` / ``NonFiniteInput`` for a
    bad contour, ``ValueError`` for a bad name.
    """
    if isinstance(contour, dict):
        return _relgeo.check_extrusion("<dict>", json.dumps(contour), algorithm, kernel, uncertainty,
                                       absolute_uncertainty, prune, max_listed)
    return _relgeo.check_extrusion(os.fspath(contour), None, algorithm, kernel, uncertainty, absolute_uncertainty,
                                   prune, max_listed)


# ---- subdivision ----------------------------------------------------------------------

def loop_subdivide(V, F, levels=1, kernel="double", rules="hoppe"):
    """(V, F) refined ``levels`` times by Loop's scheme (``relgeo subdivide``):
    levels 0..12, a kernel with constructions (float, double, long-double,
    failsafe, interval, filtered, exact, mpfr-53, mpfr-113; the tool's
    default "double"), crease rules
    "hoppe" or "blz" (crease and corner tags are not taken yet).
    Raises ``InvalidMesh`` / ``NonFiniteInput`` for bad meshes, ``ValueError``
    for bad names or levels."""
    return _relgeo.subdivide(V, F, levels, kernel, rules)["refined"]


def limit_mesh(V, F, levels=1, kernel="double", rules="hoppe"):
    """The limit mesh of (V, F) refined ``levels`` times: the refined mesh with
    every vertex moved to its point on the limit surface (``relgeo subdivide
    --limit``); arguments as ``loop_subdivide``."""
    return _relgeo.subdivide(V, F, levels, kernel, rules)["limit"]


def limit_evaluate(V, F, face, u, v, kernel="double", rules="hoppe"):
    """The point of the Loop limit surface of the control mesh (V, F) at the
    parameter (u, v) of face ``face`` (relgeo::Loop_limit_surface: box
    splines on regular patches, exact local subdivision elsewhere; the
    point w a + u b + v c of face (a, b, c) when the surface is the face),
    computed under ``kernel`` (those of ``loop_subdivide``; exact under
    "exact", enclosed under "interval") and rounded to double.

    face, u, v: scalars or arrays, broadcast against each other. Returns a
    (3,) array for scalars, else an (n, 3) array. Raises ``InvalidInput``
    for a face out of range or (u, v) outside the triangle u, v >= 0,
    u + v <= 1, ``NonFiniteInput`` for NaN parameters, ``InvalidMesh`` for
    a mesh Loop's scheme refuses, ``ValueError`` for bad names.
    """
    single = all(np.ndim(a) == 0 for a in (face, u, v))
    face, u, v = (np.atleast_1d(a) for a in np.broadcast_arrays(np.asarray(face, dtype=np.int64),
                                                                 np.asarray(u, dtype=np.float64),
                                                                 np.asarray(v, dtype=np.float64)))
    if face.ndim != 1:
        raise ValueError(f"limit_evaluate: face, u and v must be scalars or 1-d arrays, not of shape {face.shape}")
    points = _relgeo.limit_evaluate(V, F, face, u, v, kernel, rules)
    return points[0] if single else points


# ---- joining --------------------------------------------------------------------------

def join(surface, meshes, method="whitney", kernel=DEFAULT_KERNEL, curves=(), output=None,
         max_absolute_error=float("inf"), max_normal_error=float("inf"), edge_curves=True, layers=1, min_angle=0.0,
         slope_margin=2.0**-30, extrapolation=0.05):
    """Joins mesh patches to the trimmed faces of a surface model (thesis Ch.
    4, ``relgeo join``).

    surface: the model's file (a JSON relgeo-surface-model, doc/joining.md;
    STEP/IGES when relgeo has OpenCASCADE), or that JSON document as a dict
    (written to a temporary file "surface-model-dict.json", the name the
    errors give; Python's floats are written so that they read back bit for
    bit). meshes: one patch per face, in
    face order, each a mesh file or a pair (V, F) of arrays. method
    "whitney" (default), "naive" or "occt"; kernel of the certified checks:
    "failsafe", "interval", "filtered" (default), "exact". curves: edge-curve
    JSON files; output: also write the joined mesh there. The criteria and
    joiner parameters are the tool's options (``max_absolute_error``,
    ``max_normal_error``, ``edge_curves=False`` for ``--no-edge-curves``,
    ``layers``, ``min_angle`` (0: 20.7 degrees), ``slope_margin``,
    ``extrapolation``).

    Returns a dict: the joined mesh ``V``, ``F``, ``face_of_triangle`` (the
    model face of each triangle, int64) and the fields of ``relgeo join
    --format json`` (status "ok" or "failed" and failure, faces with the
    errors before and after and the certified flip counts, summary,
    criteria, ...; ``meshes`` names array patches "<arrays i>", ``output``
    is "" when not written). Raises ``UnreadableFile`` for a missing or
    malformed file, ``InvalidInput`` for meshes that do not project onto
    their faces or do not fit the model, ``ValueError`` for bad options.
    """
    names, arrays = [], []
    for i, mesh in enumerate(meshes):
        if isinstance(mesh, (str, os.PathLike)):
            names.append(os.fspath(mesh))
            arrays.append(None)
        else:
            V, F = mesh
            names.append(f"<arrays {i}>")
            arrays.append((np.asarray(V, dtype=np.float64), np.asarray(F, dtype=np.int64)))
    def run(surface_path):
        return _relgeo.join(surface_path, names, arrays, [os.fspath(c) for c in curves],
                            os.fspath(output) if output is not None else "", method, kernel, max_absolute_error,
                            max_normal_error, edge_curves, layers, min_angle, slope_margin, extrapolation)

    if isinstance(surface, collections.abc.Mapping):
        with tempfile.TemporaryDirectory(prefix="relgeo-join-") as folder:
            path = os.path.join(folder, "surface-model-dict.json")
            with open(path, "w") as f:
                json.dump(surface, f)
            return run(path)
    return run(os.fspath(surface))
