#!/usr/bin/env python3
"""Writes the replay sessions of the GUI tests (tests/gui/CMakeLists.txt). Pixel positions are for
the default scene (data/default_scene.json) in an 800x600 viewport, where the default plane covers
about x 392..596, y 127..360 and its jack dragger sits at about (481, 243)."""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
HUNDRED_EDIT_ROUNDS = 28


def stroke(points, t0, dt=8):
    """press, moves, release along points (pixels), dt ms apart."""
    events = [{"type": "press", "x": points[0][0], "y": points[0][1], "button": "left", "t": t0}]
    t = t0
    for x, y in points[1:]:
        t += dt
        events.append({"type": "move", "x": x, "y": y, "t": t})
    events.append({"type": "release", "x": points[-1][0], "y": points[-1][1], "button": "left", "t": t + dt})
    return events, t + dt


def wave(x0, x1, y, amplitude, n=40):
    return [(round(x0 + (x1 - x0) * i / (n - 1)), round(y + amplitude * math.sin(2 * math.pi * i / (n - 1))))
            for i in range(n)]


def arc(cx, cy, r, n=40):
    return [(round(cx + r * math.cos(math.pi * i / (n - 1))), round(cy - 0.6 * r * math.sin(math.pi * i / (n - 1))))
            for i in range(n)]


def loop(cx, cy, rx, ry, n=60):
    """A closed loop, counter-clockwise on screen from its rightmost point."""
    return [(round(cx + rx * math.cos(2 * math.pi * i / n)), round(cy - ry * math.sin(2 * math.pi * i / n)))
            for i in range(n + 1)]


def drag(start, end, t0, steps=30, dt=10):
    path = [(round(start[0] + (end[0] - start[0]) * i / steps), round(start[1] + (end[1] - start[1]) * i / steps))
            for i in range(steps + 1)]
    return stroke(path, t0, dt)


def write(name, events):
    with open(os.path.join(HERE, name), "w") as f:
        json.dump({"size": [800, 600], "events": events}, f, indent=1)
        f.write("\n")


def two_strokes():
    events = [{"type": "action", "name": "mode.sketch", "t": 0}]
    s1, t = stroke(wave(410, 575, 170, 15), 50)
    s2, t = stroke(arc(490, 330, 70), t + 50)
    return events + s1 + s2, t


