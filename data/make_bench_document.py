#!/usr/bin/env python3
"""Writes bench_20_curves_5_planes.json: the default scene plus four smaller planes, with four
sketched cubic curves on each of the five planes (20 curves), for `sculptline --stats` during a plane
drag (issue 5 goal: p99 <= 16 ms). Everything lies inside the default scene's bounding box, so the
viewer frames it exactly as it frames the default scene and the default plane's jack stays at the
pixel the sessions press (see sessions/make_sessions.py)."""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def curve(plane, k, half):
    """A cubic wave across the plane, row k of 4, in plane-local 2D points."""
    y = -0.6 * half + 0.4 * half * k
    pts = [[round(-0.8 * half + 1.6 * half * i / 6, 3), round(y + 0.15 * half * math.sin(i + k), 3)] for i in range(7)]
    n = len(pts)
    knots = [0.0] * 4 + [float(i) for i in range(1, n - 3)] + [float(n - 3)] * 4
    return {"degree": 3, "knots": knots, "points": pts, "plane": plane}


def main():
    with open(os.path.join(HERE, "default_scene.json")) as f:
        doc = json.load(f)
    doc["planes"][0]["id"] = 1
    extra = [([-60, -60, 40], [1, 0, 0]), ([60, -70, 30], [-1, 0.2, 0]), ([-20, -80, 45], [0, 1, 0.3]),
             ([30, -40, 20], [0, 0, 1])]
    for i, (origin, normal) in enumerate(extra):
        doc["planes"].append({"id": i + 2, "origin": origin, "normal": normal, "size": 60})
    for plane in doc["planes"]:
        for k in range(4):
            doc["curves"].append(curve(plane["id"], k, plane["size"] / 2))
    with open(os.path.join(HERE, "bench_20_curves_5_planes.json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
