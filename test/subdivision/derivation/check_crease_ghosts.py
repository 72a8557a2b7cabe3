#!/usr/bin/env python3
# Checks (exact rationals) that Hoppe's crease rules on a regular crease (crease
# vertices with 3 faces on the patch side) equal the regular Loop rules on the
# net extended by the ghosts g = a + b - c (a, b the crease edge, c its interior
# opposite vertex), and that refined ghosts are the ghosts of the refined net:
# the basis of the regular crease patches of limit_evaluation.h.
# Run: python3 check_crease_ghosts.py
from fractions import Fraction as Fr

from lattice_forms import add, edge_ends as edge_of, regular_edge_point, regular_refine, regular_vertex_point, scale
R=6
real=[(i,j) for i in range(-R,R+1) for j in range(0,R+1)]
idx={p:k for k,p in enumerate(real)}
def ghosts(vals):
    g={}
    for i in range(-R,R):
        p=(i,0);q=(i+1,0);o=(i,1)
        if p in vals and q in vals and o in vals:
            g[(i+1,-1)]=add(add(vals[p],vals[q]),vals[o],Fr(-1))
    return g
def crease_refine(vals):
    # Hoppe's crease rules on the crease row y = 0, the regular rules elsewhere.
    out={}
    for x in range(-2*R,2*R+1):
        for y in range(0,2*R+1):
            if x%2==0 and y==0:
                p=(x//2,0)
                if all(q in vals for q in [p,(p[0]-1,0),(p[0]+1,0)]):
                    out[(x,y)]=add(add(scale(vals[p],Fr(3,4)),vals[(p[0]-1,0)],Fr(1,8)),vals[(p[0]+1,0)],Fr(1,8))
                continue
            if x%2==0 and y%2==0:
                v=regular_vertex_point(vals,(x//2,y//2))
            else:
                p,q=edge_of(x,y)
                if p[1]==0 and q[1]==0:
                    if p in vals and q in vals: out[(x,y)]=add(scale(vals[p],Fr(1,2)),vals[q],Fr(1,2))
                    continue
                v=regular_edge_point(vals,p,q)
            if v is not None: out[(x,y)]=v
    return out
V={p:{idx[p]:Fr(1)} for p in real}
ext=dict(V); ext.update(ghosts(V))
C=crease_refine(V)
Rg=regular_refine(ext,range(-2*R,2*R+1),range(-2,2*R+1))
n=0
for p,v in C.items():
    if p in Rg: assert Rg[p]==v,p; n+=1
G2=ghosts(C)
m=0
for p,v in G2.items():
    if p in Rg: assert Rg[p]==v,p; m+=1
print("real points checked",n,"ghosts checked",m)
