#!/usr/bin/env python3
"""Compares the two deformation methods of sculptline-cli deform (README "Surface deformation"): the
global solve ("method": "global", least displacement and least force change) against the thesis's
iso-curve propagation ("isocurves", eqs. 6-17, 6-18) on flat nets of the sizes of the thesis's
Table 6-2, with one position constraint in the middle and one target curve across the net.

For each: the largest residual (model units), the smoothness of the change (the norm of the net's
graph Laplacian applied to the control point changes: lower is smoother, as the benchmark's
`smoothness` counter), and the solve time (`elapsed_ms`, median of 5 runs).
Run from the repository root after a build: python3 scripts/compare_deformation_methods.py
"""
import json
import math
import statistics
import subprocess
import sys

CLI = "build/sculptline-cli"
NETS = [(21, 10), (20, 20), (26, 26), (28, 10), (24, 8), (35, 8), (18, 135)]


def knots(n):
    inner = n - 4
    return [0.0] * 4 + [i / (inner + 1) for i in range(1, inner + 1)] + [1.0] * 4


def sheet(nu, nv):
    # A flat net over [0, 100] x [0, 100 * nv / nu] (square cells).
    h = 100.0 / (nu - 1)
    pts = [[h * i, h * j, 0.0] for i in range(nu) for j in range(nv)]
    return {"degreeU": 3, "degreeV": 3, "knotsU": knots(nu), "knotsV": knots(nv), "countU": nu, "countV": nv, "points": pts}


def laplacian_norm(before, after, nu, nv):
    d = [[a[k] - b[k] for k in range(3)] for a, b in zip(after, before)]
    total = 0.0
    for i in range(nu):
        for j in range(nv):
            n = [(i + di, j + dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)) if 0 <= i + di < nu and 0 <= j + dj < nv]
            for k in range(3):
                v = len(n) * d[i * nv + j][k] - sum(d[a * nv + b][k] for a, b in n)
                total += v * v
    return math.sqrt(total)


def run(payload):
    out = subprocess.run([CLI, "deform"], input=json.dumps(payload), capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(out.stderr)
    return json.loads(out.stdout)


def main():
    print("| net | method | max residual (mm) | smoothness ‖L d‖ | solve (ms) |")
    print("|---|---|---|---|---|")
    for nu, nv in NETS:
        s = sheet(nu, nv)
        width = 100.0 * (nv - 1) / (nu - 1)
        arch = [[100.0 * i / 8, 0.3 * width, 12.0 * math.sin(math.pi * i / 8)] for i in range(9)]
        target = {"degree": 3, "knots": knots(9), "points": arch}
        constraints = [{"type": "position", "uv": [0.5, 0.5], "value": [50.0, 0.5 * width, 10.0]},
                       {"type": "curve", "target": target}]
        for label, extra in (("global, force", {"objective": "force"}), ("global, displacement", {"objective": "displacement"}),
                             ("isocurves", {"method": "isocurves"})):
            outs = [run(dict({"surface": s, "constraints": constraints}, **extra)) for _ in range(5)]
            o = outs[0]
            smooth = laplacian_norm(s["points"], o["surface"]["points"], nu, nv)
            ms = statistics.median(x["elapsed_ms"] for x in outs)
            print(f"| {nu}×{nv} | {label} | {o['max_residual']:.2g} | {smooth:.3g} | {ms:.2f} |")


if __name__ == "__main__":
    main()
