#!/usr/bin/env python3
# Checks (exact rationals) that Hoppe's crease rules on a regular crease (crease
# vertices with 3 faces on the patch side) equal the regular Loop rules on the
# net extended by the ghosts g = a + b - c (a, b the crease edge, c its interior
# opposite vertex), and that refined ghosts are the ghosts of the refined net:
# the basis of the regular crease patches of limit_evaluation.h.
# Run: python3 check_crease_ghosts.py
from fractions import Fraction as Fr
D6 = [(1,0),(0,1),(-1,1),(-1,0),(0,-1),(1,-1)]
R=6
real=[(i,j) for i in range(-R,R+1) for j in range(0,R+1)]
idx={p:k for k,p in enumerate(real)}
def add(a,b,s=Fr(1)):
    r=dict(a)
    for k,v in b.items():
        r[k]=r.get(k,0)+s*v
        if r[k]==0: del r[k]
    return r
def sc(a,s): return {k:v*s for k,v in a.items()}
def ghosts(vals):
    g={}
    for i in range(-R,R):
        p=(i,0);q=(i+1,0);o=(i,1)
        if p in vals and q in vals and o in vals:
            g[(i+1,-1)]=add(add(vals[p],vals[q]),vals[o],Fr(-1))
    return g
def nb(p): return [(p[0]+d[0],p[1]+d[1]) for d in D6]
def edge_of(x,y):
    if x%2==1 and y%2==0: return ((x-1)//2,y//2),((x+1)//2,y//2)
    if x%2==0 and y%2==1: return (x//2,(y-1)//2),(x//2,(y+1)//2)
    return ((x-1)//2,(y+1)//2),((x+1)//2,(y-1)//2)
def crease_refine(vals):
    out={}
    for x in range(-2*R,2*R+1):
        for y in range(0,2*R+1):
            if x%2==0 and y%2==0:
                p=(x//2,y//2)
                if y==0:
                    if all(q in vals for q in [p,(p[0]-1,0),(p[0]+1,0)]):
                        out[(x,y)]=add(add(sc(vals[p],Fr(3,4)),vals[(p[0]-1,0)],Fr(1,8)),vals[(p[0]+1,0)],Fr(1,8))
                elif all(q in vals for q in [p]+nb(p)):
                    v=sc(vals[p],Fr(5,8))
                    for q in nb(p): v=add(v,vals[q],Fr(1,16))
                    out[(x,y)]=v
            else:
                p,q=edge_of(x,y)
                if p[1]==0 and q[1]==0:
                    if p in vals and q in vals: out[(x,y)]=add(sc(vals[p],Fr(1,2)),vals[q],Fr(1,2))
                    continue
                opp=list(set(nb(p))&set(nb(q)))
                if all(r in vals for r in [p,q]+opp):
                    v=add(sc(vals[p],Fr(3,8)),vals[q],Fr(3,8))
                    for r in opp: v=add(v,vals[r],Fr(1,8))
                    out[(x,y)]=v
    return out
def regular_refine(vals):
    out={}
    for x in range(-2*R,2*R+1):
        for y in range(-2,2*R+1):
            if x%2==0 and y%2==0:
                p=(x//2,y//2)
                if all(q in vals for q in [p]+nb(p)):
                    v=sc(vals[p],Fr(5,8))
                    for q in nb(p): v=add(v,vals[q],Fr(1,16))
                    out[(x,y)]=v
            else:
                p,q=edge_of(x,y)
                opp=list(set(nb(p))&set(nb(q)))
                if all(r in vals for r in [p,q]+opp):
                    v=add(sc(vals[p],Fr(3,8)),vals[q],Fr(3,8))
                    for r in opp: v=add(v,vals[r],Fr(1,8))
                    out[(x,y)]=v
    return out
V={p:{idx[p]:Fr(1)} for p in real}
ext=dict(V); ext.update(ghosts(V))
C=crease_refine(V)
Rg=regular_refine(ext)
n=0
for p,v in C.items():
    if p in Rg: assert Rg[p]==v,p; n+=1
G2=ghosts(C)
m=0
for p,v in G2.items():
    if p in Rg: assert Rg[p]==v,p; m+=1
print("real points checked",n,"ghosts checked",m)
