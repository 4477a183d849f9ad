#!/usr/bin/env python3
"""A small hanging cloth: the static equilibrium of a square of fabric pinned at its two upper corners,
under gravity, with hylc's shell element (Algorithm C8, libhylcmat through hylc.Mesh) and a fitted
material table, found by minimizing the total energy with scipy: trust-region Newton-CG
(scipy.optimize.minimize, the exact gradient and the element-wise PSD-projected Hessian) down to a
gradient 1e-6 of the initial one, then Newton steps on grad E = 0 with the exact Hessian
(scipy.sparse.linalg.spsolve). The second phase is needed because near the minimum the energy changes
by less than its own rounding (1e-16 of E), so an energy-based trust region or line search can no
longer tell good steps from bad ones; Newton's method converges quadratically there on the gradient.

    PYTHONPATH=python /usr/bin/python3 examples/hanging_cloth.py [table.json] [-n 12] [-size 0.2] [-o out.npz]

The table defaults to $HYLC_REFDATA/materials/stock1.json (the paper's stockinette). Prints the energy,
the gradient norm and the sag; exits 1 unless the gradient norm fell by at least -tol (1e-8).
"""
import argparse
import os
import sys

import numpy as np
import scipy.optimize
import scipy.sparse
import scipy.sparse.linalg

import hylc


def square(n, size):
    """an (n+1) x (n+1) grid of a size x size square, material coordinates (u, v) with v up; triangles
    counter-clockwise in (u, v), diagonals alternating"""
    u = np.linspace(0, size, n + 1)
    U, V = np.meshgrid(u, u, indexing="ij")
    uv = np.stack([U.ravel(), V.ravel()], 1)
    tri = []
    for i in range(n):
        for j in range(n):
            p, q, r, s = i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1
            tri += [(p, q, r), (p, r, s)] if (i + j) % 2 == 0 else [(p, q, s), (q, r, s)]
    return uv, np.array(tri)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    default = os.path.join(os.environ.get("HYLC_REFDATA", os.path.join(os.path.dirname(__file__), "..", "..", "shared", "refdata")), "materials", "stock1.json")
    ap.add_argument("table", nargs="?", default=default)
    ap.add_argument("-n", type=int, default=12, help="cells per side")
    ap.add_argument("-size", type=float, default=0.2, help="side of the square (m)")
    ap.add_argument("-tol", type=float, default=1e-8, help="required reduction of the gradient norm")
    ap.add_argument("-o", help="write the rest and final positions and the triangles to this .npz")
    a = ap.parse_args()

    material = hylc.Material(a.table)
    uv, tri = square(a.n, a.size)
    # the cloth hangs in the plane y = 0: x = u, z = v (v up); the normal n of the counter-clockwise
    # (u, v) triangles is then -y
    X = np.c_[uv[:, 0], np.zeros(len(uv)), uv[:, 1]]
    mesh = hylc.Mesh(tri, uv=uv)
    # lumped masses: a third of each triangle's rest area times the area density
    area = 0.5 * np.abs(np.cross(uv[tri[:, 1]] - uv[tri[:, 0]], uv[tri[:, 2]] - uv[tri[:, 0]]))
    mass = np.zeros(len(uv))
    np.add.at(mass, tri.ravel(), np.repeat(area / 3, 3))
    mass *= material.density if material.density > 0 else 0.3
    g = 9.81
    top = np.flatnonzero(np.isclose(uv[:, 1], a.size))
    pinned = top[[np.argmin(uv[top, 0]), np.argmax(uv[top, 0])]]  # the two upper corners
    free = np.setdiff1d(np.arange(len(uv)), pinned)
    fdof = (3 * free[:, None] + np.arange(3)).ravel()

    def full(y):
        x = X.copy()
        x.ravel()[fdof] = y
        return x

    def fun(y):
        x = full(y)
        E, grad = mesh.evaluate(material, x, hessian=False)
        grad = grad.copy()
        grad[:, 2] += mass * g
        return E + g * np.dot(mass, x[:, 2]), grad.ravel()[fdof]

    cache = {}

    def hessp(y, p):
        """the projected Hessian (of the free coordinates) times p; one evaluation per iterate"""
        key = y.tobytes()
        if cache.get("key") != key:
            _, _, H = mesh.evaluate(material, full(y), project=True)
            cache.update(key=key, H=H[fdof][:, fdof].tocsr())
        return cache["H"] @ p

    y0 = X.ravel()[fdof].copy()
    # a small out-of-plane push breaks the symmetry of the flat start
    y0[1::3] += 1e-4 * np.sin(np.pi * uv[free, 0] / a.size) * (1 - uv[free, 1] / a.size)
    E0, g0 = fun(y0)
    gn0 = np.linalg.norm(g0)
    res = scipy.optimize.minimize(fun, y0, jac=True, hessp=hessp, method="trust-ncg", options={"gtol": 1e-6 * gn0, "maxiter": 1000})
    y, (E1, g1) = res.x, fun(res.x)
    gn1, newton = np.linalg.norm(g1), 0
    while gn1 > a.tol * gn0 and newton < 30:  # Newton on grad E = 0, backtracking on |grad E|
        _, _, H = mesh.evaluate(material, full(y))
        step = scipy.sparse.linalg.spsolve(H[fdof][:, fdof].tocsc(), -g1)
        t = 1.0
        while True:
            En, gnew = fun(y + t * step)
            if np.linalg.norm(gnew) < gn1 or t < 1e-3:
                break
            t *= 0.5
        y, E1, g1, gn1, newton = y + t * step, En, gnew, np.linalg.norm(gnew), newton + 1
    x = full(y)
    print("hanging cloth: %s, %d vertices, %d triangles, %g m square pinned at two corners" % (os.path.basename(a.table), mesh.nv, mesh.nt, a.size))
    print("  energy %.10g J -> %.10g J; |gradient| %.3e -> %.3e N (reduced by %.2e): %d trust-region Newton-CG iterations (%s), %d Newton steps"
          % (E0, E1, gn0, gn1, gn1 / gn0, res.nit, res.message, newton))
    z = mesh.strains(x)
    print("  lowest point %.4f m below the pins; out of plane %.4f m; largest |sx| %.3f, |sy| %.3f, |II| %.1f 1/m" %
          (a.size - x[:, 2].min(), np.abs(x[:, 1]).max(), np.abs(z[:, 0]).max(), np.abs(z[:, 2]).max(), np.abs(z[:, 3:]).max()))
    if a.o:
        np.savez(a.o, rest=X, x=x, triangles=tri)
    return 0 if gn1 <= a.tol * gn0 else 1


if __name__ == "__main__":
    sys.exit(main())
