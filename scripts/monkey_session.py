#!/usr/bin/env python3
"""Writes a monkey session: random input for the real window, replayed by `sculptline --replay`.

A fixed seed gives the same session every time, so a failure found by a seed is reproducible:

    scripts/monkey_session.py --seed 3 --seconds 20 > monkey.json
    xvfb-run -a sculptline --replay monkey.json --save out.json --quit

The monkey switches modes (hot keys and named actions), drags, clicks and draws in the viewport
(random walks, loops that end on their first pixel, clicks without motion, strokes along the edge
of the viewport, drags with the middle and right buttons and with modifiers), undoes and redoes,
deletes, builds and cancels surfaces, adds planes and picks recognition candidates. It never uses
the file actions, whose dialogs would wait for a person.
"""
import argparse
import json
import math
import random

# Hot keys of the modes and the other non-file commands (ui/main_window.cpp); Ctrl+S, Ctrl+O,
# Ctrl+N and Ctrl+Q open dialogs or end the program and are left out.
MODE_KEYS = ["V", "S", "E", "O", "L", "P", "F", "R", "X", "W", "K", "B", "G", "U", "M"]
OTHER_KEYS = ["Ctrl+Z", "Ctrl+Shift+Z", "Delete", "Return", "Escape", "N", "T", "C", "Home", "Ctrl+P"]
ACTIONS = ["stroke.useRecognized", "stroke.nextCandidate", "stroke.useFreeform", "surface.build", "surface.cancel",
           "plane.add", "view.all", "edit.delete"]


class Monkey:
    def __init__(self, seed, width, height):
        self.rng = random.Random(seed)
        self.width, self.height = width, height
        self.t = 0.0
        self.events = []

    def emit(self, event, dt):
        self.t += dt
        event["t"] = round(self.t, 1)
        self.events.append(event)

    def point(self):
        # Mostly inside, sometimes on or just past the edge of the viewport.
        if self.rng.random() < 0.05:
            return [self.rng.choice([-5, 0, self.width - 1, self.width + 5]), self.rng.randrange(self.height)]
        return [self.rng.randrange(self.width), self.rng.randrange(self.height)]

    def mouse(self, kind, p, button, modifiers, dt):
        e = {"type": kind, "x": int(p[0]), "y": int(p[1])}
        if kind != "move":
            e["button"] = button
        if modifiers:
            e["modifiers"] = modifiers
        self.emit(e, dt)

    def gesture(self):
        r = self.rng.random()
        button = "left" if r < 0.85 else ("middle" if r < 0.93 else "right")
        modifiers = []
        if self.rng.random() < 0.1:
            modifiers = [self.rng.choice(["shift", "ctrl", "alt"])]
        start = self.point()
        shape = self.rng.choice(["click", "walk", "loop", "line", "jitter", "arc"])
        path = [start]
        if shape == "walk":
            p = list(start)
            for _ in range(self.rng.randrange(3, 60)):
                p = [p[0] + self.rng.gauss(0, 12), p[1] + self.rng.gauss(0, 12)]
                path.append(p)
        elif shape == "loop":
            # A closed loop that ends exactly on its first pixel.
            radius = self.rng.uniform(2, 150)
            n = self.rng.randrange(8, 80)
            for k in range(1, n):
                a = 2 * math.pi * k / n
                path.append([start[0] + radius * (math.cos(a) - 1), start[1] + radius * math.sin(a)])
            path.append(list(start))
        elif shape == "line":
            end = self.point()
            n = self.rng.randrange(2, 40)
            path += [[start[0] + (end[0] - start[0]) * k / n, start[1] + (end[1] - start[1]) * k / n] for k in range(1, n + 1)]
        elif shape == "jitter":
            # A pen held still: tiny motions around one pixel, often exactly on it.
            for _ in range(self.rng.randrange(2, 30)):
                path.append([start[0] + self.rng.choice([0, 0, 0, 1, -1]), start[1] + self.rng.choice([0, 0, 1, -1])])
        elif shape == "arc":
            radius = self.rng.uniform(10, 300)
            a0 = self.rng.uniform(0, 2 * math.pi)
            sweep = self.rng.uniform(-3, 3)
            n = self.rng.randrange(5, 60)
            cx, cy = start[0] - radius * math.cos(a0), start[1] - radius * math.sin(a0)
            path += [[cx + radius * math.cos(a0 + sweep * k / n), cy + radius * math.sin(a0 + sweep * k / n)] for k in range(1, n + 1)]
        self.mouse("press", path[0], button, modifiers, self.rng.uniform(5, 120))
        for p in path[1:]:
            self.mouse("move", p, button, modifiers, self.rng.uniform(2, 20))
        self.mouse("release", path[-1], button, modifiers, self.rng.uniform(2, 60))

    def run(self, seconds):
        while self.t < seconds * 1000.0:
            r = self.rng.random()
            if r < 0.15:
                self.emit({"type": "key", "key": self.rng.choice(MODE_KEYS)}, self.rng.uniform(5, 100))
            elif r < 0.30:
                self.emit({"type": "key", "key": self.rng.choice(OTHER_KEYS)}, self.rng.uniform(5, 100))
            elif r < 0.38:
                self.emit({"type": "action", "name": self.rng.choice(ACTIONS)}, self.rng.uniform(5, 100))
            else:
                self.gesture()
        return {"size": [self.width, self.height], "seed": self.seed_note, "events": self.events}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--seconds", type=float, default=20.0, help="recorded duration of the session")
    parser.add_argument("--size", default="1024x768", help="viewport WIDTHxHEIGHT")
    parser.add_argument("--output", "-o", help="file to write (default: standard output)")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    monkey = Monkey(args.seed, width, height)
    monkey.seed_note = args.seed
    session = monkey.run(args.seconds)
    text = json.dumps(session, separators=(",", ":"))
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    else:
        print(text)


if __name__ == "__main__":
    main()
