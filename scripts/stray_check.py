#!/usr/bin/python3
"""How far `sculptline-cli fit` strays from the stroke between its samples, on people's strokes.

    scripts/stray_check.py BUILD_DIR GESTURE [GESTURE ...] [--worst N] [--png NAME OUT.png]
        GESTURE: a unistroke gesture of the development subjects (s02-s06, 150 drawings each, e.g.
        circle, pigtail, v), or qd for the first 41 Quick, Draw! circles.
        --worst N: list the N strokes that stray most (default 5).
        --png NAME OUT.png: draw one stroke (its name as listed) and its fit: the samples (red), the
        curve (blue), the control points (green).

The tolerance bounds the distance from every kept sample to the curve (max_error), and
compare_splprep.py measures only that. It says nothing of the curve between two samples: a curve
can pass within the tolerance of every sample and still shoot far out between two of them. This
measures that, independently of the fitter: the curve at 40,000 points (equal steps in parameter)
against the polyline through the kept samples (a loop's closed), each curve point's distance to the
nearest point of that polyline (30 points per segment, nearest neighbour by k-d tree). It reports
the largest distance per stroke in tolerances; a curve that follows its stroke stays near 1 (a
smooth curve through two samples bulges from their chord by its sagitta, a little more on sparse
strokes).

Found 2026-12-06 (session 46, README "Fitting"): spikes of 5-160 tolerances (tens of pixels) on
about a tenth of the development strokes, while every sample is within the tolerance.
"""
import json
import os
import subprocess
import sys

try:
    import numpy as np
    from scipy.spatial import cKDTree
except ImportError:
    print("stray_check.py: needs python3-numpy and python3-scipy (scripts/debian-packages.txt)")
    sys.exit(77)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_splprep as cs  # noqa: E402  (its stroke loaders and B-spline evaluation)

SEGMENT_POINTS = 30


def fitted(build, stroke):
    fit = json.loads(subprocess.run([f"{build}/sculptline-cli", "fit"], input=json.dumps({"stroke": stroke}),
                                    check=True, capture_output=True, text=True).stdout)
    raw = np.array(stroke["points"], dtype=float)
    dropped = set(fit["dropped_samples"])
    kept = raw[[i for i in range(len(raw)) if i not in dropped]]
    curve = fit["curve"]
    # (Without the domain's end: scipy's BSpline gives (0, 0) there where a loop's seam has a triple
    # knot. A loop's end is its start; an open curve's end is its last control point, a sample's.)
    dense = cs.bspline_dense(curve["degree"], curve["knots"], curve["points"])[:-1, :kept.shape[1]]
    return fit, raw, kept, dense


def stray(fit, kept, dense):
    poly = np.vstack([kept, kept[:1]]) if fit["closed"] else kept
    t = np.linspace(0.0, 1.0, SEGMENT_POINTS, endpoint=False)
    pts = np.concatenate([poly[i] + np.outer(t, poly[i + 1] - poly[i]) for i in range(len(poly) - 1)] + [poly[-1:]])
    d, _ = cKDTree(pts).query(dense)
    return float(d.max())


def load(gesture):
    return cs.load_quickdraw(41) if gesture == "qd" else cs.load_dev(gesture)


def draw(build, gesture, name, out):
    from PIL import Image, ImageDraw
    item = next(x for x in load(gesture) if x["name"] == name)
    fit, raw, kept, dense = fitted(build, item["stroke"])
    cp = np.array(fit["curve"]["points"])[:, :2]
    every = np.vstack([raw[:, :2], dense[:, :2]])
    lo, hi = every.min(0), every.max(0)
    scale = 700.0 / max(hi - lo)

    def at(p):
        return (30 + (p[0] - lo[0]) * scale, 30 + (hi[1] - p[1]) * scale)

    im = Image.new("RGB", (760, 760), "white")
    d = ImageDraw.Draw(im)
    d.line([at(p) for p in dense[::10]], fill=(0, 90, 220), width=2)
    for p in raw:
        x, y = at(p)
        d.ellipse([x - 3, y - 3, x + 3, y + 3], outline=(200, 0, 0))
    for p in cp:
        x, y = at(p)
        d.rectangle([x - 2, y - 2, x + 2, y + 2], outline=(0, 160, 0))
    d.text((5, 5), f"{name}: tolerance {fit['tolerance']:.3f}, max_error {fit['max_error']:.3f}, "
                   f"{len(cp)} control points, stray {stray(fit, kept, dense) / fit['tolerance']:.1f} tolerances",
           fill=(0, 0, 0))
    im.save(out)


def main():
    argv = sys.argv[1:]
    if len(argv) < 2:
        print(__doc__)
        sys.exit(2)
    worst = 5
    if "--worst" in argv:
        i = argv.index("--worst")
        worst = int(argv[i + 1])
        del argv[i:i + 2]
    if "--png" in argv:
        i = argv.index("--png")
        name, out = argv[i + 1], argv[i + 2]
        del argv[i:i + 3]
        draw(argv[0], argv[1], name, out)
        return
    build = argv[0]
    for gesture in argv[1:]:
        rows = []
        for item in load(gesture):
            fit, _, kept, dense = fitted(build, item["stroke"])
            rows.append((stray(fit, kept, dense) / fit["tolerance"], item["name"], len(kept),
                         len(fit["curve"]["points"]), len(fit["corners"])))
        rows.sort(reverse=True)
        r = np.array([x[0] for x in rows])
        print(f"{gesture}: {len(r)} strokes; stray in tolerances: max {r.max():.2f}, "
              f"beyond 1.5: {(r > 1.5).sum()}, beyond 3: {(r > 3).sum()}, beyond 10: {(r > 10).sum()}")
        for x in rows[:worst]:
            print("  %6.2f  %-18s %3d samples, %2d control points, %d corners" % x)


if __name__ == "__main__":
    main()
