#!/usr/bin/env python3
"""body_space_accuracy.py -- how accurately float solves A x = b, A = J W J^T + eps I, for Topple's
blocks: through the rows' Cholesky factor (Kea's direct path) or through the bodies' coordinates,
(eps W^-1 + J^T J) dv = J^T b and x = (b - J dv) / eps (a 6 x 6 system per body), each with and
without one step of iterative refinement (the residual b - A x formed through the bodies in float,
as KeaDenseRefine does). Prints the velocity change's error, M^-1 J^T x against float64, relative to
its largest entry (bench/RESULTS.md, "Topple: the exact path's remaining levers measured").

Needs python3-numpy (Debian). Usage: python3 bench/topple/body_space_accuracy.py"""
import numpy as np

F32 = np.float32
MASS, SIZE = 48.0, (0.4, 0.6, 0.4)  # demos/topple.c's block
EPS = 0.01 / 50                      # the world's epsilon at massScale 50


def body_inverse_mass():
    a, b, c = SIZE
    inertia = np.diag([MASS * (b * b + c * c) / 12, MASS * (a * a + c * c) / 12, MASS * (a * a + b * b) / 12])
    w = np.zeros((6, 6))
    w[:3, :3] = np.eye(3) / MASS
    w[3:, 3:] = np.linalg.inv(inertia)
    return w


def contact_rows(p, below, above, bodies):
    """A contact's normal and two friction rows at p (relative to the upper block's centre)."""
    rows = []
    for d in (np.array([0, 1.0, 0]), np.array([1.0, 0, 0]), np.array([0, 0, 1.0])):
        row = np.zeros(6 * bodies)
        row[6 * above:6 * above + 6] = np.concatenate([d, np.cross(p, d)])
        if below >= 0:
            q = p + np.array([0, SIZE[1], 0])
            row[6 * below:6 * below + 6] = -np.concatenate([d, np.cross(q, d)])
        rows.append(row)
    return rows


def stack(blocks, corners=4):
    a, b, c = SIZE
    points = [np.array([sx * a / 2, -b / 2, sz * c / 2]) for sx in (-1, 1) for sz in (-1, 1)][:corners]
    rows = []
    for i in range(blocks):
        for p in points:
            rows += contact_rows(p, i - 1, i, blocks)
    return np.array(rows), np.kron(np.eye(blocks), body_inverse_mass())


def trial(rng, J, W):
    n = len(J)
    b = rng.normal(size=n) * 0.1
    A = J @ W @ J.T + EPS * np.eye(n)
    dv64 = W @ J.T @ np.linalg.solve(A, b)
    L = np.linalg.cholesky(A.astype(F32))
    J32, W32, b32 = J.astype(F32), W.astype(F32), b.astype(F32)
    S = F32(EPS) * np.linalg.inv(W).astype(F32) + J32.T @ J32

    def rows_solve(r):
        return np.linalg.solve(L.T, np.linalg.solve(L, r))

    def body_solve(r):
        return (r - J32 @ np.linalg.solve(S, J32.T @ r)) / F32(EPS)

    def residual(x):
        return b32 - (J32 @ (W32 @ (J32.T @ x)) + F32(EPS) * x)

    xc, xb = rows_solve(b32), body_solve(b32)
    answers = (xc, xc + rows_solve(residual(xc)), xb, xb + body_solve(residual(xb)))
    errors = [np.abs(W @ J.T @ x.astype(np.float64) - dv64).max() / np.abs(dv64).max() for x in answers]
    return errors + [np.linalg.cond(A)]


def main():
    rng = np.random.default_rng(2)
    cases = (("one contact (3 rows)", stack(1, 1)), ("four corners (12 rows)", stack(1)),
             ("a stack of 3 (36 rows)", stack(3)), ("a stack of 6 (72 rows)", stack(6)))
    print("free rows | cond(A) | Cholesky | refined | body system | refined")
    for name, (J, W) in cases:
        r = np.array([trial(rng, J, W) for _ in range(100)]).mean(axis=0)
        print(f"{name} | {r[4]:.2g} | {r[0]:.2g} | {r[1]:.2g} | {r[2]:.2g} | {r[3]:.2g}")


if __name__ == "__main__":
    main()
