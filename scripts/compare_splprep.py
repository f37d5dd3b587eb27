#!/usr/bin/python3
"""Control points needed for the same maximum deviation: sculptline-cli fit against FITPACK's
smoothing spline (scipy.interpolate.splprep), on the benchmark strokes (issue 3, §4).

    scripts/compare_splprep.py [BUILD_DIR] [--mode default|minimize|both] [--check]
        BUILD_DIR defaults to build-stroke and needs stroke-export and sculptline-cli built there.
        --check: exit status 1 if, in a compared mode, a stroke needs more control points than
        splprep (the issue's goal); ctest runs it so (tests/stroke/CMakeLists.txt).

Which fit is compared. sculptline-cli fit has two knot-removal modes (SplineFitOptions::removal):
  default   after the error-driven insertion, only the knots of the last insertion round are tried
            for removal (KnotRemoval::LastRound). This is what `fit`, `recognize` and the GUI use:
            the 1,000-sample stroke fits within the 0.2 ms budget (bench BM_StrokeFit).
  minimize  `"minimize_control_points": true`: every interior knot is tried for removal, cheapest
            first (KnotRemoval::AllKnots), ~2x the fitting time (bench BM_StrokeFitFewest).
Both are printed; the last column says whether ours needs no more control points than splprep.
ctest runs both modes with --check: the goal "no more than splprep" holds for each.

How. For each stroke: `sculptline-cli fit` with its default tolerance gives a curve; both curves are
measured the same way, as the largest distance from a raw stroke sample to a dense polyline of the
curve (40,000 points, nearest neighbour by k-d tree: an upper bound that overestimates by at most
half the polyline spacing). splprep's smoothing factor s is then bisected (in log s) to the
largest value whose deviation is still within ours; its control-point count is len(t) - k - 1
(periodic: minus k wrapped repeats), ours the curve's points (closed: minus the 3 wrapped repeats).
"""
import json
import subprocess
import sys
import warnings

try:
    import numpy as np
    from scipy.interpolate import BSpline, splev, splprep
    from scipy.spatial import cKDTree
except ImportError:  # ctest counts exit status 77 as skipped
    print("compare_splprep.py: needs python3-numpy and python3-scipy (scripts/debian-packages.txt)")
    sys.exit(77)

DENSE = 40000


def deviation(curve_points, raw):
    tree = cKDTree(curve_points)
    d, _ = tree.query(raw)
    return float(d.max())


def ours_dense(curve):
    k = curve["degree"]
    t = np.array(curve["knots"])
    c = np.array(curve["points"], dtype=float)
    n = len(c) - 1
    u = np.linspace(t[k], t[n + 1], DENSE)
    return BSpline(t, c, k)(u)


def splprep_fit(raw, s, closed):
    pts = raw[:-1] if closed and np.allclose(raw[0], raw[-1]) else raw
    tck, _ = splprep(pts.T, s=s, k=3, per=1 if closed else 0, quiet=2)
    u = np.linspace(0, 1, DENSE)
    dense = np.array(splev(u, tck)).T
    ncoef = len(tck[0]) - 3 - 1
    if closed:
        ncoef -= 3
    return dense, ncoef


def tune_splprep(raw, target, closed):
    """Largest s (bisection in log s) whose deviation stays within target."""
    # FITPACK stops with "s too small" (and an unconverged, wild spline) for s far below the noise
    # level, so the bracket starts where the residual per sample is a twentieth of the target.
    lo, hi = np.log10(len(raw) * (0.05 * target) ** 2), np.log10(len(raw) * target * target * 4)
    dense, n = splprep_fit(raw, 0.0, closed)  # interpolation: always within
    best = (0.0, n, deviation(dense, raw))
    for _ in range(30):  # the bracket spans ~3 decades: 2^-30 of it is far below any change in n
        mid = 0.5 * (lo + hi)
        s = 10.0 ** mid
        try:
            dense, n = splprep_fit(raw, s, closed)
        except Exception:  # FITPACK may refuse extreme s; treat as too smooth
            hi = mid
            continue
        dev = deviation(dense, raw)
        if dev <= target:
            lo = mid
            if best is None or n < best[1] or (n == best[1] and s > best[0]):
                best = (s, n, dev)
        else:
            hi = mid
    return best


def main():
    warnings.simplefilter("ignore")  # FITPACK's iteration-limit warnings; the deviation is measured anyway
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    build = args[0] if args else "build-stroke"
    mode = "both"
    if "--mode" in sys.argv:
        mode = sys.argv[sys.argv.index("--mode") + 1]
        args = [a for a in args if a != mode]
        build = args[0] if args else "build-stroke"
    if mode not in ("default", "minimize", "both"):
        sys.exit("--mode: must be default, minimize or both")
    check = "--check" in sys.argv
    strokes = json.loads(subprocess.run([f"{build}/stroke-export"], check=True, capture_output=True, text=True).stdout)
    modes = {"default": [False], "minimize": [True], "both": [False, True]}[mode]
    failures = []
    for minimize in modes:
        label = "minimize_control_points = true (KnotRemoval::AllKnots)" if minimize else \
            "default (KnotRemoval::LastRound, what fit/recognize/GUI use)"
        print(f"sculptline-cli fit, {label}")
        print(f"{'stroke':<15}{'samples':>8}{'max dev':>9}{'ours ctrl':>10}{'splprep ctrl':>13}{'splprep dev':>12}"
              f"{'s':>10}  ours <= splprep")
        met = 0
        for item in strokes:
            stroke = item["stroke"]
            request = {"stroke": stroke, "minimize_control_points": minimize}
            fit = json.loads(subprocess.run([f"{build}/sculptline-cli", "fit"], input=json.dumps(request),
                                            check=True, capture_output=True, text=True).stdout)
            raw = np.array(stroke["points"], dtype=float)
            curve = fit["curve"]
            ours = len(curve["points"]) - (3 if fit["closed"] else 0)
            dev = deviation(ours_dense(curve), raw)
            s, n, sdev = tune_splprep(raw, dev, fit["closed"])
            ok = ours <= n
            met += ok
            if not ok:
                failures.append((minimize, item["name"], ours, n))
            print(f"{item['name']:<15}{len(raw):>8}{dev:>9.3f}{ours:>10}{n:>13}{sdev:>12.3f}{s:>10.3g}  "
                  f"{'yes' if ok else 'no'}")
        print(f"-> no more control points than splprep on {met} of {len(strokes)} strokes\n")
    if check and failures:
        for minimize, name, ours, n in failures:
            print(f"FAIL {'minimize' if minimize else 'default'} {name}: {ours} control points, splprep {n}")
        sys.exit(1)


if __name__ == "__main__":
    main()
