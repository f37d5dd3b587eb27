#!/usr/bin/python3
"""Control points needed for the same maximum deviation: sculptline-cli fit against FITPACK's
smoothing spline (scipy.interpolate.splprep) and OpenCASCADE's GeomAPI_PointsToBSpline (cubic, C2),
on the synthesized benchmark strokes and on real pen strokes (the $1 unistroke logs, development
subjects only).

    scripts/compare_splprep.py [BUILD_DIR] [--mode default|minimize|both] [--check] [--no-real] [--time]
                               [--quickdraw N] [--dev GESTURE] [--held-out GESTURE] [--resolution Q]
        BUILD_DIR defaults to build-stroke and needs stroke-export and sculptline-cli built there;
        the OCCT column needs occt-fit (built with the project, OpenCASCADE being required), else "-".
        --check: exit status 1 if, in a compared mode, any stroke (synthesized or real) needs more
        control points than the fewer of the two peers (splprep alone where OCCT did not run), or
        the total over all strokes exceeds either peer's total; ctest runs it so
        (tests/stroke/CMakeLists.txt). Before 2026-12-05 only synthesized strokes were held to
        splprep, the fewer of the peers on every stroke being not yet met in the default mode.
        --quickdraw N: also the first N one-stroke circles of the Quick, Draw! test set
        (tests/data/quickdraw), drawn with a mouse or a finger by other people.
        --dev GESTURE: also every development drawing (s02-s06, 150) of one unistroke gesture, e.g.
        circle: where a fitting change may be tuned, unlike the Quick, Draw! and held-out strokes.
        --held-out GESTURE: also every held-out drawing (s07-s11, 150) of one gesture, to report how
        the development strokes' result carries over (added 2026-12-07). Never tune on it.
        --resolution Q: the real strokes (drawn in whole pixels) are fitted with "resolution": Q, as
        the window fits a stroke with its pointer's pixel: the default tolerance is then at least Q
        (FitOptions::resolution; added 2026-12-07). Without it, 0.5 % of the stroke's extent, below
        the pixel on the unistroke logs' strokes of 60-150 px, where every fit follows the pixels'
        staircase.
        --time: also times each fit at the equal deviation found (warm: the fastest of TIME_REPEAT
        calls; ours cold too, the first call in a fresh sculptline-cli process, as `elapsed_ms`).
        splprep is timed around the scipy call (FITPACK plus scipy's Python wrapper), OCCT inside
        occt-fit around GeomAPI_PointsToBSpline, ours inside sculptline-cli around fitStroke.

Which fit is compared. sculptline-cli fit has two search modes (FitOptions::countUp; every knot is
tried for removal in both, SplineFitOptions::removal):
  default   what `fit`, `recognize` and the GUI use.
  minimize  `"minimize_control_points": true` (FitOptions::countUp: the search counts up from the least count).

How. For each stroke: `sculptline-cli fit` (its default tolerance, or the tolerance in the stroke's
name, "s-curve-clean@0.25") gives a curve and the raw samples it dropped (hooks, a loop's
overshoot). The kept raw samples are the data of every fit, and each curve is measured the same
way: the largest distance from a kept raw sample to a dense polyline of the curve (40,000 points,
nearest neighbour by k-d tree: an upper bound that overestimates by at most half the polyline
spacing). splprep's smoothing factor s is bisected (in log s) to the fewest control points whose
deviation is still within ours; OCCT's Tol3D is bisected (in log) likewise. Counts:
ours the curve's points (closed: minus the 3 wrapped repeats); splprep len(t) - k - 1 (periodic:
minus k); OCCT its poles (no periodic mode: a loop is passed with its first point repeated, and is
clamped at the seam).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time
import warnings

try:
    import numpy as np
    from scipy.interpolate import BSpline, splev, splprep
    from scipy.spatial import cKDTree
except ImportError:  # ctest counts exit status 77 as skipped
    print("compare_splprep.py: needs python3-numpy and python3-scipy (scripts/debian-packages.txt)")
    sys.exit(77)

DENSE = 40000
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Real strokes: curved gestures (a C2 peer has no corners to lose), development subjects only
# (tests/data/unistrokes/README.md: s07-s11 are held out), one slow and one fast drawing each.
REAL_GESTURES = ["pigtail", "left_curly_brace", "right_curly_brace", "question_mark", "circle"]
REAL_PICKS = [("s02", "fast", 1), ("s04", "slow", 1), ("s05", "medium", 2)]
# The tolerance sweep of the clean s-curve: the count must follow the tolerance.
SWEEP = [("s-curve-clean", t) for t in (1.0, 0.5, 0.25)]
# --time: each fit timed this many times, the fastest reported (warm).
TIME_REPEAT = 20


def deviation(curve_points, raw):
    tree = cKDTree(curve_points)
    d, _ = tree.query(raw)
    return float(d.max())


# measureStray's share of a segment's length added to the tolerance (kStrayChordShare,
# solvers/stroke/fit_reading.h): a curve point strays where it lies beyond tolerance + share * length
# of every segment of the kept samples' polyline.
STRAY_CHORD_SHARE = 1.0 / 6.0


def stray_excess(dense, raw, closed, tol):
    """How far a curve (dense points) strays from the polyline of the samples (a loop's closed), as
    sculptline's measureStray judges its own curves: the largest, over the curve's points, of the
    least ratio over the segments of the point's distance to the segment over tol + STRAY_CHORD_SHARE
    * its length (<= 1: every point near the stroke). The peers are not held to it; this tells
    whether a peer's fewer control points were bought by straying between samples."""
    a, b = raw, np.roll(raw, -1, axis=0)
    if not closed:
        a, b = a[:-1], b[:-1]
    ab = b - a
    l2 = (ab * ab).sum(axis=1)
    allow = tol + STRAY_CHORD_SHARE * np.sqrt(l2)
    worst = 0.0
    for chunk in np.array_split(dense, max(1, len(dense) // 1000)):
        ap = chunk[:, None, :] - a[None, :, :]
        t = np.clip((ap * ab[None, :, :]).sum(axis=2) / np.where(l2 > 0.0, l2, 1.0)[None, :], 0.0, 1.0)
        d = np.linalg.norm(ap - t[:, :, None] * ab[None, :, :], axis=2)
        worst = max(worst, float((d / allow[None, :]).min(axis=1).max()))
    return worst


def bspline_dense(degree, knots, points):
    t = np.array(knots, dtype=float)
    c = np.array(points, dtype=float)
    n = len(c) - 1
    u = np.linspace(t[degree], t[n + 1], DENSE)
    # The domain's end from inside: where the end knot is repeated (a loop clamped at its seam),
    # scipy evaluates u = t[n + 1] on an interval past the curve (the origin came out).
    u[-1] = np.nextafter(t[n + 1], t[degree])
    return BSpline(t, c, degree)(u)


def splprep_points(raw, closed):
    """The points splprep is given, as a fresh array. With per=1 FITPACK treats the last point as
    the first one's periodic repeat: it ignores it, and scipy overwrites it with the first point in
    place (through the transposed view, so the caller's samples changed too). A loop is therefore
    passed with its first point repeated, unless the stroke already ends on it, so that every kept
    sample enters the fit and the deviation is measured on the samples as drawn. (Before
    2026-12-06 the last kept sample of a loop was replaced so: neither peer was given it, nor was
    either measured on it.) Repeated consecutive samples (the pen resting) are passed once: they
    give FITPACK equal parameters, which its periodic fit refuses ("Invalid inputs")."""
    pts = np.vstack([raw, raw[:1]]) if closed and not np.allclose(raw[0], raw[-1]) else np.array(raw, copy=True)
    moved = np.concatenate([[True], np.any(np.diff(pts, axis=0) != 0.0, axis=1)])
    return pts[moved]


def splprep_fit(raw, s, closed):
    tck, _ = splprep(splprep_points(raw, closed).T, s=s, k=3, per=1 if closed else 0, quiet=2)
    u = np.linspace(0, 1, DENSE)
    dense = np.array(splev(u, tck)).T
    ncoef = len(tck[0]) - 3 - 1
    if closed:
        ncoef -= 3
    return dense, ncoef


def tune_splprep(raw, target, closed):
    """Fewest control points (bisection in log s) whose deviation stays within target."""
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
            if n < best[1] or (n == best[1] and s > best[0]):
                best = (s, n, dev)
        else:
            hi = mid
    return best


def occt_request(exe, pts, tol, repeat=1):
    request = {"points": [[float(v) for v in p] + [0.0] * (3 - len(p)) for p in pts], "tolerances": [tol],
               "repeat": repeat}
    return json.loads(subprocess.run([exe], input=json.dumps(request), check=True, capture_output=True,
                                     text=True).stdout)[0]


def occt_fit(exe, pts, tol, dim):
    r = occt_request(exe, pts, tol)
    if not r["ok"]:
        return None
    return bspline_dense(r["degree"], r["knots"], r["points"])[:, :dim], len(r["points"])


def occt_points(raw, closed):
    """The points OCCT is given: a loop with its first point repeated (no periodic mode)."""
    if closed and not np.allclose(raw[0], raw[-1]):
        return np.vstack([raw, raw[:1]])
    return raw


def time_splprep(raw, s, closed):
    """The fastest of TIME_REPEAT splprep calls at smoothing factor s, in ms."""
    pts = splprep_points(raw, closed).T
    best = float("inf")
    for _ in range(TIME_REPEAT):
        start = time.perf_counter()
        splprep(pts, s=s, k=3, per=1 if closed else 0, quiet=2)
        best = min(best, time.perf_counter() - start)
    return 1000.0 * best


def time_occt(build, raw, tol, closed):
    """The fastest of TIME_REPEAT GeomAPI_PointsToBSpline calls at Tol3D tol, in ms."""
    r = occt_request(os.path.join(build, "occt-fit"), occt_points(raw, closed), tol, TIME_REPEAT)
    return r["ms_min"] if r["ok"] else None


def tune_occt(build, raw, target, closed):
    """Fewest poles (bisection in log Tol3D of GeomAPI_PointsToBSpline) with deviation <= target."""
    exe = os.path.join(build, "occt-fit")
    if not os.path.exists(exe):
        return None
    pts = occt_points(raw, closed)
    # Tol3D bounds OCCT's own deviation measure, near ours: the bracket [target / 4, 4 target] holds
    # the answer; a tolerance far below it costs OCCT seconds on a 1,000-sample stroke.
    lo, hi = np.log(0.25 * target), np.log(4.0 * target)
    best = None
    for _ in range(10):  # 2^-10 of a factor of 16 in Tol3D: below any change in the pole count
        mid = 0.5 * (lo + hi)
        fit = occt_fit(exe, pts, float(np.exp(mid)), raw.shape[1])
        if fit is None:
            hi = mid
            continue
        dev = deviation(fit[0], raw)
        if dev <= target:
            lo = mid
            if best is None or fit[1] < best[1]:
                best = (float(np.exp(mid)), fit[1], dev)
        else:
            hi = mid
    return best


def parse_samples(samples):
    """A recording's "x y t;..." field (tests/data/unistrokes, tests/data/quickdraw) as a stroke:
    y up, as tests/stroke/unistroke_eval.cpp reads them; t from ms to s."""
    pts, times = [], []
    for triple in samples.split(";"):
        x, y, t = (float(v) for v in triple.split())
        pts.append([x, -y])
        times.append(t / 1000.0)
    return {"points": pts, "times": times}


DEV_SUBJECTS = ("s02", "s03", "s04", "s05", "s06")  # tests/data/unistrokes/README.md: s07-s11 are held out
HELD_OUT_SUBJECTS = ("s07", "s08", "s09", "s10", "s11")  # reported (--held-out), never tuned on


def unistroke_rows(subject, held_out=False):
    """(gesture, speed, number, samples) of each drawing in a subject's CSV (x y t; t in ms), none
    when the file is absent. A held-out subject only when asked for (`held_out`: --held-out)."""
    assert subject in DEV_SUBJECTS or (held_out and subject in HELD_OUT_SUBJECTS), \
        f"{subject}: held-out subjects are compared only with --held-out"
    path = os.path.join(ROOT, "tests", "data", "unistrokes", f"{subject}.csv")
    if not os.path.exists(path):
        return
    with open(path) as f:
        for row in csv.reader(f):
            yield row[0], row[1], int(row[2]), row[3]


def load_real():
    """The REAL_PICKS drawings of REAL_GESTURES."""
    out = []
    for subject, speed, number in REAL_PICKS:
        for gesture, sp, num, samples in unistroke_rows(subject):
            if gesture in REAL_GESTURES and sp == speed and num == number:
                out.append({"name": f"{gesture[:12]}-{subject}{sp[0]}{number}", "stroke": parse_samples(samples)})
    return out


def load_dev(gesture, subjects=DEV_SUBJECTS):
    """Every drawing of `gesture` by `subjects` (the development subjects unless told)."""
    held_out = subjects == HELD_OUT_SUBJECTS
    return [{"name": f"{gesture[:8]}-{subject}{sp[0]}{num}", "stroke": parse_samples(samples)}
            for subject in subjects for g, sp, num, samples in unistroke_rows(subject, held_out) if g == gesture]


def unistroke_gestures():
    """The gesture names of the unistroke logs (those --dev and --held-out take)."""
    return sorted({g for g, _, _, _ in unistroke_rows(DEV_SUBJECTS[0], False)})


def load_quickdraw(count):
    """The first `count` one-stroke Quick, Draw! circles (tests/data/quickdraw; a test set, never
    tuned on), as load_real reads the unistroke logs."""
    out = []
    path = os.path.join(ROOT, "tests", "data", "quickdraw", "quickdraw.csv")
    with open(path) as f:
        for row in csv.reader(f):
            if row[0] != "circle" or len(out) >= count:
                continue
            out.append({"name": f"qd-circle-{row[2]}", "stroke": parse_samples(row[3])})
    return out


def main():
    warnings.simplefilter("ignore")  # FITPACK's iteration-limit warnings; the deviation is measured anyway
    parser = argparse.ArgumentParser(description="Control points at equal deviation: ours, splprep and OCCT "
                                     "(see the module's docstring).")
    parser.add_argument("build", nargs="?", default="build-stroke", help="build directory (default build-stroke)")
    parser.add_argument("--mode", choices=("default", "minimize", "both"), default="both")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--no-real", action="store_true")
    parser.add_argument("--time", dest="timing", action="store_true")
    parser.add_argument("--quickdraw", type=int, default=0, metavar="N")
    parser.add_argument("--dev", dest="dev_gesture", metavar="GESTURE")
    parser.add_argument("--held-out", dest="held_out_gesture", metavar="GESTURE")
    parser.add_argument("--resolution", type=float, metavar="Q")
    opt = parser.parse_args()
    build, mode, check, timing, resolution = opt.build, opt.mode, opt.check, opt.timing, opt.resolution
    strokes = json.loads(subprocess.run([f"{build}/stroke-export"], check=True, capture_output=True, text=True).stdout)
    by_name = {s["name"]: s for s in strokes}
    # (name, stroke, tolerance or None, drawn in whole pixels: the real strokes)
    items = [(s["name"], s["stroke"], None, False) for s in strokes if s["name"] != "s-curve-clean"]
    items += [(f"{name}@{tol:g}", by_name[name]["stroke"], tol, False) for name, tol in SWEEP if name in by_name]
    if not opt.no_real:
        items += [(s["name"], s["stroke"], None, True) for s in load_real()]
    items += [(s["name"], s["stroke"], None, True) for s in load_quickdraw(opt.quickdraw)]
    for gesture, subjects in ((opt.dev_gesture, DEV_SUBJECTS), (opt.held_out_gesture, HELD_OUT_SUBJECTS)):
        if not gesture:
            continue
        drawings = load_dev(gesture, subjects)
        if not drawings:
            # (A name that matches no gesture would otherwise compare the synthesized strokes alone.)
            parser.error(f"no drawings of gesture '{gesture}' (the log's names: {', '.join(unistroke_gestures())})")
        items += [(s["name"], s["stroke"], None, True) for s in drawings]
    modes = {"default": [False], "minimize": [True], "both": [False, True]}[mode]
    failures = []
    for minimize in modes:
        label = "minimize_control_points = true (FitOptions::countUp)" if minimize else \
            "default (what fit/recognize/GUI use)"
        print(f"sculptline-cli fit, {label}")
        print(f"{'stroke':<22}{'kept':>6}{'tol':>7}{'max dev':>9}{'ours':>6}{'splprep':>9}{'occt':>6}{'ms':>7}"
              f"  ours <= min(peers)" + ("   warm ms: ours splprep occt" if timing else ""))
        met = 0
        short_straying = 0  # strokes short of a peer where every peer that needs fewer strays
        counts = []
        times = []  # --time: (ours cold, ours warm, splprep warm, occt warm or None)
        for name, stroke, tol, pixels in items:
            request = {"stroke": stroke, "minimize_control_points": minimize}
            if pixels and resolution is not None:
                request["resolution"] = resolution
            if timing:
                request["repeat"] = TIME_REPEAT
            if tol is not None:
                request["tolerance"] = tol
            fit = json.loads(subprocess.run([f"{build}/sculptline-cli", "fit"], input=json.dumps(request),
                                            check=True, capture_output=True, text=True).stdout)
            raw = np.array(stroke["points"], dtype=float)
            dropped = set(fit["dropped_samples"])
            raw = raw[[i for i in range(len(raw)) if i not in dropped]]
            curve = fit["curve"]
            ours = len(curve["points"]) - (3 if fit["closed"] else 0)
            dense = bspline_dense(curve["degree"], curve["knots"], curve["points"])[:, :raw.shape[1]]
            dev = deviation(dense, raw)
            drawn = raw.copy()
            s, n, sdev = tune_splprep(raw, dev, fit["closed"])
            occ = tune_occt(build, raw, dev, fit["closed"])
            # The peers are measured on the samples as drawn (splprep_points).
            assert np.array_equal(raw, drawn), f"{name}: a peer's fit changed the samples"
            peers = [n] + ([occ[1]] if occ else [])
            ok = ours <= min(peers)
            met += ok
            counts.append((ours, n, occ[1] if occ else None))
            strays = ""
            if not ok:
                failures.append((minimize, name, ours, n, occ[1] if occ else None))
                # Whether the peers with fewer control points stay near the stroke between samples.
                beat = []
                if n < ours:
                    beat.append(("splprep", stray_excess(splprep_fit(raw, s, fit["closed"])[0], raw, fit["closed"],
                                                         fit["tolerance"])))
                if occ and occ[1] < ours:
                    occ_dense = occt_fit(os.path.join(build, "occt-fit"), occt_points(raw, fit["closed"]), occ[0],
                                         raw.shape[1])[0]
                    beat.append(("occt", stray_excess(occ_dense, raw, fit["closed"], fit["tolerance"])))
                short_straying += all(e > 1.0 for _, e in beat)
                strays = "  stray " + ", ".join(f"{who} {e:.2f}" for who, e in beat) + \
                    f" (ours {fit['stray']['excess']:.2f})"
            timed = ""
            if timing:
                t = (fit["elapsed_ms"], fit["elapsed_ms_min"], time_splprep(raw, s, fit["closed"]),
                     time_occt(build, raw, occ[0], fit["closed"]) if occ else None)
                times.append(t)
                timed = f"   {t[1]:>13.3f}{t[2]:>8.3f}" + (f"{t[3]:>8.3f}" if t[3] is not None else f"{'-':>8}")
            print(f"{name:<22}{len(raw):>6}{fit['tolerance']:>7.3f}{dev:>9.3f}{ours:>6}{n:>9}"
                  f"{(occ[1] if occ else '-'):>6}{fit['elapsed_ms']:>7.2f}  {'yes' if ok else 'no '}{timed}{strays}")
        tot = [sum(c[i] for c in counts if c[2] is not None) for i in range(3)]
        print(f"-> no more control points than the fewer of the peers on {met} of {len(items)} strokes; "
              f"totals where OCCT ran: ours {tot[0]}, splprep {tot[1]}, occt {tot[2]}")
        print(f"-> of the {len(items) - met} strokes short of a peer, {short_straying} are short only of peers whose "
              f"curve strays between samples (stray excess above 1 by sculptline's measure, which ours meets)"
              + ("" if timing else "\n"))
        if timing:
            def ratios(k):
                r = sorted(t[k] / t[1] for t in times if t[k] is not None)
                return f"{r[len(r) // 2]:.1f}x median ({r[0]:.1f}-{r[-1]:.1f}x)" if r else "-"
            print(f"-> time at equal deviation, summed: ours {sum(t[1] for t in times):.2f} ms warm "
                  f"({sum(t[0] for t in times):.2f} cold), splprep {sum(t[2] for t in times):.2f}, occt "
                  f"{sum(t[3] for t in times if t[3] is not None):.2f}; slower than ours (warm): splprep "
                  f"{ratios(2)}, occt {ratios(3)}\n")
        if tot[0] > tot[1] or (any(c[2] is not None for c in counts) and tot[0] > tot[2]):
            failures.append((minimize, "total", tot[0], tot[1], tot[2]))
    if check and failures:
        for minimize, name, ours, n, occ in failures:
            print(f"FAIL {'minimize' if minimize else 'default'} {name}: {ours} control points, splprep {n}, occt {occ}")
        sys.exit(1)


if __name__ == "__main__":
    main()
