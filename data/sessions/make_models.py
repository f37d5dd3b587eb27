#!/usr/bin/env python3
"""Writes the surface-model sessions of issue 6 §4 (the thesis's Figs. 5-7, 5-9, 5-10): a bottle with
its plug and handle, a boat, a fish and a vase, each from a few strokes, plus the live-update
benchmark session. Each session starts from a document in data/models/ that holds only the
projection planes the designer placed (and, for the drag session, curves and surfaces); the strokes,
mode switches and curve picks are replayed. Pointer events name model points ("at": [x, y, z]) and
the replayer finds their pixels with the camera of the moment, so the sessions do not depend on how
the window frames the scene. Units: mm, Z up."""
import json
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = os.path.join(os.path.dirname(HERE), "models")


class Session:
    def __init__(self):
        self.events = []
        self.t = 0

    def tick(self, dt=20):
        self.t += dt
        return self.t

    def action(self, name):
        self.events.append({"type": "action", "name": name, "t": self.tick()})

    def key(self, key):
        self.events.append({"type": "key", "key": key, "t": self.tick()})

    def stroke(self, points, dt=8):
        """press, moves, release through world points (on the active plane)."""
        self.events.append({"type": "press", "at": points[0], "button": "left", "t": self.tick(50)})
        for p in points[1:]:
            self.events.append({"type": "move", "at": p, "t": self.tick(dt)})
        self.events.append({"type": "release", "at": points[-1], "button": "left", "t": self.tick(dt)})

    def click(self, point):
        self.events.append({"type": "press", "at": point, "button": "left", "t": self.tick(40)})
        self.events.append({"type": "release", "at": point, "button": "left", "t": self.tick(10)})

    def select_plane(self, origin):
        """Select mode, a click on the plane's jack (at its origin), back to sketching."""
        self.action("mode.select")
        self.click(origin)
        self.action("mode.sketch")

    def turn_view(self, dx, dy, at=(400, 300)):
        """View mode's drag from the viewport's centre (pixels): the examiner turns the camera. The
        pointer rests before the release, so the view does not keep spinning."""
        x, y = at
        self.events.append({"type": "press", "x": x, "y": y, "button": "left", "t": self.tick(50)})
        for k in range(1, 21):
            self.events.append({"type": "move", "x": x + dx * k // 20, "y": y + dy * k // 20, "t": self.tick(15)})
        self.events.append({"type": "move", "x": x + dx, "y": y + dy, "t": self.tick(400)})
        self.events.append({"type": "release", "x": x + dx, "y": y + dy, "button": "left", "t": self.tick(400)})

    def write(self, name):
        with open(os.path.join(HERE, name), "w") as f:
            json.dump({"size": [800, 600], "events": self.events + [{"type": "wait", "ms": 50}]}, f, indent=1)
            f.write("\n")


def r(p):
    return [round(c, 3) for c in p]


def bezier(ctrl, n=40):
    """Points of the Bezier curve with control points ctrl (any dimension), n samples."""
    out = []
    for i in range(n):
        t = i / (n - 1)
        pts = [list(c) for c in ctrl]
        while len(pts) > 1:
            pts = [[(1 - t) * a + t * b for a, b in zip(p, q)] for p, q in zip(pts, pts[1:])]
        out.append(r(pts[0]))
    return out


def circle(centre, u, v, radius, n=48, turns=1.0):
    return [r([centre[k] + radius * (math.cos(2 * math.pi * turns * i / (n - 1)) * u[k] +
                                      math.sin(2 * math.pi * turns * i / (n - 1)) * v[k]) for k in range(3)])
            for i in range(n)]


def plane(pid, origin, normal, size, x_axis):
    return {"id": pid, "origin": origin, "normal": normal, "size": size, "xAxis": x_axis}


def write_document(name, planes, curves=(), surfaces=(), compact=False):
    """compact: lists of numbers on one line each (a large control net stays a small file)."""
    doc = {"units": "mm", "grid": {"size": 200, "spacing": 10}, "planes": planes,
           "curves": list(curves), "surfaces": list(surfaces)}
    text = json.dumps(doc, indent=1)
    if compact:
        text = re.sub(r"\[\s*(-?[0-9.e+-]+(?:,\s*-?[0-9.e+-]+)*)\s*\]",
                      lambda m: "[" + ",".join(v.strip() for v in m.group(1).split(",")) + "]", text)
    with open(os.path.join(MODELS, name), "w") as f:
        f.write(text + "\n")


def bottle():
    # Plane 1: small, facing +X at the handle's upper end (its profile circle); plane 2: the
    # vertical XZ plane through the axis, added last so it is the active one.
    handle_start = [37, 0, 78]
    p1 = [37, 10, 88]
    write_document("bottle_start.json", [plane(1, p1, [1, 0, 0], 40, [0, 1, 0]),
                                         plane(2, [-20, 0, 65], [0, -1, 0], 180, [1, 0, 0])])
    s = Session()
    s.action("mode.sketch")
    s.stroke([r([0, 0, z]) for z in range(8, 127, 3)])  # the axis
    s.stroke(bezier([[18, 0, 6], [36, 0, 6], [34, 0, 40], [33, 0, 62], [32, 0, 84],
                     [10, 0, 84], [10, 0, 100], [10, 0, 116]], 60))  # the bottle's profile
    s.stroke(bezier([[2, 0, 132], [8, 0, 132], [8, 0, 120], [7, 0, 106]], 30))  # the plug's profile
    s.stroke(bezier([handle_start, [62, 0, 78], [64, 0, 38], [37, 0, 40]], 40))  # the handle's path
    s.select_plane(p1)
    # The handle's section, started at its top: a start within the pick radius of the path
    # would put the stroke on an auxiliary plane (seed 000 §3.1).
    s.stroke(circle(handle_start, [0, 0, 1], [0, 1, 0], 8, 64))
    s.action("stroke.useRecognized")
    s.action("mode.revolve")
    s.click([33.4, 0, 50])   # bottle profile
    s.click([0, 0, 60])      # axis
    s.click([8, 0, 126])     # plug profile
    s.click([0, 0, 90])      # axis
    s.action("mode.sweep")
    s.click([37, -8, 78])  # section
    s.click(bezier([handle_start, [62, 0, 78], [64, 0, 38], [37, 0, 40]], 41)[20])  # path
    s.action("mode.view")
    s.write("bottle.json")


def boat():
    # Five cross-section planes across the hull (normal +X), jacks above the sections.
    xs = [-70, -35, 0, 35, 70]
    half = [6, 26, 32, 28, 14]    # half beam at the gunwale
    depth = [24, 22, 20, 19, 16]  # keel depth below the gunwale (z = 40)
    planes = [plane(k + 1, [x, 0, 75], [1, 0, 0], 90, [0, 1, 0]) for k, x in enumerate(xs)]
    write_document("boat_start.json", planes)
    s = Session()
    for k, x in enumerate(xs):
        s.select_plane([x, 0, 75])
        w, d = half[k], depth[k]
        # a U from one gunwale round the keel to the other
        s.stroke(bezier([[x, -w, 40], [x, -w, 40 - d], [x, w, 40 - d], [x, w, 40]], 36))
    s.action("mode.loft")
    for k, x in enumerate(xs):
        w, d = half[k], depth[k]
        s.click(r([x, 0, 40 - 0.75 * d]))  # bottom of each section
    s.key("Return")
    s.action("mode.view")
    s.write("boat.json")


def fish():
    # One vertical plane (XZ) for the side view.
    write_document("fish_start.json", [plane(1, [0, 0, 100], [0, -1, 0], 200, [1, 0, 0])])
    s = Session()
    s.action("mode.sketch")
    top = bezier([[-60, 0, 42], [-50, 0, 72], [20, 0, 70], [40, 0, 43]], 40)
    bottom = bezier([[-60, 0, 38], [-45, 0, 14], [15, 0, 18], [40, 0, 37]], 40)
    tail_top = bezier([[47, 0, 43], [58, 0, 48], [66, 0, 62], [78, 0, 66]], 30)
    tail_bottom = bezier([[47, 0, 37], [58, 0, 32], [66, 0, 20], [78, 0, 14]], 30)
    for stroke in (top, bottom, tail_top, tail_bottom):
        s.stroke(stroke)
    s.action("mode.boundaryRotation")
    s.click(top[18])
    s.click(bottom[18])
    s.click(tail_top[20])
    s.click(tail_bottom[20])
    s.action("mode.view")
    s.write("fish.json")


def vase():
    # Two horizontal planes for the rails, their jacks well off the rails (a stroke pressed on a
    # jack would drag the plane instead).
    lower, upper = [0, 0, 10], [0, 0, 110]
    jack1, jack2 = [-40, -40, 10], [-40, -40, 110]
    write_document("vase_start.json", [plane(1, jack1, [0, 0, 1], 140, [1, 0, 0]),
                                       plane(2, jack2, [0, 0, 1], 140, [1, 0, 0])])
    s = Session()
    s.select_plane(jack1)
    s.stroke(circle(lower, [1, 0, 0], [0, 1, 0], 30, 56))
    s.action("stroke.useRecognized")
    s.select_plane(jack2)
    s.stroke(circle(upper, [1, 0, 0], [0, 1, 0], 20, 56))
    s.action("stroke.useRecognized")
    # The profile from rail 1 to rail 2: a stroke between two curves lies on the plane through
    # both points and the first curve's binormal (seed 000 §3.1), here the vertical XZ plane.
    profile = bezier([[30, 0, 10], [60, 0, 40], [10, 0, 80], [20, 0, 110]], 40)
    s.stroke(profile)
    s.action("mode.railRotation")
    s.click([-30, 0, 10])
    s.click([-20, 0, 110])
    s.click(profile[20])
    s.action("mode.view")
    s.write("vase.json")


def cubic(ctrl):
    return {"degree": 3, "knots": [0, 0, 0, 0, 1, 1, 1, 1], "points": ctrl}


def surfaces_drag():
    """20 curves' worth of work on one plane: four surfaces of four modes depend on its curves,
    and the session drags the plane by its jack (issue 6 §2's latency goal)."""
    # Plane 1 vertical (XZ, local x = X, local y = Z - 60); plane 2 small, facing +X, for the sweep's section.
    # Plane 1 vertical (XZ: local x = X, local y = Z - 60), its jack at the centre kept clear of
    # the surfaces (a press there must reach the dragger); plane 2 small, facing +Z, for the
    # sweep's section at the path's start.
    planes = [plane(1, [0, 0, 60], [0, -1, 0], 200, [1, 0, 0]), plane(2, [60, 8, 80], [0, 0, 1], 40, [1, 0, 0])]
    curves = [
        dict(cubic([[-90, 20], [-80, 60], [-60, 60], [-50, 20]]), id=3, plane=1),   # outline left
        dict(cubic([[-90, 17], [-80, -5], [-60, -5], [-50, 17]]), id=4, plane=1),   # outline right
        dict(cubic([[-25, -75], [-10, -60], [-25, -30], [-20, -10]]), id=5, plane=1),  # revolve profile
        dict(cubic([[-40, -80], [-40, -60], [-40, -30], [-40, -5]]), id=6, plane=1),  # revolve axis
        dict(cubic([[20, -70], [30, -50], [50, -80], [60, -60]]), id=7, plane=1),     # extrude profile
        dict(cubic([[60, 20], [85, 30], [85, 70], [60, 80]]), id=8, plane=1),          # sweep path
        {"degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
         "points": [[0, -3], [5, -3], [5, -8], [5, -13], [0, -13], [-5, -13], [-5, -8], [-5, -3], [0, -3]],
         "weights": [1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1, 0.7071067811865476, 1],
         "id": 9, "plane": 2},                                                           # sweep section
    ]
    # Plane 2's local (0, -8) is world (60, 0, 80), the path's start: the section is centred there.
    surfaces = [
        {"id": 10, "construction": {"mode": "boundary-rotation", "curves": [3, 4]}},
        {"id": 11, "construction": {"mode": "revolve", "curves": [5, 6], "angle": 360}},
        {"id": 12, "construction": {"mode": "extrude", "curves": [7], "direction": [0, 0, 30]}},
        {"id": 13, "construction": {"mode": "sweep", "curves": [9, 8]}},
    ]
    write_document("surfaces_drag_start.json", planes, curves, surfaces)
    s = Session()
    s.action("mode.sketch")
    # The jack's translator plate at plane 1's origin, dragged in 60 steps.
    start, end = [0, 0, 60], [30, 0, 80]
    pts = [r([start[k] + (end[k] - start[k]) * i / 60 for k in range(3)]) for i in range(61)]
    s.stroke(pts, dt=10)
    s.write("surfaces_drag.json")
    # The same drag with every surface coloured by Gaussian curvature (View > Surface display):
    # recoloured at every event; the model it leaves is the plain drag's.
    s = Session()
    s.action("view.surfaceGaussian")
    s.action("mode.sketch")
    s.stroke(pts, dt=10)
    s.write("surfaces_drag_gaussian.json")


def extrude():
    """Thesis mode 3 on the default scene: a stroke on the default plane (y = 95, facing -Y), then
    extrude mode: the curve is pressed and pulled 40 mm towards the viewer, the surface following
    the pointer; then undo and redo of that one step."""
    s = Session()
    s.action("mode.sketch")
    wave = [r([-40 + 80 * i / 39, 95, 50 + 10 * math.sin(2 * math.pi * i / 39)]) for i in range(40)]
    s.stroke(wave)
    s.action("mode.extrude")
    grab = wave[10]
    s.stroke([r([grab[0], grab[1] - 40 * i / 30, grab[2]]) for i in range(31)], dt=10)
    s.key("Ctrl+Z")
    s.key("Ctrl+Shift+Z")
    s.action("mode.view")
    s.write("extrude.json")


def pin_pull():
    """A stroke on the default plane, pinned with Shift+click at a quarter of its length, then
    pulled 15 mm up at three quarters: the pin holds, the pulled point follows (thesis §6.1)."""
    s = Session()
    s.action("mode.sketch")
    wave = [r([-40 + 80 * i / 39, 95, 50 + 10 * math.sin(2 * math.pi * i / 39)]) for i in range(40)]
    s.stroke(wave)
    s.action("mode.pull")
    s.events.append({"type": "press", "at": wave[10], "button": "left", "modifiers": ["shift"], "t": s.tick(40)})
    s.events.append({"type": "release", "at": wave[10], "button": "left", "modifiers": ["shift"], "t": s.tick(10)})
    grab = wave[30]
    s.stroke([r([grab[0], grab[1], grab[2] + 15 * i / 20]) for i in range(21)], dt=10)
    s.action("mode.view")
    s.write("pin_pull.json")


def pull_circle():
    """A circle on the default plane, regularized to the exact rational circle, then pulled 12 mm
    outwards at its top and over-sketched at its bottom: both edits keep it rational and closed."""
    s = Session()
    s.action("mode.sketch")
    centre = [0, 95, 55]
    s.stroke(circle(centre, [1, 0, 0], [0, 0, 1], 30, 64))
    s.action("stroke.useRecognized")
    s.action("mode.pull")
    s.stroke([r([0, 95, 85 + 12 * i / 20]) for i in range(21)], dt=10)
    s.action("mode.oversketch")
    s.stroke([r([-20 + 40 * i / 29, 95, 25 - 6 * math.sin(math.pi * i / 29)]) for i in range(30)])
    s.action("mode.view")
    s.write("pull_circle.json")


def networks():
    """Curve networks on the default plane (y = 95): a Gordon surface through two waves and two
    strokes crossing them (U: one family, Enter, the other, Enter), and a mesh filling one closed
    stroke (M: the loop, Enter)."""
    s = Session()
    s.action("mode.sketch")
    # Kept left of the plane's jack (at its centre, (0, 95, 60)): a press there would drag the plane.
    waves = [[r([-55 + 40 * i / 29, 95, z + 3 * math.sin(2 * math.pi * i / 29)]) for i in range(30)] for z in (70, 95)]
    lines = [[r([x + 2 * math.sin(math.pi * i / 29), 95, 105 - 43 * i / 29]) for i in range(30)] for x in (-50, -25)]
    for stroke in waves + lines:
        s.stroke(stroke)
    loop = circle([30, 95, 45], [1, 0, 0], [0, 0, 1], 15, 48)
    s.stroke(loop)
    s.action("mode.gordon")
    for stroke in waves:
        s.click(stroke[12])
    s.key("Return")
    for stroke in lines:
        s.click(stroke[20])
    s.key("Return")
    s.action("mode.network")
    s.click(loop[10])
    s.key("Return")
    s.action("mode.view")
    s.write("networks.json")


def cap_session():
    """The start of the cap sessions on sculpt_start.json: the sheet selected, Sculpt mode, and the
    target arch drawn in plane 1 from one edge of the sheet to the other, 30 mm high."""
    s = Session()
    s.action("mode.select")
    s.click([45, 45, 0])  # the sheet: select it
    s.action("mode.sculpt")
    s.stroke([r([-60 + 120 * i / 40, 0, 30 * math.sin(math.pi * i / 40)]) for i in range(41)])
    return s


def sculpt_cap():
    """Thesis Fig. 6-8 and §6.4: a flat sheet deformed by one target curve into a cap, then the
    target's plane dragged by its jack: the sculpted surface follows live (the sail of Fig. 6-16)."""
    # Plane 1 vertical (XZ: local x = X, local y = Z - 60) across the sheet's middle; its jack at
    # (0, 0, 60) stays clear of the sheet and the arch. The sheet: a flat bicubic 8 x 8 net over
    # [-70, 70]^2 at z = 0.
    planes = [plane(1, [0, 0, 60], [0, -1, 0], 160, [1, 0, 0])]
    knots = [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5]
    net = [[-70 + 20 * i, -70 + 20 * j, 0] for i in range(8) for j in range(8)]
    sheet = {"id": 2, "degreeU": 3, "degreeV": 3, "knotsU": knots, "knotsV": knots, "countU": 8, "countV": 8,
             "points": net}
    write_document("sculpt_start.json", planes, (), [sheet])
    s = cap_session()
    # Drag plane 1 by its jack 25 mm along -Y in 30 steps: the cap's crest follows.
    s.action("mode.view")
    s.action("mode.select")
    start, end = [0, 0, 60], [0, -25, 60]
    s.stroke([r([start[k] + (end[k] - start[k]) * i / 30 for k in range(3)]) for i in range(31)], dt=12)
    s.write("sculpt_cap.json")


def sculpt_tangent():
    """Thesis Fig. 6-4 d: the sheet sculpted by the cap's arch, then Sculpt > Hold the tangent across
    the last target (Alt+G): along the arch the surface's cross tangent keeps the direction it has at
    the arch's middle."""
    s = cap_session()
    s.action("sculpt.holdTangent")
    s.write("sculpt_tangent.json")
def fish_fins():
    """Thesis Fig. 6-14 (the fish's fins): the fish of fish() as a start document, its body selected,
    Sculpt mode, and one target curve drawn over its back: the dorsal fin is pulled out of the body.
    The tail is fish()'s boundary rotation of its outlines on the side plane. The body is a bicubic
    net on ellipses between fish()'s body outlines, 30 x 33 points: a sculpt's change falls off
    over a few rings of control points (solvers/deformation, force objective), and the boundary
    rotation's 9 points around would carry the belly up with the fin."""
    # The side plane (XZ, y = 0): local x = X - 10, local y = Z - 100; its jack above the fin.
    o = [10, 0, 100]
    planes = [plane(1, o, [0, -1, 0], 160, [1, 0, 0])]

    def local(ctrl):
        return [[p[0] - o[0], p[1] - o[2]] for p in ctrl]
    curves = [dict(cubic(local(c)), id=k + 2, plane=1) for k, c in enumerate((FISH_TAIL_TOP, FISH_TAIL_BOTTOM))]
    nu, nv = 30, 33
    net = []
    for i in range(nu):
        x = -59 + 99 * i / (nu - 1)
        top, bottom = bezier_z(FISH_TOP, x), bezier_z(FISH_BOTTOM, x)
        centre, half = 0.5 * (top + bottom), 0.5 * (top - bottom)
        for j in range(nv):
            a = -math.pi + 2 * math.pi * j / (nv - 1)  # 0 on the back, +-pi on the belly
            net.append(r([x, -FISH_WIDTH * half * math.sin(a), centre + half * math.cos(a)]))
    body = {"id": 4, "degreeU": 3, "degreeV": 3, "knotsU": uniform_knots(nu), "knotsV": uniform_knots(nv),
            "countU": nu, "countV": nv, "points": net}
    surfaces = [body, {"id": 5, "construction": {"mode": "boundary-rotation", "curves": [2, 3]}}]
    write_document("fish_fins_start.json", planes, curves, surfaces)
    s = Session()
    s.action("mode.select")
    s.click([-10, -12, 44])  # the body's flank facing the viewer: select it
    s.action("mode.sculpt")
    s.stroke([[x, 0, z] for x, z in fish_fin()])
    s.action("mode.view")
    s.turn_view(170, 20)  # the fish from its side, for the picture
    s.write("fish_fins.json")


def uniform_knots(n, degree=3):
    return [0] * degree + list(range(n - degree + 1)) + [n - degree] * degree


def bezier_z(ctrl, x):
    """z of the planar Bezier curve ctrl ([x, z] points, x increasing) at x."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if bezier_at(ctrl, mid)[0] < x:
            lo = mid
        else:
            hi = mid
    return bezier_at(ctrl, lo)[1]


FISH_TOP = [[-60, 42], [-50, 72], [20, 70], [40, 43]]
FISH_BOTTOM = [[-60, 38], [-45, 14], [15, 18], [40, 37]]
FISH_TAIL_TOP = [[47, 43], [58, 48], [66, 62], [78, 66]]
FISH_TAIL_BOTTOM = [[47, 37], [58, 32], [66, 20], [78, 14]]
FISH_WIDTH = 0.6  # the body's half width, relative to its half height


def fish_fin(x0=-44, x1=6, lift=2, height=20, n=40):
    """The dorsal fin's target in the side plane, [x, z]: `lift` above the back at both ends and
    `height` more in the middle (z = back(x) + lift + height sin(pi t))."""
    out = []
    for i in range(n):
        t = i / (n - 1)
        x = x0 + (x1 - x0) * t
        out.append(r([x, bezier_z(FISH_TOP, x) + lift + height * math.sin(math.pi * t)]))
    return out


def bezier_at(ctrl, t):
    pts = [list(c) for c in ctrl]
    while len(pts) > 1:
        pts = [[(1 - t) * a + t * b for a, b in zip(p, q)] for p, q in zip(pts, pts[1:])]
    return pts[0]


def penguin():
    """Thesis Fig. 6-14 (the penguin's mouth): a penguin's body and head, a bicubic net on circles
    about the vertical axis (a revolved shape, 32 x 33 points: the revolve mode's exact circles
    have 9 points around, and a sculpt's change falls off over a few rings of them: the whole
    body would lean towards the beak), selected; Sculpt mode, and one target curve drawn in front
    of the face on the vertical plane through the axis: the beak is pulled out of the head."""
    # Plane 1 vertical (XZ, y = 0): local x = X, local y = Z - 45; its jack inside the body.
    o = [0, 0, 45]
    planes = [plane(1, o, [0, -1, 0], 150, [1, 0, 0])]
    nu, nv = 32, 33
    net = []
    for i in range(nu):
        f = i / (nu - 1) * (len(PENGUIN_PROFILE) - 1)
        k = min(int(f), len(PENGUIN_PROFILE) - 2)
        f -= k
        radius, z = [(1 - f) * a + f * b for a, b in zip(PENGUIN_PROFILE[k], PENGUIN_PROFILE[k + 1])]
        for j in range(nv):
            a = -math.pi + 2 * math.pi * j / (nv - 1)  # 0 at the front (+X), +-pi at the back
            net.append(r([radius * math.cos(a), radius * math.sin(a), z]))
    body = {"id": 2, "degreeU": 3, "degreeV": 3, "knotsU": uniform_knots(nu), "knotsV": uniform_knots(nv),
            "countU": nu, "countV": nv, "points": net}
    write_document("penguin_start.json", planes, (), [body])
    s = Session()
    s.action("mode.select")
    s.click([8, -24, 30])  # the front of the body, facing the viewer: select it
    s.action("mode.sculpt")
    s.stroke(bezier([[x, 0, z] for x, z in PENGUIN_BEAK], 40))
    s.action("mode.view")
    s.turn_view(130, 0)  # the head from its side, the beak in profile, for the picture
    s.write("penguin.json")


# The body's profile, [radius, z] from the feet to the top of the head (the net's rows follow it).
PENGUIN_PROFILE = [[30, 0], [34, 14], [31, 30], [24, 44], [21, 54], [25, 66], [24, 78], [16, 90], [4, 97], [0.5, 98]]
# The beak's target (Bezier control points in plane 1, [x, z]): from the face above the mouth out to
# the tip and back below it.
PENGUIN_BEAK = [[22, 88], [38, 80], [44, 68], [22, 52]]


def sail():
    """Thesis Fig. 6-16 and §6.4: a sail above the boat's hull with two target curves on two
    planes across it (one sculpt, two targets), then each plane dragged by its jack in turn: the
    sail follows live and meets both moved targets."""
    # The hull of boat(): its five sections as world curves (no planes) lofted.
    xs = [-70, -35, 0, 35, 70]
    half = [6, 26, 32, 28, 14]
    depth = [24, 22, 20, 19, 16]
    sections = []
    for k, x in enumerate(xs):
        w, d = half[k], depth[k]
        sections.append(dict(cubic([[x, -w, 40], [x, -w, 40 - d], [x, w, 40 - d], [x, w, 40]]), id=10 + k))
    hull = {"id": 15, "construction": {"mode": "loft", "curves": [10 + k for k in range(5)]}}
    # The sail: a flat bicubic 12 x 12 net in y = 0 between the mast (x = -40) and the leech, from
    # the boom (z = 45) to the head (z = 150).
    n = 12
    knots = uniform_knots(n)
    net = []
    for i in range(n):
        for j in range(n):
            s_, t = i / (n - 1), j / (n - 1)
            net.append(r([(1 - s_) * -40 + s_ * (40 - 60 * t), 0, 45 + 105 * t]))
    sheet = {"id": 3, "degreeU": 3, "degreeV": 3, "knotsU": knots, "knotsV": knots, "countU": n, "countV": n,
             "points": net}
    # Planes A and B: vertical, across the sail (YZ: normal +X, local x = Y, local y = Z), their
    # jacks in front of the sail.
    planes = [plane(1, SAIL_JACKS[0], [1, 0, 0], 140, [0, 1, 0]), plane(2, SAIL_JACKS[1], [1, 0, 0], 140, [0, 1, 0])]
    write_document("sail_start.json", planes, sections, [sheet, hull])
    s = Session()
    s.action("mode.select")
    for k in range(2):
        s.click(SAIL_JACKS[k])     # plane k: the active plane
        s.click(SAIL_CLICKS[k])    # the sail (then the sculpt): what is sculpted
        s.action("mode.sculpt")
        x, z0, z1, bulge = SAIL_TARGETS[k]
        s.stroke([r([x, bulge * math.sin(math.pi * i / 40), z0 + (z1 - z0) * i / 40]) for i in range(41)])
        s.action("mode.select")
    # Drag plane A by its jack, then plane B: the sail follows each.
    for k in range(2):
        start = SAIL_JACKS[k]
        end = [start[0], start[1] + SAIL_DRAGS[k], start[2]]
        s.stroke([r([start[c] + (end[c] - start[c]) * i / 30 for c in range(3)]) for i in range(31)], dt=12)
    s.action("mode.view")
    s.turn_view(220, 90)  # from above the stern's side: the sail's camber and both planes, for the picture
    s.write("sail.json")


# The sail's planes (jack positions: high and in front, so that no jack hides where a stroke or a
# click begins), where the session clicks the sail to select it, the targets
# ([x, z from, z to, bulge in +y]: y = bulge * sin(pi t)) and the drags along +Y (mm).
SAIL_JACKS = [[-20, -30, 120], [10, -30, 120]]
SAIL_CLICKS = [[0, 0, 60], [0, 0, 60]]
SAIL_TARGETS = [[-20, 62, 145, 14], [10, 62, 92, 10]]
SAIL_DRAGS = [12, 10]


def sculpt_18x135():
    """Table 6-2's largest net in the GUI (issue 13 §3): a long, gently curved strip with an 18 x 135
    bicubic control net (18 across, in Y; 135 along, in X), sculpted by one target arch on plane 1
    (facing +X, at x = -100, across the strip); the session drags that plane by its jack 150 mm
    along the strip in 60 moves, the sculpted bump following at every event."""
    # Plane 1: normal +X, local x = world Y, local y = world Z - 70; its jack at (-100, 0, 70) clear
    # of the strip (at most 20 high) and of the arch (about 33 high).
    planes = [plane(1, [-100, 0, 70], [1, 0, 0], 120, [0, 1, 0])]
    cu, cv = 18, 135
    knots_u = [0] * 4 + list(range(1, cu - 3)) + [cu - 3] * 4
    knots_v = [0] * 4 + list(range(1, cv - 3)) + [cv - 3] * 4
    net = []
    for i in range(cu):
        y = -40 + 80 * i / (cu - 1)
        for j in range(cv):
            x = -200 + 400 * j / (cv - 1)
            net.append(r([x, y, 20 * (1 - (x / 200) ** 2) - 0.002 * y * y]))
    strip = {"id": 2, "degreeU": 3, "degreeV": 3, "knotsU": knots_u, "knotsV": knots_v, "countU": cu,
             "countV": cv, "points": net}
    # The target (curve 3, in plane 1's frame): a cubic arch across the strip, its ends near the
    # surface (z about 12.5 at y = +-35), its crest about 33 mm high.
    arch = dict(cubic([[-35, -57.5], [-15, -30], [15, -30], [35, -57.5]]), id=3, plane=1)
    sculpt = {"id": 4, "construction": {"mode": "sculpt", "base": 2, "curves": [3]}}
    write_document("sculpt_18x135.json", planes, [arch], [strip, sculpt], compact=True)
    s = Session()
    s.action("mode.select")
    start, end = [-100, 0, 70], [50, 0, 70]
    s.stroke([r([start[k] + (end[k] - start[k]) * i / 60 for k in range(3)]) for i in range(61)], dt=12)
    s.write("sculpt_18x135_drag.json")


def sculpt_sheet():
    """The flat bicubic 8 x 8 sheet of the sculpt sessions, over [-70, 70]^2 at z = 0 (id 2)."""
    knots = [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5]
    net = [[-70 + 20 * i, -70 + 20 * j, 0] for i in range(8) for j in range(8)]
    return {"id": 2, "degreeU": 3, "degreeV": 3, "knotsU": knots, "knotsV": knots, "countU": 8, "countV": 8,
            "points": net}


def jack_drag(s, start, end, steps=25, dt=12):
    """A press on a handle's jack at `start`, moved in `steps` to `end`, released."""
    s.stroke([r([start[k] + (end[k] - start[k]) * i / steps for k in range(3)]) for i in range(steps + 1)], dt=dt)


def sculpt_handles():
    """Thesis Fig. 6-5 c-d: a point handle dropped on the sheet (Sculpt mode, Alt+H, a click), its
    jack dragged up 20 mm, then its ball turned; the sculpt passes through the point. The second
    session is the same followed by two undos (the turn, then the drag): the sheet is flat again."""
    handle = [-10, 20, 0]
    for undo in (False, True):
        s = Session()
        s.action("mode.select")
        s.click([45, 45, 0])  # the sheet (2): select it
        s.action("mode.sculpt")
        s.action("sculpt.handle")
        s.click(handle)
        top = [handle[0], handle[1], 20]
        jack_drag(s, handle, top)
        # The turn: a press on the end of the jack's x axis (its rotator's lines reach 1.5 jack
        # units, its translator's 1.1; the jack is 0.04 of the sheet's 198 mm diagonal per unit),
        # carried 30 degrees up around the point.
        arm = 1.35 * 0.04 * math.hypot(140, 140)
        turn = [r([top[0] + arm * math.cos(math.radians(a)), top[1], top[2] + arm * math.sin(math.radians(a))])
                for a in range(0, 31, 2)]
        s.stroke(turn, dt=12)
        if undo:
            s.key("Ctrl+Z")
            s.key("Ctrl+Z")
        s.write("sculpt_handle_undo.json" if undo else "sculpt_handle.json")


def sculpt_bump():
    """Thesis Figs. 6-9 and 6-13: a local bump. A bound drawn around the sheet's middle (Alt+B, a
    closed loop on the horizontal plane 1 through the sheet), a handle dropped in its centre (Alt+H)
    and pulled 25 mm up by its jack: only the control points inside the bound move."""
    # Plane 1 horizontal through the sheet (z = 0), small and in a corner: its jack stays clear of
    # the sheet; strokes meet its (unbounded) plane anywhere.
    planes = [plane(1, [-95, -95, 0], [0, 0, 1], 30, [1, 0, 0])]
    write_document("sculpt_bump_start.json", planes, (), [sculpt_sheet()])
    s = Session()
    s.action("mode.select")
    s.click([45, 45, 0])
    s.action("mode.sculpt")
    s.action("sculpt.bound")
    s.stroke(circle([0, 0, 0], [1, 0, 0], [0, 1, 0], 38, 64))
    s.action("sculpt.handle")
    s.click([0, 0, 0])
    jack_drag(s, [0, 0, 0], [0, 0, 25])
    s.write("sculpt_bump.json")


def sculpt_constraints():
    """Thesis Fig. 6-7 and Table 6-1's distance: on the sheet, a handle dropped at its middle, a
    control point blocked (Alt+K, a click at control point (4, 4), (10, 10, 0)), two points picked
    for a distance (Alt+D, two clicks 40 mm apart), then the handle's jack pulled 20 mm up: the
    blocked point stays and the two points stay 40 mm apart."""
    s = Session()
    s.action("mode.select")
    s.click([45, 45, 0])
    s.action("mode.sculpt")
    s.action("sculpt.handle")
    s.click([-10, -10, 0])
    s.action("sculpt.block")
    s.click([10, 10, 0])
    s.action("sculpt.distance")
    s.click([-30, -50, 0])
    s.click([10, -50, 0])
    s.action("sculpt.handle")
    jack_drag(s, [-10, -10, 0], [-10, -10, 20])
    s.write("sculpt_constraints.json")



def sculpt_oversketch():
    """Issue 13 §1: the cap's target arch over-sketched (Over-sketch mode, O): its middle redrawn
    10 mm higher, and the sculpt follows the changed target."""
    s = cap_session()
    s.action("mode.oversketch")

    def height(x):
        return 30 * math.sin(math.pi * (x + 60) / 120)
    over = [r([x, 0, height(x) + 10 * math.sin(math.pi * (x + 25) / 50)]) for x in [-25 + 50 * i / 30 for i in range(31)]]
    s.stroke(over)
    s.write("sculpt_oversketch.json")


def bspline_basis(knots, degree, t):
    """All basis functions N_i,degree(t) (Cox-de Boor); t at the domain's end belongs to the last span."""
    n = len(knots) - degree - 1
    if t >= knots[n]:
        return [1.0 if i == n - 1 else 0.0 for i in range(n)]
    N = [1.0 if knots[i] <= t < knots[i + 1] else 0.0 for i in range(len(knots) - 1)]
    for p in range(1, degree + 1):
        N = [(((t - knots[i]) / (knots[i + p] - knots[i]) * N[i]) if knots[i + p] > knots[i] else 0.0) +
             (((knots[i + p + 1] - t) / (knots[i + p + 1] - knots[i + 1]) * N[i + 1]) if knots[i + p + 1] > knots[i + 1] else 0.0)
             for i in range(len(N) - 1)]
    return N


def surface_point(srf, u, v):
    """S(u, v) at fractions u, v in [0, 1] of the domain."""
    u = srf["knotsU"][srf["degreeU"]] + u * (srf["knotsU"][srf["countU"]] - srf["knotsU"][srf["degreeU"]])
    v = srf["knotsV"][srf["degreeV"]] + v * (srf["knotsV"][srf["countV"]] - srf["knotsV"][srf["degreeV"]])
    Nu = bspline_basis(srf["knotsU"], srf["degreeU"], u)
    Nv = bspline_basis(srf["knotsV"], srf["degreeV"], v)
    nv = srf["countV"]
    return [sum(Nu[i] * Nv[j] * srf["points"][i * nv + j][k] for i in range(srf["countU"]) for j in range(nv) if Nu[i] and Nv[j])
            for k in range(3)]


def jug_surface():
    """A jug's body as a free-form bicubic surface (no recipe: a static surface), revolved-looking:
    u runs around (13 control points on a 12-gon, the first repeated last), v runs up (6 rows:
    foot, belly, shoulder, neck, rim); the rim is the u-curve at v = 1. The front (u = 0.5) faces
    the window's default camera (ui/main_window.cpp looks along (-1, 1.6, -0.9)), the seam is at
    the back."""
    rows = [(0, 30), (18, 42), (45, 46), (70, 34), (88, 27), (100, 31)]  # (height, radius)
    count_u, count_v = 13, len(rows)
    net = []
    for i in range(count_u):
        a = math.atan2(-1.6, 1.0) + math.pi + 2 * math.pi * i / (count_u - 1)
        for z, radius in rows:
            net.append(r([radius * math.cos(a), radius * math.sin(a), z]))
    return {"id": 1, "degreeU": 3, "degreeV": 3, "knotsU": uniform_knots(count_u), "knotsV": uniform_knots(count_v),
            "countU": count_u, "countV": count_v, "points": net}


def jug_mouth():
    """Seed 001 Fig. 10, the jug's mouth: the jug selected, Sculpt mode's Re-sketch tool (Alt+R); a
    marking along the rim's front (just below it) picks the rim, the strip's rulings turned once
    (Alt+A: across the rim, the jug's wall continued upwards), and a stroke over the strip raises
    the lip at the front by up to 14 mm, the spout. A second session undoes it (Ctrl+Z)."""
    jug = jug_surface()
    write_document("jug_start.json", [], (), [jug])
    s = Session()
    s.action("mode.select")
    s.click(r(surface_point(jug, 0.5, 0.45)))  # the belly's front
    s.action("mode.sculpt")
    s.action("sculpt.resketch")
    s.stroke([r(surface_point(jug, 0.36 + 0.28 * k / 30, 0.96)) for k in range(31)])
    s.action("sculpt.resketchRulings")
    # Over the strip: the rim's point plus a lift along the wall's direction at the rim.
    lift = []
    for k in range(41):
        u = 0.33 + 0.34 * k / 40
        top, below = surface_point(jug, u, 1.0), surface_point(jug, u, 0.98)
        d = [a - b for a, b in zip(top, below)]
        n = math.sqrt(sum(c * c for c in d))
        h = 14 * math.sin(math.pi * k / 40) ** 2
        lift.append(r([top[c] + h * d[c] / n for c in range(3)]))
    s.stroke(lift)
    # Alt+R again starts over: the strip goes, the jug's new mouth shows.
    s.action("sculpt.resketch")
    s.write("jug_mouth.json")
    # The same, undone (one step): the jug as it was.
    s.key("Ctrl+Z")
    s.write("jug_mouth_undo.json")



def incidence_dome():
    """Seed 000 Figs. 2 and 8 in the window (issue 14 §3): the dome. Rim A, a circle of radius 50 on
    the ground (plane 1), is fixed (Ctrl+Shift+F); Interpolation (I) through A and the arch B (plane
    2, y = 0, 30 mm high) makes a surface that the incidence solve bends through both; then, drawing
    onto it, the arch C is added on plane 3 (x = 0) across B; last, B's plane is dragged 8 mm along
    -Y by its jack and the dome follows live (the --stats of issue 14 §4); B's ends then leave the
    rim by about 0.7 mm, a conflict the solve settles softly."""
    # Plane 1: the ground, its jack at (-80, -80, 0) well off the rim (local = world + (80, 80)), so
    # that no stroke or click near the rim lands on it. Plane 2:
    # normal -Y, local x = X, local y = Z - 60, its jack at (0, 0, 60) over the dome. Plane 3:
    # normal +X, local x = Y, local y = Z - 95, its jack at (0, 0, 95).
    planes = [plane(1, [-80, -80, 0], [0, 0, 1], 320, [1, 0, 0]),
              plane(2, [0, 0, 60], [0, -1, 0], 160, [1, 0, 0]),
              plane(3, [0, 0, 95], [1, 0, 0], 160, [0, 1, 0])]
    # A: a closed uniform cubic B-spline with 12 control points on the circle of radius 50 (the
    # kernel's closed curves: "closed", the first three points repeated, unwrapped uniform knots).
    # At each control point's angle the curve passes at radius 50 (4 + 2 cos 30°) / 6 = 47.77.
    n = 12
    ring = [[50 * math.cos(2 * math.pi * k / n) + 80, 50 * math.sin(2 * math.pi * k / n) + 80, 0] for k in range(n)]
    pts = ring + ring[:3]
    rim = {"id": 4, "plane": 1, "degree": 3, "closed": True, "knots": list(range(len(pts) + 4)),
           "points": [r(p) for p in pts]}
    on_rim = 50 * (4 + 2 * math.cos(math.pi / 6)) / 6
    # B: an arch 30 mm high whose ends sit on the rim (at radius on_rim, where the rim crosses y = 0).
    arch = dict(cubic([r([-on_rim, -60]), [-20, -20], [20, -20], r([on_rim, -60])]), id=5, plane=2)
    write_document("incidence_dome.json", planes, [rim, arch])
    s = Session()
    s.action("mode.select")
    s.click(r([on_rim * math.cos(-math.pi / 6), on_rim * math.sin(-math.pi / 6), 0]))  # the rim, clear of plane 1's jack: select it
    s.key("Ctrl+Shift+F")   # fix it: the surface meets it exactly
    s.action("mode.incidence")
    s.click(r([on_rim * math.cos(-math.pi / 3), on_rim * math.sin(-math.pi / 3), 0]))  # A
    s.click([0, 0, 30])      # B's crest
    s.key("Return")
    s.action("mode.select")
    s.click([0, 0, 95])      # plane 3's jack: the next curve goes there
    s.action("mode.incidence")
    # C starts and ends a few millimetres inside the rim: a stroke started on a curve would go onto
    # the plane along that curve's tangent (seed 000 §3.1, case 1), not onto plane 3.
    # Its crest meets B's (30 mm over the centre, where the two cross: they tie there).
    s.stroke([r([0, -44 + 88 * i / 40, 3 + 27 * math.sin(math.pi * i / 40)]) for i in range(41)])
    s.write("incidence_dome.json")
    s.action("mode.select")
    start, end = [0, 0, 60], [0, -8, 60]
    s.stroke([r([start[k] + (end[k] - start[k]) * i / 30 for k in range(3)]) for i in range(31)], dt=12)
    s.write("incidence_dome_drag.json")



def incidence_free():
    """Issue 14 §3, Sculpting on a surface built from curves: a fill of four cubic boundaries on the
    ground is selected, I, plane 2's jack clicked (the curve goes there), and an arch drawn across
    the fill: the fill becomes a free-form surface (refined, its four boundaries on it) that passes
    through the arch. incidence_free_undo.json adds Ctrl+Z, which gives the fill back."""
    # Plane 1: the ground, its square (and jack) at (-150, -150) away from the fill, which lies
    # over [-50, 50]^2 (local = world + 150); a click on the fill hits the fill alone. Plane 2:
    # vertical along X through y = 0, local y = Z - 60, its jack at (0, 0, 60).
    planes = [plane(1, [-150, -150, 0], [0, 0, 1], 100, [1, 0, 0]),
              plane(2, [0, 0, 60], [0, -1, 0], 160, [1, 0, 0])]

    def side(a, b, cid):
        pts = [[a[k] + (b[k] - a[k]) * i / 3 + 150 for k in range(2)] for i in range(4)]
        return dict(cubic([r(p) for p in pts]), id=cid, plane=1)
    corners = [[-50, -50], [50, -50], [50, 50], [-50, 50]]
    sides = [side(corners[k], corners[(k + 1) % 4], 3 + k) for k in range(4)]
    fill = {"id": 7, "construction": {"mode": "fill", "curves": [3, 4, 5, 6]}}
    write_document("incidence_free_start.json", planes, sides, [fill])
    s = Session()
    s.action("mode.select")
    s.click([20, 20, 0])     # the fill
    s.action("mode.incidence")
    s.action("mode.select")
    s.click([0, 0, 60])      # plane 2's jack: the curve goes there
    s.action("mode.incidence")
    s.stroke([r([-40 + 80 * i / 40, 0, 2 + 25 * math.sin(math.pi * i / 40)]) for i in range(41)])
    s.write("incidence_free.json")
    s.key("Ctrl+Z")
    s.write("incidence_free_undo.json")


def aesthetics():
    """The curvature comb: an S-shaped wave (one period of a sine, so its curvature takes both signs)
    sketched on the default plane, its comb shown (Shift+C), the view zoomed in, then the wave pulled
    12 mm up at three quarters of its length: the comb follows the drag. (View > Aesthetics is left out: at 800 x 600
    the docks do not fit beside the viewport and are hidden; opening one would shrink the viewport.)"""
    s = Session()
    s.action("mode.sketch")
    wave = [r([-45 + 90 * i / 39, 95, 55 + 14 * math.sin(2 * math.pi * i / 39)]) for i in range(40)]
    s.stroke(wave)
    s.action("view.curvatureComb")
    # Closer (Alt+right-drag upwards zooms in), so that the screenshot shows the teeth.
    s.events.append({"type": "press", "x": 480, "y": 250, "button": "right", "modifiers": ["alt"], "t": s.tick(50)})
    for k in range(1, 21):
        s.events.append({"type": "move", "x": 480, "y": 250 - 6 * k, "button": "right", "modifiers": ["alt"], "t": s.tick(15)})
    s.events.append({"type": "release", "x": 480, "y": 130, "button": "right", "modifiers": ["alt"], "t": s.tick(300)})
    s.action("mode.pull")
    grab = wave[30]
    s.stroke([r([grab[0], grab[1], grab[2] + 12 * i / 20]) for i in range(21)], dt=10)
    s.action("mode.view")
    s.write("aesthetics.json")


if __name__ == "__main__":
    aesthetics()
    jug_mouth()
    incidence_free()
    incidence_dome()
    sculpt_oversketch()
    sculpt_handles()
    sculpt_bump()
    sculpt_constraints()
    sculpt_18x135()
    sculpt_tangent()
    sculpt_cap()
    fish_fins()
    penguin()
    sail()
    networks()
    pull_circle()
    pin_pull()
    extrude()
    bottle()
    boat()
    fish()
    vase()
    surfaces_drag()
