#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (fuzz/CMakeLists.txt) into tests/fuzz/corpus/<target>/.

Seeds are valid inputs, so that the fuzzer starts from what the loaders accept: the documents of
data/ and data/models, the sessions of data/sessions (their first events; small files fuzz faster),
the curves and surfaces of tests/cli/data, and one small hand-written input per subcommand and mode.
Files named crash-* or hang-* are findings kept as regression inputs; this script never removes them.
Run from anywhere: python3 tests/fuzz/make_corpus.py
"""
import json
import math
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"
SESSION_EVENTS = 40  # events kept per recorded session


def load(path):
    return json.loads((ROOT / path).read_text())


def write(target, name, value):
    d = CORPUS / target
    d.mkdir(parents=True, exist_ok=True)
    (d / (name + ".json")).write_text(json.dumps(value, separators=(",", ":")) + "\n")


def clamped(points, degree=3):
    p = min(degree, len(points) - 1)
    inner = len(points) - p - 1
    knots = [0.0] * (p + 1) + [i / (inner + 1) for i in range(1, inner + 1)] + [1.0] * (p + 1)
    return {"degree": p, "knots": knots, "points": points}


def stroke(points, with_times=True):
    s = {"points": points}
    if with_times:
        s["times"] = [0.01 * i for i in range(len(points))]
        s["pressure"] = [0.5 + 0.4 * math.sin(i) ** 2 for i in range(len(points))]
    return s


def circle_points(n, r=10.0, cx=0.0, cy=0.0):
    return [[round(cx + r * math.cos(2 * math.pi * i / n), 4), round(cy + r * math.sin(2 * math.pi * i / n), 4)]
            for i in range(n + 1)]


quarter = load("tests/cli/data/quarter_circle.json")
closed = load("tests/cli/data/closed_cubic.json")
ex31 = load("tests/cli/data/nurbs_book_ex3_1_curve.json")
paraboloid = load("tests/cli/data/paraboloid_surface.json")
cylinder = load("tests/cli/data/quarter_cylinder.json")
curves = {"quarter": quarter, "closed": closed, "ex31": ex31}
surfaces = {"paraboloid": paraboloid, "cylinder": cylinder}

# Documents.
write("document", "default_scene", load("data/default_scene.json"))
for model in sorted((ROOT / "data" / "models").glob("*.json")):
    write("document", model.stem, json.loads(model.read_text()))
square = [[[-50, -50], [0, -60], [50, -50]], [[50, -50], [60, 0], [50, 50]],
          [[50, 50], [0, 60], [-50, 50]], [[-50, 50], [-60, 0], [-50, -50]]]
doc_curves = [dict(clamped(pts, 2), id=2 + i, plane=1) for i, pts in enumerate(square)]
doc_curves[0]["fixed"] = [0]
write("document", "fill_mesh_constraint", {
    "grid": {"size": 200, "spacing": 10},
    "planes": [{"id": 1, "origin": [0, 0, 10], "normal": [0, 0, 1], "size": 200, "xAxis": [1, 0, 0],
                "rotation": [0, 0, 0, 1]}],
    "curves": doc_curves,
    "surfaces": [{"id": 6, "construction": {"mode": "fill", "curves": [2, 3, 4, 5]}}],
    "meshes": [{"id": 7, "curves": [2, 3, 4, 5]}],
    "constraints": [{"id": 8, "curve": 2, "type": "position", "u": 0.5}]})
write("document", "revolve_extrude", {
    "planes": [{"id": 1, "origin": [0, 0, 0], "normal": [0, -1, 0], "size": 200}],
    "curves": [dict(clamped([[10, 0], [20, 10], [15, 30], [10, 40]]), id=2, plane=1),
               dict(clamped([[0, 0], [0, 50]], 1), id=3, plane=1)],
    "surfaces": [{"id": 4, "construction": {"mode": "revolve", "curves": [2, 3], "angle": 270}},
                 {"id": 5, "construction": {"mode": "extrude", "curves": [2], "direction": [0, 0, 30]}},
                 dict(paraboloid, id=6)]})

# Replay sessions.
for session in sorted((ROOT / "data" / "sessions").glob("*.json")):
    s = json.loads(session.read_text())
    s["events"] = s["events"][:SESSION_EVENTS]
    write("session", session.stem, s)
write("session", "every_event", {"size": [640, 480], "events": [
    {"type": "press", "x": 10, "y": 20, "button": "left", "modifiers": ["shift", "ctrl", "alt"], "t": 0},
    {"type": "move", "at": [1, 2, 3], "t": 5}, {"type": "release", "x": 10, "y": 20, "button": "right"},
    {"type": "key", "key": "Ctrl+Z", "t": 10}, {"type": "action", "name": "mode.revolve"},
    {"type": "wait", "ms": 100}, {"type": "press", "x": 1, "y": 2, "button": "middle"}]})

# Subcommands on curves and surfaces.
for name, c in curves.items():
    lo, hi = c["knots"][c["degree"]], c["knots"][-c["degree"] - 1]
    write("eval", "curve_" + name, {"curve": c, "params": [lo, (lo + hi) / 2, hi], "derivatives": 2})
    write("insert-knot", "curve_" + name, {"curve": c, "knot": (lo + hi) / 3, "times": 1})
    write("elevate", "curve_" + name, {"curve": c, "times": 1})
    write("remove-knots", "curve_" + name, {"curve": c, "tolerance": 1e-3})
    write("project", "curve_" + name, {"curve": c, "points": [[0.5, 0.5, 0], [2, -1, 1]]})
for name, s in surfaces.items():
    write("eval", "surface_" + name, {"surface": s, "params": [[0, 0], [0.5, 0.25], [1, 1]], "derivatives": 2})
    write("insert-knot", "surface_" + name, {"surface": s, "direction": "u", "knot": 0.5, "times": 2})
    write("elevate", "surface_" + name, {"surface": s, "direction": "v", "times": 1})
    write("remove-knots", "surface_" + name, {"surface": s, "direction": "u", "tolerance": 1e-9})
    write("project", "surface_" + name, {"surface": s, "points": [[2, 2, 1], [0.5, 0, 0.5]]})

# Strokes.
wave = [[i * 2.0, round(5 * math.sin(i / 3.0), 4)] for i in range(30)]
corner = [[i, 0] for i in range(10)] + [[9, j] for j in range(1, 10)]
write("fit", "wave", {"stroke": stroke(wave), "tolerance": 0.1})
write("fit", "corner_minimize", {"stroke": stroke(corner, False), "minimize_control_points": True, "sampling": "all"})
write("fit", "circle_closed", {"stroke": stroke(circle_points(24)), "closed": "closed"})
write("recognize", "circle", {"stroke": stroke(circle_points(32))})
write("recognize", "line", {"stroke": stroke([[i, 0.5 * i] for i in range(20)]), "regularize": False})
write("recognize", "sequence", {"strokes": [stroke(circle_points(24)), stroke(circle_points(24, 10, 0, 30))],
                                "tolerance": 0.2})
open_curve = clamped([[0, 0, 0], [10, 10, 0], [20, -5, 0], [30, 5, 0], [40, 0, 0]])
write("oversketch", "local_c2", {"curve": open_curve, "stroke": stroke([[8 + i, 6 + 0.2 * i] for i in range(15)])})
write("oversketch", "blend", {"curve": open_curve, "stroke": stroke([[8 + i, 6 - 0.2 * i] for i in range(15)]),
                              "method": "blend", "scale": 0.5, "tolerance": 0.01})
write("lift", "wave", {"stroke": stroke(wave, False), "depth": [0, 10]})
write("lift", "view", {"stroke": stroke(circle_points(12), False), "depth": [5, -5],
                       "view": {"origin": [1, 2, 3], "right": [1, 0, 0], "up": [0, 0, 1], "depth": [0, 1, 0]}})
write("constrain-curve", "position_tangent", {"curve": open_curve, "constraints": [
    {"type": "position", "u": 0.5, "value": [20, 3, 1]}, {"type": "tangent", "u": 0.25, "value": [30, 0, 0]}],
    "blocked": [0, 4]})
write("constrain-curve", "distance_curvature", {"curve": open_curve, "insert_knots": 1, "constraints": [
    {"type": "distance", "u": 0.2, "u2": 0.8, "value": 25}, {"type": "curvature", "u": 0.5, "value": [0, 1, 0]}]})
write("constrain-curve", "closed", {"curve": closed, "constraints": [
    {"type": "position", "u": 4.5, "value": [0, 0, 1]}]})

# deform: every constraint type on a flat bicubic 6 x 6 net (tests/deformation/deform_cli_test.cpp).
flat_knots = [0, 0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1, 1]
flat = {"degreeU": 3, "degreeV": 3, "knotsU": flat_knots, "knotsV": flat_knots, "countU": 6, "countV": 6,
        "points": [[i, j, 0] for i in range(6) for j in range(6)]}
line = {"degree": 1, "knots": [0, 0, 1, 1]}
write("deform", "all_types", {"surface": flat, "objective": "force", "constraints": [
    {"type": "position", "uv": [0.5, 0.5], "value": [2.5, 2.5, 1]},
    {"type": "normal", "uv": [0.2, 0.2], "value": [0.1, 0, 1]},
    {"type": "curve", "target": dict(line, points=[[0.5, 4, 0.3], [4.5, 4, 0.3]])},
    {"type": "curve-tangent", "domain": dict(line, points=[[0.2, 0.1], [0.8, 0.1]]), "value": [0, 1, 0.2]},
    {"type": "distance", "uv": [0.1, 0.9], "uv2": [0.9, 0.9], "value": 4.5}]})
write("deform", "bound_blocked", {"surface": flat, "stiffness": 0.5, "blocked": [[2, 2]], "objective": "displacement",
    "bound": {"degree": 1, "knots": [0, 0, 0.25, 0.5, 0.75, 1, 1],
              "points": [[0.2, 0.2], [0.8, 0.2], [0.8, 0.8], [0.2, 0.8], [0.2, 0.2]]},
    "constraints": [{"type": "position", "uv": [0.5, 0.5], "value": [2.5, 2.5, 1]}]})
write("deform", "isocurves", {"surface": flat, "method": "isocurves", "constraints": [
    {"type": "position", "uv": [0.3, 0.3], "value": [1.5, 1.5, 1]},
    {"type": "curve", "target": dict(line, points=[[0.5, 4, 0.3], [4.5, 4, 0.3]])}]})

# Surfaces, one per mode (the inputs of tests/surfaces/surface_cli_test.cpp).
profile = clamped([[1, 0, 0], [1.5, 0, 1], [0.8, 0, 2], [1, 0, 3]])
section2 = clamped([[0, 1, 0], [0.5, 1, 1], [0, 1.5, 2], [0.2, 1, 3]])
path = clamped([[1, 0, 0], [1, 1, 0.5], [2, 2, 0], [3, 2, 1]])
sq = [clamped([[0, 0, 0], [1, 0, 0.2], [2, 0, 0]]), clamped([[2, 0, 0], [2, 1, 0.1], [2, 2, 0]]),
      clamped([[2, 2, 0], [1, 2, -0.2], [0, 2, 0]]), clamped([[0, 2, 0], [0, 1, 0], [0, 0, 0]])]
ring = lambda r, z: {"degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                     "points": [[r, 0, z], [r, r, z], [0, r, z], [-r, r, z], [-r, 0, z], [-r, -r, z], [0, -r, z],
                                [r, -r, z], [r, 0, z]],
                     "weights": [1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1,
                                 0.7071067811865476, 1]}
modes = {
    "revolve": {"curves": [profile], "axis": {"point": [0, 0, 0], "direction": [0, 0, 1]}, "angle": 180},
    "extrude_direction": {"curves": [profile], "direction": [0, 2, 0]},
    "extrude_path": {"curves": [profile], "path": path},
    "loft": {"curves": [profile, section2], "degree": 1},
    "sweep": {"curves": [clamped([[1, 0.2, 0], [1, 0, 0.2], [1, -0.2, 0]]), path], "tolerance": 1e-3},
    "boundary-rotation": {"curves": [profile, clamped([[-1, 0, 0], [-1.2, 0, 1], [-1, 0, 3]])]},
    "rail-rotation": {"curves": [ring(1, 0), ring(1.5, 2), clamped([[1, 0, 0], [1.4, 0, 1], [1.5, 0, 2]])]},
    "fill": {"curves": sq},
    "fill_tangents": {"curves": sq, "angle_tolerance": 10, "tangents": [{"curve": 0, "surface": {
        "degreeU": 2, "degreeV": 1, "knotsU": [0, 0, 0, 1, 1, 1], "knotsV": [0, 0, 1, 1], "countU": 3, "countV": 2,
        "points": [[0, 0, 0], [0, -1, 0], [1, 0, 0.2], [1, -1, 0.2], [2, 0, 0], [2, -1, 0]]}}]},
    "gordon": {"curves": [clamped([[0, 0, 0], [1, 0, 0.5], [2, 0, 0]]), clamped([[0, 2, 0], [1, 2, -0.5], [2, 2, 0]])],
               "v_curves": [clamped([[0, 0, 0], [0, 1, 0.3], [0, 2, 0]]), clamped([[2, 0, 0], [2, 1, 0.2], [2, 2, 0]])]},
}
for name, value in modes.items():
    write("surface", name, dict(value, mode=name.split("_")[0]))
# plan: documents (inline; a "path" would fuzz the file system), with states and every constraint form.
for name in ("default_scene", "bench_20_curves_5_planes"):
    write("plan", name, {"document": load("data/" + name + ".json")})
write("plan", "constraints", {"document": {
    "planes": [{"id": 1, "origin": [0, 0, 0], "normal": [0, 0, 1], "size": 100, "state": "fixed"}],
    "curves": [{"id": 2, "plane": 1, "fixed": [0], **clamped([[0, 0], [10, 5], [20, 5], [30, 0]])},
               {"id": 3, "plane": 1, **clamped([[0, 20], [10, 25], [20, 25], [30, 20]])}],
    "surfaces": [{"id": 4, "construction": {"mode": "loft", "curves": [2, 3]}}],
    "constraints": [{"curve": 2, "type": "position", "u": 0.5},
                    {"type": "curve-on-surface", "targets": [3, 4]},
                    {"type": "smoothing", "targets": [4], "weight": 0.5},
                    {"type": "normal", "targets": [4], "uv": [0.5, 0.5], "value": [0, 0, 1]}]}})
# A sculpt: a flat sheet deformed onto an arch on a vertical plane (data/models/sculpt_start.json).
sculpt_doc = load("data/models/sculpt_start.json")
sculpt_doc["curves"] = [dict(clamped([[-60, -60], [-20, -30], [20, -30], [60, -60]]), id=3, plane=1)]
sculpt_doc["surfaces"].append({"id": 4, "construction": {"mode": "sculpt", "base": 2, "curves": [3], "stiffness": 0.8,
                                                         "objective": "displacement"}})
write("document", "sculpt", sculpt_doc)
write("plan", "sculpt", {"document": sculpt_doc})
# A sculpt with every constraint beside its target: a handle point, a bound, blocked points, a distance
# and a curve tangent (tests/model/sculpt_constraints_test.cpp).
handles_doc = json.loads(json.dumps(sculpt_doc))
handles_doc["surfaces"].pop()
handles_doc["points"] = [{"id": 4, "position": [0, 0, 12], "rotation": [0.1, 0, 0, 0.995]}]
handles_doc["surfaces"].append({"id": 5, "construction": {
    "mode": "sculpt", "base": 2, "curves": [3], "points": [{"point": 4, "uv": [2.5, 2.5], "normal": True}],
    "bound": [[0.5, 0.5], [4.5, 0.5], [4.5, 4.5], [0.5, 4.5]], "blocked": [[0, 0], [7, 7]],
    "distances": [{"uv": [1, 1], "uv2": [4, 1], "value": 40}],
    "curve_tangents": [{"curve": 3, "direction": [0, 1, 1]}]}})
write("document", "sculpt_handles", handles_doc)
write("plan", "sculpt_handles", {"document": handles_doc})
write("network", "square", {"curves": sq, "loops": [[0, 1, 2, 3]], "fairing": 2})
write("network", "closed_ring", {"curves": [ring(1, 0)], "loops": [[0]], "edge_length": 0.2})
# regularize: a small ill-conditioned system (Hilbert-like), TSVD with a prior, MTSVD with a given
# smoothing, three right-hand-side columns (tests/regularization/regularize_cli_test.cpp).
hilbert = [[1 / (i + j + 1) for j in range(6)] for i in range(8)]
hb = [sum(row) + 1e-4 * ((-1) ** i) for i, row in enumerate(hilbert)]
write("regularize", "tsvd_corner", {"matrix": hilbert, "rhs": hb})
write("regularize", "tsvd_prior_k", {"matrix": hilbert, "rhs": hb, "k": 3, "prior": [0.5] * 6,
                                     "corner_method": "knot-removal"})
write("regularize", "mtsvd_default", {"matrix": hilbert, "rhs": [[v, 2 * v, -v] for v in hb], "method": "mtsvd"})
write("regularize", "mtsvd_smoothing", {"matrix": hilbert, "rhs": hb, "method": "mtsvd", "svd": "eigen",
                                        "smoothing": [[1 if c == r else -1 if c == r + 1 else 0 for c in range(6)]
                                                      for r in range(5)]})
write("regularize", "wide", {"matrix": [row[:] for row in hilbert[:4]], "rhs": hb[:4], "method": "mtsvd"})
# incidence: a flat 6 x 6 sheet, a raised diagonal, a fixed edge, a target without domain
# (tests/incidence/incidence_cli_test.cpp).
diag = dict(line, points=[[0.05, 0.05], [0.95, 0.95]])
raised = {"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "points": [[0.25, 0.25, 0], [2.5, 2.5, 1], [4.75, 4.75, 0]]}
write("incidence", "mtsvd", {"surface": flat, "curves": [{"domain": diag, "target": raised}]})
write("incidence", "tsvd_fixed", {"surface": flat, "method": "tsvd", "k": 4, "curves": [
    {"domain": dict(line, points=[[0, 0], [1, 0]]), "fixed": True}, {"domain": diag, "target": raised}]})
write("incidence", "projected", {"surface": flat, "smoothing": {"area": 1, "thin_plate": 1},
                                 "curves": [{"target": raised}]})