def main():
    events, t = two_strokes()
    write("sketch_two_strokes.json", events + [{"type": "wait", "ms": 50}])

    # Two strokes, then the plane dragged by the jack's translator plate (one undo step).
    d, t2 = drag((463, 246), (380, 290), t + 100)
    write("sketch_and_drag.json", events + d + [{"type": "wait", "ms": 50}])

    # Undo and redo: two strokes, undo both, redo one; the drag undone.
    u = [{"type": "key", "key": "Ctrl+Z", "t": t2 + 50}, {"type": "action", "name": "edit.undo", "t": t2 + 60},
         {"type": "key", "key": "Ctrl+Z", "t": t2 + 70}, {"type": "key", "key": "Ctrl+Shift+Z", "t": t2 + 80}]
    write("undo_redo.json", events + d + u + [{"type": "wait", "ms": 50}])

    # Delete and undo: the last stroke (selected when made) deleted with the Delete key; then, in
    # select mode, a click on the plane's jack selects the plane, Delete removes it with its curve,
    # and Ctrl+Z brings both back.
    x = [{"type": "key", "key": "Del", "t": t + 50}, {"type": "action", "name": "mode.select", "t": t + 60},
         {"type": "press", "x": 463, "y": 246, "button": "left", "t": t + 70},
         {"type": "release", "x": 463, "y": 246, "button": "left", "t": t + 80},
         {"type": "key", "key": "Del", "t": t + 90}, {"type": "key", "key": "Ctrl+Z", "t": t + 100}]
    write("delete_undo.json", events + x + [{"type": "wait", "ms": 50}])

    # Auxiliary planes (seed 000 §3.1). The fitted curves interpolate their strokes' ends, so the
    # first stroke's start pixel (410, 170) lies on curve 4 and the second's (560, 330) on curve 5.
    # Case 1: from curve 4 into the air; case 2: from curve 4 to curve 5.
    a1, ta = stroke([(410 - 3 * i, 170 - 2 * i) for i in range(30)], t + 50)
    a2, ta = stroke([(round(410 + 150 * i / 29), round(170 + 160 * i / 29 + 25 * math.sin(math.pi * i / 29)))
                     for i in range(30)], ta + 50)
    write("auxiliary_planes.json", events + a1 + a2 + [{"type": "wait", "ms": 50}])

    # Over-sketch: a straight stroke from curve 4 at x 450 (y 185) to x 540 (y 155) replaces the
    # wave's middle; then undo and redo it.
    o = [{"type": "action", "name": "mode.oversketch", "t": t + 40}]
    s, to = stroke([(round(450 + 90 * i / 29), round(185 - 30 * i / 29)) for i in range(30)], t + 50)
    o += s + [{"type": "key", "key": "Ctrl+Z", "t": to + 20}, {"type": "key", "key": "Ctrl+Shift+Z", "t": to + 30}]
    write("oversketch.json", events + o + [{"type": "wait", "ms": 50}])

    # Pull: curve 4 grabbed at (450, 185) and pulled 45 pixels down; undone and redone.
    g, tg = drag((450, 185), (450, 230), t + 60, steps=20, dt=10)
    u = [{"type": "key", "key": "Ctrl+Z", "t": tg + 20}, {"type": "key", "key": "Ctrl+Shift+Z", "t": tg + 30}]
    write("pull.json", events + [{"type": "action", "name": "mode.pull", "t": t + 50}] + g + u + [{"type": "wait", "ms": 50}])

    # Lift: in lift mode the stroke of the auxiliary case 2 (curve 4's start to curve 5's start)
    # becomes a space curve.
    write("lift.json", events + [{"type": "action", "name": "mode.lift", "t": t + 40}] + a2 + [{"type": "wait", "ms": 50}])

    # Recognition: the arc stroke (curve 5) replaced by the recognized exact arc; undone, redone.
    r = [{"type": "action", "name": "stroke.useRecognized", "t": t + 40}, {"type": "key", "key": "Ctrl+Z", "t": t + 50},
         {"type": "key", "key": "Ctrl+Shift+Z", "t": t + 60}]
    write("recognize.json", events + r + [{"type": "wait", "ms": 50}])

    # A new plane facing the view, and a stroke on it.
    p = [{"type": "action", "name": "mode.sketch", "t": 0}, {"type": "action", "name": "plane.add", "t": 10}]
    s, t = stroke(wave(250, 550, 300, 40), 60)
    write("add_plane_and_sketch.json", p + s + [{"type": "wait", "ms": 50}])

    # A long history of four kinds of edit, 28 rounds of: an arc stroke (a new curve), the
    # recognized arc instead (a new shape), Delete (the curve removed), a 5-pixel drag of the
    # plane's jack, down in even rounds and back up in odd ones (the jack stays under the
    # pointer). 112 edits; then 112 undos.
    h = [{"type": "action", "name": "mode.sketch", "t": 0}]
    th = 50
    for i in range(HUNDRED_EDIT_ROUNDS):
        s, th = stroke(arc(490, 330, 70), th + 50)
        h += s
        h += [{"type": "action", "name": "stroke.useRecognized", "t": th + 20}, {"type": "key", "key": "Del", "t": th + 30}]
        down = i % 2 == 0
        d, th = drag((463, 246 if down else 251), (463, 251 if down else 246), th + 50, steps=5, dt=10)
        h += d
    write("hundred_edits.json", h + [{"type": "wait", "ms": 50}])
    undos = [{"type": "key", "key": "Ctrl+Z", "t": th + 50 + 5 * k} for k in range(4 * HUNDRED_EDIT_ROUNDS)]
    write("hundred_edits_undone.json", h + undos + [{"type": "wait", "ms": 50}])

    # Recognition habits (thesis §3.1.3): a flattened loop, recognized as an ellipse, corrected to
    # the circle (N twice: the recognized ellipse, then the second candidate); then, in another
    # session on the same habits file, a smaller, rounder loop elsewhere, which the habit makes a circle.
    c, t = stroke(loop(490, 250, 75, 60), 50)
    write("habits_correct.json", [{"type": "action", "name": "mode.sketch", "t": 0}] + c +
          [{"type": "action", "name": "stroke.nextCandidate", "t": t + 40},
           {"type": "action", "name": "stroke.nextCandidate", "t": t + 60}, {"type": "wait", "ms": 50}])
    c, t = stroke(loop(480, 240, 60, 50), 50)
    write("habits_similar.json", [{"type": "action", "name": "mode.sketch", "t": 0}] + c + [{"type": "wait", "ms": 50}])

    # The --stats goal: drag the default plane of ../bench_20_curves_5_planes.json (20 curves on 5
    # planes) for 120 pointer events at 125 Hz, to and fro.
    d1, t = drag((463, 246), (380, 300), 100, steps=60, dt=8)
    d2, t = drag((380, 300), (470, 230), t + 8, steps=60, dt=8)
    # One press-move-release: drop the inner release/press pair of the two halves.
    write("drag_bench.json", [{"type": "action", "name": "mode.select", "t": 0}] + d1[:-1] + d2[1:])


if __name__ == "__main__":
    main()
