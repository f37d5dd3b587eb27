#!/usr/bin/env python3
"""Checks a document the monkey's session saved: it is JSON, every number in it is finite, and no
curve is degenerate (its control points spread over less than DEGENERATE_SPREAD of the scene's
size: a curve the designer cannot see or edit). Exit status 1 with one line per problem."""
import json
import math
import sys

# Relative spread below which a curve is a point for every purpose of the modeler: far below a
# pixel at any zoom the viewer allows, far above the round-off of the plane transforms (1e-16).
DEGENERATE_SPREAD = 1e-9


def numbers(value, path):
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return
    if isinstance(value, (int, float)):
        yield path, value
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(value, dict):
        for k, v in value.items():
            yield from numbers(v, f"{path}.{k}")


def main(path):
    with open(path) as f:
        doc = json.load(f, parse_constant=lambda c: float("nan"))
    problems = [f"{p}: not finite ({v})" for p, v in numbers(doc, "document") if not math.isfinite(v)]
    size = max([p.get("size", 0) for p in doc.get("planes", [])] + [doc.get("grid", {}).get("size", 0), 1.0])
    for i, curve in enumerate(doc.get("curves", [])):
        points = curve.get("points", [])
        spread = max((max(q[k] for q in points) - min(q[k] for q in points) for k in range(len(points[0]))), default=0.0)
        if spread <= DEGENERATE_SPREAD * size:
            problems.append(f"curves[{i}] (id {curve.get('id')}): degenerate, control points spread {spread:g} in a scene of size {size:g}")
    for line in problems:
        print(f"{path}: {line}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
