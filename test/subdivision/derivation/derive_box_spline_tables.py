#!/usr/bin/env python3
# Derives (exact rationals) the tables of include/relgeo/subdivision/box_spline.h:
# the Bezier form (x24) of the regular Loop patch over its 12 control points and
# the 12x12 nets (x16) of its four children, by refining a lattice symbolically,
# taking limit positions at the 15 level-2 points of the triangle and
# interpolating; asserts that all 45 level-3 limit points lie on the quartic.
# Run: python3 derive_box_spline_tables.py
# Derivation of the regular Loop patch tables (exact rationals).
from fractions import Fraction as Fr

from lattice_forms import D6, add, limit, regular_refine, scale
from itertools import product
from math import factorial

SLOTS = [(0,0),(1,0),(0,1),(-1,0),(0,-1),(1,-1),(2,-1),(2,0),(1,1),(0,2),(-1,2),(-1,1)]
R = 7
coarse = [(i,j) for i in range(-R,R+1) for j in range(-R,R+1)]
cidx = {p:k for k,p in enumerate(coarse)}
N = len(coarse)

def refine(vals):
    return regular_refine(vals, range(-2*R,2*R+1), range(-2*R,2*R+1))

L0={p:{cidx[p]:Fr(1)} for p in coarse}
L1=refine(L0)
L2=refine(L1)
L3=refine(L2)

BEZ=[(4-j-k,j,k) for k in range(5) for j in range(5-k)]   # (w,u,v) powers
def bern(i,j,k,w,u,v):
    return Fr(factorial(4),factorial(i)*factorial(j)*factorial(k))*w**i*u**j*v**k

# Interpolate at level-2 points (a,b), a+b<=4: param (a/4,b/4)
pts=[(a,b) for b in range(5) for a in range(5-b)]
A=[[bern(i,j,k,1-Fr(a,4)-Fr(b,4),Fr(a,4),Fr(b,4)) for (i,j,k) in BEZ] for (a,b) in pts]
rhs=[limit(L2,p) for p in pts]
# solve A c = rhs (rhs are linear forms)
n=15
M=[row[:]+[r] for row,r in zip(A,rhs)]
for col in range(n):
    piv=next(r for r in range(col,n) if M[r][col]!=0)
    M[col],M[piv]=M[piv],M[col]
    pv=M[col][col]
    M[col]=[x/pv for x in M[col][:n]]+[scale(M[col][n],1/pv)]
    for r in range(n):
        if r!=col and M[r][col]!=0:
            f=M[r][col]
            M[r]=[a-f*b for a,b in zip(M[r][:n],M[col][:n])]+[add(M[r][n],M[col][n],-f)]
coef=[M[r][n] for r in range(n)]
slot_of={cidx[p]:s for s,p in enumerate(SLOTS)}
tab=[]
for c in coef:
    assert all(k in slot_of for k in c), c
    row=[c.get(cidx[p],Fr(0)) for p in SLOTS]
    assert sum(row)==1
    tab.append(row)
# check: level-3 limit points lie on the quartic
for b in range(9):
    for a in range(9-b):
        u,v=Fr(a,8),Fr(b,8); w=1-u-v
        lim=limit(L3,(a,b))
        val={}
        for (ijk,row) in zip(BEZ,tab):
            B=bern(*ijk,w,u,v)
            for s,x in enumerate(row):
                if x: val=add(val,{cidx[SLOTS[s]]:x},B)
        assert val==lim, (a,b)
print("BEZ order (w,u,v powers):",BEZ)
print("Bezier rows x24:")
for ijk,row in zip(BEZ,tab):
    print(ijk,[int(x*24) for x in row], all((x*24).denominator==1 for x in row))
# child nets
frames=[((0,0),(1,0),(0,1)),((2,0),(-1,1),(-1,0)),((0,2),(0,-1),(1,-1)),((1,0),(0,1),(-1,1))]
for ci,(o,e1,e2) in enumerate(frames):
    print("child",ci)
    for s,(a,b) in enumerate(SLOTS):
        fp=(o[0]+a*e1[0]+b*e2[0],o[1]+a*e1[1]+b*e2[1])
        f=L1[fp]
        assert all(k in slot_of for k in f),(ci,s)
        row=[f.get(cidx[p],Fr(0)) for p in SLOTS]
        print(" ",[int(x*16) for x in row])
