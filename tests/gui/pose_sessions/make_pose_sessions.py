#!/usr/bin/env python3
"""Writes the 6-DOF replay sessions of the GUI tests (tests/gui/CMakeLists.txt, pose_replay_test.cpp):
pose events (../shared/interfaces.md, "6-DOF input") of a tracked pointer sampled at 100 Hz, on the
default scene (data/default_scene.json: its plane at (0, 95, 60), normal -y, 120 mm; a space curve;
a surface spanning x -80..80, y -90..30 at z 7..45). Positions in mm, orientations [x, y, z, w].

  pose_helix.json   two turns of a helix drawn in space (the view pose frames it first)
  pose_bridge.json  two space curves, then a stroke from one to the other whose ends stop 3 mm short
                    of them (within the 5 mm snapping distance)
  pose_plane.json   the second hand carries the plane to a new place and turns it while a mouse
                    stroke and two pointer strokes (one while the plane turns) are drawn on it, then
                    lets go; one more pointer stroke in the air
  pose_plane_undo.json  the same, then two undos (the air stroke; the whole carry, one step)
  pose_helix_undo.json  the helix, then one undo (the space curve is one undo step)
  pose_live.json    the helix with the trigger still held at the end: the live polyline, no curve yet
  pose_oversketch.json  in Over-sketch mode, a pointer stroke over the middle of the default scene's
                    space curve, raised 4 mm along z: the curve follows it, its ends kept
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DT = 10  # ms between tracker samples (100 Hz)
IDENTITY = [0.0, 0.0, 0.0, 1.0]


def pose(device, p, q=IDENTITY, buttons=(), t=0):
    return {"type": "pose", "device": device, "position": [round(c, 6) for c in p],
            "orientation": [round(c, 12) for c in q], "buttons": list(buttons), "t": t}


def pointer_stroke(points, t0):
    """Trigger held along points, then one pose with the trigger up (the stroke ends)."""
    events = [pose("pointer", p, buttons=["trigger"], t=t0 + DT * i) for i, p in enumerate(points)]
    t = t0 + DT * len(points)
    events.append(pose("pointer", points[-1], t=t))
    return events, t + DT


def axis_angle(axis, angle):
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(angle / 2) / n
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2)]


def rotate(q, v):
    x, y, z, w = q
    # v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
    ux = (y * v[2] - z * v[1], z * v[0] - x * v[2], x * v[1] - y * v[0])
    uux = (y * ux[2] - z * ux[1], z * ux[0] - x * ux[2], x * ux[1] - y * ux[0])
    return [v[k] + 2 * w * ux[k] + 2 * uux[k] for k in range(3)]


def write(name, events):
    with open(os.path.join(HERE, name), "w") as f:
        json.dump({"size": [800, 600], "events": events}, f, indent=None, separators=(",", ":"))
        f.write("\n")


def helix():
    # The view device grips and pulls back 60 mm so that the whole helix is in the picture.
    events = [pose("view", [0, 0, 0], buttons=["grip"], t=0)]
    for i in range(1, 11):
        events.append(pose("view", [0, -6 * i, 4 * i], buttons=["grip"], t=DT * i))
    events.append(pose("view", [0, -60, 40], t=DT * 11))
    # Radius 30, 25 mm per turn, two turns about the vertical through (0, -30), from z = 70.
    n = 400
    points = [[30 * math.cos(4 * math.pi * i / n), -30 + 30 * math.sin(4 * math.pi * i / n), 70 + 50 * i / n]
              for i in range(n + 1)]
    s, t = pointer_stroke(points, DT * 13)
    return events + s


def bridge():
    events = []
    t = 0
    # Two space curves 100 mm apart, each a bowed vertical at x = -50 and x = 50.
    for x in (-50, 50):
        bow = 6 if x < 0 else -6  # towards each other
        pts = [[x + bow * math.sin(math.pi * i / 60), -60 + 8 * math.sin(math.pi * i / 60), 60 + 50 * i / 60] for i in range(61)]
        s, t = pointer_stroke(pts, t)
        events += s
    # Their midpoints (i = 30): (-44, -52, 85) and (44, -52, 85). The bridge starts and ends 3 mm off them (along y)
    # and sags in y and rises in z between: a non-planar curve.
    n = 150
    pts = []
    for i in range(n + 1):
        s = i / n
        x = -44 + 88 * s
        y = -55 - 20 * math.sin(math.pi * s)
        z = 85 + 12 * math.sin(2 * math.pi * s)
        pts.append([x, y, z])
    s, t = pointer_stroke(pts, t + 50)
    return events + s


PLANE_START = [0, 95, 60]                      # where the default plane is (the grip starts there)
PLANE_MID = [0, -10, 120]
PLANE_Q1 = axis_angle([1, 0, 0], math.pi / 3)  # normal (0, -0.87, 0.5): towards the default camera
PLANE_Q2 = axis_angle([1, 0.3, 0], math.pi / 4)


def plane_frame(p, q):
    return p, rotate(q, [1, 0, 0]), rotate(q, [0, 1, 0]), rotate(q, [0, 0, 1])


def on_plane(p, q, u, v, w=0.0):
    o, ex, ey, n = plane_frame(p, q)
    return [o[k] + u * ex[k] + v * ey[k] + w * n[k] for k in range(3)]


def plane(undo):
    events = [{"type": "action", "name": "mode.sketch", "t": 0}]
    t = 10
    # The second hand takes the plane where it is and carries it up to PLANE_MID, turning it to Q1.
    q0 = axis_angle([1, 0, 0], math.pi / 2)  # the default plane's own frame (normal -y)
    steps = 30
    for i in range(steps + 1):
        s = i / steps
        p = [PLANE_START[k] + (PLANE_MID[k] - PLANE_START[k]) * s for k in range(3)]
        q = slerp(q0, PLANE_Q1, s)
        events.append(pose("plane", p, q, ["grip"], t))
        t += DT
    # A mouse stroke on the carried plane (its pixels from model points on it).
    wave = [on_plane(PLANE_MID, PLANE_Q1, -40 + 80 * i / 40, 20 + 10 * math.sin(2 * math.pi * i / 40)) for i in range(41)]
    events.append({"type": "press", "at": wave[0], "button": "left", "t": t})
    for p in wave[1:]:
        t += 8
        events.append({"type": "move", "at": p, "t": t})
    t += 8
    events.append({"type": "release", "at": wave[-1], "button": "left", "t": t})
    t += 50
    # A pointer stroke near the plane, wobbling 8 mm off it: planar on it (the two-hands rule).
    arc = [on_plane(PLANE_MID, PLANE_Q1, 35 * math.cos(math.pi * i / 80), -15 + 25 * math.sin(math.pi * i / 80),
                    8 * math.sin(6 * math.pi * i / 80)) for i in range(81)]
    s, t = pointer_stroke(arc, t)
    events += s
    # The plane turns from Q1 to Q2 (and keeps its origin) while the pointer draws a line across it,
    # 5 mm off it: each sample lands on the plane as it is at that moment.
    n = 60
    for i in range(n + 1):
        s = i / n
        q = slerp(PLANE_Q1, PLANE_Q2, s)
        events.append(pose("plane", PLANE_MID, q, ["grip"], t))
        events.append(pose("pointer", on_plane(PLANE_MID, q, -45 + 90 * s, -40 + 10 * s * s, 5.0), buttons=["trigger"], t=t))
        t += DT
    events.append(pose("pointer", on_plane(PLANE_MID, PLANE_Q2, 45, -30, 5.0), t=t))
    t += DT
    events.append(pose("plane", PLANE_MID, PLANE_Q2, [], t))  # lets go
    t += 50
    # A pointer stroke in the air: a free space curve (three quarters of a helix turn).
    air = [[-60 + 30 * math.cos(1.5 * math.pi * i / 100), 40 + 30 * math.sin(1.5 * math.pi * i / 100), 100 + 50 * i / 100]
           for i in range(101)]
    s, t = pointer_stroke(air, t)
    events += s
    if undo:
        events.append({"type": "key", "key": "Ctrl+Z", "t": t + 50})
        events.append({"type": "key", "key": "Ctrl+Z", "t": t + 100})
    return events


def slerp(a, b, s):
    d = sum(a[k] * b[k] for k in range(4))
    if d < 0:
        b, d = [-c for c in b], -d
    th = math.acos(min(1.0, d))
    if th < 1e-12:
        return a
    wa, wb = math.sin((1 - s) * th) / math.sin(th), math.sin(s * th) / math.sin(th)
    q = [wa * a[k] + wb * b[k] for k in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


# The default scene's space curve (data/default_scene.json).
DEFAULT_KNOTS = [0, 0, 0, 0, 1, 2, 3, 3, 3, 3]
DEFAULT_POINTS = [[-90, -40, 10], [-60, 40, 90], [-20, 80, 20], [20, -10, 110], [60, 30, 40], [90, 70, 95]]


def de_boor(u, degree=3, knots=DEFAULT_KNOTS, points=DEFAULT_POINTS):
    """The NURBS Book A3.1 by de Boor's recurrence."""
    k = max(i for i in range(degree, len(points)) if knots[i] <= u)
    d = [list(points[j + k - degree]) for j in range(degree + 1)]
    for r in range(1, degree + 1):
        for j in range(degree, r - 1, -1):
            i = j + k - degree
            a = (u - knots[i]) / (knots[i + degree + 1 - r] - knots[i])
            d[j] = [(1 - a) * d[j - 1][c] + a * d[j][c] for c in range(3)]
    return d[degree]


def oversketch():
    events = [{"type": "action", "name": "mode.oversketch", "t": 0}]
    n = 120
    pts = []
    for i in range(n + 1):
        s = i / n
        p = de_boor(1.1 + 0.8 * s)
        p[2] += 4.0 * (math.sin(math.pi * s) + 0.2)
        pts.append(p)
    s, t = pointer_stroke(pts, 20)
    return events + s


def main():
    write("pose_helix.json", helix())
    write("pose_helix_undo.json", helix() + [{"type": "key", "key": "Ctrl+Z", "t": 4500}])
    write("pose_live.json", helix()[:-1])
    write("pose_oversketch.json", oversketch())
    write("pose_bridge.json", bridge())
    write("pose_plane.json", plane(False))
    write("pose_plane_undo.json", plane(True))


if __name__ == "__main__":
    main()
