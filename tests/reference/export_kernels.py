#!/usr/bin/env python3
"""Peano-kernel constants of the Hermite interpolants on [0, 1] used by export/to_bspline.cpp:
C(deg, m) = max_t int_0^1 |K_m(t, tau)| dtau, where f(t) - (Hf)(t) = int K_m(t, tau) f^(m)(tau) dtau,
H the cubic (deg 3: f, f' at both ends) or quintic (deg 5: f, f', f'') Hermite interpolant.
Midpoint rule in tau (20001 nodes) on 1999 values of t; prints deg, m, C, 1/C, argmax t.
Reference values (mpmath, 30 digits, on a grid of t): C(3,2) = 0.0624987 (< 1/16), C(3,3) = 1/96,
C(3,4) = 1/384, C(5,3) = 0.0061848, C(5,4) = 0.00067701, C(5,5) = 1/10240, C(5,6) = 1/46080."""
import numpy as np
from math import factorial
# Hermite basis for degree 3 and 5 by solving the interpolation system
def basis(deg):
    # conditions: derivatives 0..r-1 at 0 and 1, r=(deg+1)//2
    r=(deg+1)//2
    A=np.zeros((deg+1,deg+1))
    row=0
    for x in (0.0,1.0):
        for d in range(r):
            for k in range(deg+1):
                if k>=d:
                    A[row,k]=factorial(k)/factorial(k-d)*(x**(k-d) if k-d>0 else 1.0)
            row+=1
    return np.linalg.inv(A)  # coefficients: p = T @ inv(A) @ data
def C(deg,m,nt=2001,ntau=20001):
    r=(deg+1)//2
    Ainv=basis(deg)
    ts=np.linspace(0,1,nt)[1:-1]
    taus=(np.arange(ntau)+0.5)/ntau
    best=0;bt=0
    T=np.vstack([ts**k for k in range(deg+1)]).T  # nt x (deg+1)
    # data for f_tau=(x-tau)_+^(m-1)/(m-1)!: zero at 0; at 1: derivative d: (1-tau)^(m-1-d)/(m-1-d)!
    data=np.zeros((deg+1,ntau))
    for d in range(r):
        e=m-1-d
        data[r+d]=(1-taus)**e/factorial(e) if e>=0 else 0
    H=T@Ainv@data   # nt x ntau
    F=np.maximum(ts[:,None]-taus[None,:],0)**(m-1)/factorial(m-1)
    K=np.abs(F-H).sum(axis=1)/ntau
    i=K.argmax()
    return K[i],ts[i]
for deg,ms in ((3,(2,3,4)),(5,(3,4,5,6))):
    for m in ms:
        v,t=C(deg,m)
        print(deg,m,v,1/v,t)
