#!/usr/bin/python3
"""sculptline-cli regularize against numpy: the same TSVD formula on np.linalg.svd (LAPACK's gesdd),
on a random problem and on Hansen's shaw test problem; and the SVD's time in numpy (README
"Regularization").

    scripts/compare_regularization.py [BUILD_DIR] [--check] [--timing]
        BUILD_DIR defaults to build and needs sculptline-cli built there.
        --check: exit status 1 when a solution, ρ_k (per k, beyond the reference's round-off
                 100 ε σ1 ‖x_k‖) or η_k differs by more than 1e-8 relative, or the singular values by
                 more than 1e-10 relative; ctest runs it so
                 (tests/regularization/CMakeLists.txt).
        --timing: also times np.linalg.svd of a 1000x500 matrix (full_matrices=False), best of 5.
        --timing-matrix FILE: times np.linalg.svd (gesdd) of the matrix in FILE, as written by
                 SCULPTLINE_BENCH_MATRIX=FILE build/sculptline-bench --benchmark_filter=IncidenceSvd
                 (two int32 rows, cols, then column-major float64): best and median of 7.

How. The reference is seed 000 eqs. 3-4 written out in numpy: x_k = x0 + V_k (U_kᵀ b / σ_k − V_kᵀ x0),
ρ_k = ‖A x_k − b‖ and η_k = ‖x_k − x0‖ computed directly from x_k for every k (not by the sums the
CLI uses). The CLI is asked for a given k and a prior, three right-hand sides at once for the random
problem; the shaw problem (midpoint rule, n = 32, as solvers/regularization/test_problems.cpp) with
0.1 % noise runs at the CLI's L-curve corner.
"""
import json
import subprocess
import sys
import time

try:
    import numpy as np
except ImportError:  # ctest counts exit status 77 as skipped
    print("compare_regularization.py: needs python3-numpy (scripts/debian-packages.txt)")
    sys.exit(77)

SOLUTION_TOL = 1e-8
SIGMA_TOL = 1e-10


def run_cli(build, payload):
    out = subprocess.run([f"{build}/sculptline-cli", "regularize"], input=json.dumps(payload), text=True,
                         capture_output=True, check=True)
    return json.loads(out.stdout)


def reference(a, b, x0, k):
    u, s, vt = np.linalg.svd(a, full_matrices=False)
    r = int(np.sum(s > max(a.shape) * np.finfo(float).eps * s[0]))
    b2 = b.reshape(len(b), -1)
    p2 = x0.reshape(a.shape[1], -1)

    def x_at(j):
        return p2 + vt[:j].T @ ((u[:, :j].T @ b2) / s[:j, None] - vt[:j] @ p2)

    rho = [np.linalg.norm(a @ x_at(j) - b2) for j in range(1, r + 1)]
    eta = [np.linalg.norm(x_at(j) - p2) for j in range(1, r + 1)]
    # A x_k − b computed directly cancels: its round-off is about ε σ1 ‖x_k‖, which dwarfs ρ_k when
    # x_k is large (k near the rank of an ill-posed problem). That is the reference's error, not the CLI's.
    floor = np.array([100 * np.finfo(float).eps * s[0] * np.linalg.norm(x_at(j)) for j in range(1, r + 1)])
    return s[:r], np.array(rho), np.array(eta), x_at(k).reshape(x0.shape), floor


def shaw(n):
    h = np.pi / n
    t = -np.pi / 2 + (np.arange(n) + 0.5) * h
    s_, t_ = np.meshgrid(t, t, indexing="ij")
    c = np.cos(s_) + np.cos(t_)
    u = np.pi * (np.sin(s_) + np.sin(t_))
    sinc = np.where(u == 0, 1.0, np.sin(u) / np.where(u == 0, 1.0, u))
    a = h * (c * sinc) ** 2
    x = 2 * np.exp(-6 * (t - 0.8) ** 2) + np.exp(-2 * (t + 0.5) ** 2)
    return a, x


def load_matrix(path):
    with open(path, "rb") as f:
        rows, cols = np.frombuffer(f.read(8), dtype=np.int32)
        return np.frombuffer(f.read(), dtype=np.float64).reshape((cols, rows)).T.copy()


def compare(name, build, a, b, x0, k=None):
    payload = {"matrix": a.tolist(), "rhs": b.tolist(), "prior": x0.tolist()}
    if k is not None:
        payload["k"] = k
    out = run_cli(build, payload)
    s, rho, eta, x, floor = reference(a, b, x0, out["k"])
    rel = lambda got, want: float(np.linalg.norm(np.array(got) - want) / np.linalg.norm(want))
    rho_rel = (float(np.max(np.maximum(np.abs(np.array(out["rho"]) - rho) - floor, 0.0) / rho))
               if len(out["rho"]) == len(rho) else 1.0)
    errors = {"singular_values": rel(out["singular_values"], s), "rho (per k, beyond round-off)": rho_rel,
              "eta": rel(out["eta"], eta), "solution": rel(out["solution"], x)}
    ok = (len(out["rho"]) == len(rho) and errors["singular_values"] <= SIGMA_TOL
          and max(errors["rho (per k, beyond round-off)"], errors["eta"], errors["solution"]) <= SOLUTION_TOL)
    print(f"{name}: k = {out['k']} (corner {out['corner']}), rank {len(rho)}, relative differences "
          + ", ".join(f"{key} {val:.1e}" for key, val in errors.items()) + ("" if ok else "  FAIL"))
    return ok


def main():
    argv = sys.argv[1:]
    matrix_file = None
    if "--timing-matrix" in argv:
        i = argv.index("--timing-matrix")
        matrix_file = argv[i + 1]
        del argv[i:i + 2]
        m = load_matrix(matrix_file)
        times = []
        for _ in range(7):
            t0 = time.perf_counter()
            np.linalg.svd(m, full_matrices=False)
            times.append(time.perf_counter() - t0)
        print(f"numpy {np.__version__} np.linalg.svd {m.shape[0]}x{m.shape[1]} from {matrix_file} (gesdd): "
              f"best {min(times) * 1e3:.1f} ms, median {sorted(times)[3] * 1e3:.1f} ms")
        if "--check" not in argv:
            return
    args = [a for a in argv if not a.startswith("--")]
    build = args[0] if args else "build"
    rng = np.random.default_rng(7)
    a = rng.standard_normal((40, 25))
    ok = compare("random 40x25, 3 right-hand sides, prior, k = 12", build, a, rng.standard_normal((40, 3)),
                 rng.standard_normal((25, 3)), k=12)
    sa, sx = shaw(32)
    sb = sa @ sx
    noise = rng.standard_normal(32)
    sb = sb + noise * (1e-3 * np.linalg.norm(sb) / np.linalg.norm(noise))
    ok &= compare("shaw 32, 0.1 % noise, zero prior, at the corner", build, sa, sb, np.zeros(32))
    if "--timing" in sys.argv:
        m = rng.standard_normal((1000, 500))
        times = []
        for _ in range(5):
            t0 = time.perf_counter()
            np.linalg.svd(m, full_matrices=False)
            times.append(time.perf_counter() - t0)
        print(f"numpy {np.__version__} np.linalg.svd 1000x500 (gesdd): best {min(times) * 1e3:.1f} ms, "
              f"median {sorted(times)[2] * 1e3:.1f} ms")
    if "--check" in sys.argv and not ok:
        sys.exit(1)


if __name__ == "__main__":
    main()
