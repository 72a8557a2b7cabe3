# What the derivation scripts of this folder share: values on the regular
# triangular lattice as linear forms over control points (dicts index ->
# Fraction), and Loop's regular rules applied to them symbolically.
# Lattice point (i, j); its six neighbours are D6 away; a point (x, y) of the
# refined lattice is a vertex point when x and y are even, else an edge point.
from fractions import Fraction as Fr

D6 = [(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)]


def add(a, b, s=Fr(1)):
    """The form a + s * b."""
    r = dict(a)
    for k, v in b.items():
        r[k] = r.get(k, 0) + s * v
        if r[k] == 0:
            del r[k]
    return r


def scale(a, s):
    return {k: v * s for k, v in a.items()}


def neighbours(p):
    return [(p[0] + d[0], p[1] + d[1]) for d in D6]


def edge_ends(x, y):
    """The coarse ends of the edge whose refined point is (x, y) (not both even)."""
    if x % 2 == 1 and y % 2 == 0:
        return ((x - 1) // 2, y // 2), ((x + 1) // 2, y // 2)
    if x % 2 == 0 and y % 2 == 1:
        return (x // 2, (y - 1) // 2), (x // 2, (y + 1) // 2)
    return ((x - 1) // 2, (y + 1) // 2), ((x + 1) // 2, (y - 1) // 2)


def regular_vertex_point(vals, p):
    """5/8 p + 1/16 of each neighbour; None unless all are known."""
    if not all(q in vals for q in [p] + neighbours(p)):
        return None
    v = scale(vals[p], Fr(5, 8))
    for q in neighbours(p):
        v = add(v, vals[q], Fr(1, 16))
    return v


def regular_edge_point(vals, p, q):
    """3/8 (p + q) + 1/8 of the two opposite vertices; None unless all are known."""
    opp = list(set(neighbours(p)) & set(neighbours(q)))
    assert len(opp) == 2
    if not all(r in vals for r in [p, q] + opp):
        return None
    v = add(scale(vals[p], Fr(3, 8)), vals[q], Fr(3, 8))
    for r in opp:
        v = add(v, vals[r], Fr(1, 8))
    return v


def regular_refine(vals, xs, ys):
    """One regular Loop step: the refined points (x, y), x in xs, y in ys,
    whose stencils are known."""
    out = {}
    for x in xs:
        for y in ys:
            if x % 2 == 0 and y % 2 == 0:
                v = regular_vertex_point(vals, (x // 2, y // 2))
            else:
                v = regular_edge_point(vals, *edge_ends(x, y))
            if v is not None:
                out[(x, y)] = v
    return out


def limit(vals, p):
    """The regular limit position: 1/2 p + 1/12 of each neighbour."""
    v = scale(vals[p], Fr(1, 2))
    for q in neighbours(p):
        v = add(v, vals[q], Fr(1, 12))
    return v
