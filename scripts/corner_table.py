#!/usr/bin/python3
"""The L-curve corner validation table of README "Which corner method", from the corner test's output.

    build/tests/regularization/regularization_corner_test | scripts/corner_table.py

Reads the `row <set> <regularizer> | problem | noise | seed | best k (error) | knot-removal k (error)
ok/FAIL | pruning k (error) ok/FAIL` lines and prints one Markdown row per regularizer, problem, noise
level and seed set: the best k per seed, each method's chosen k with its error over the best error,
and how many seeds meet the 1.5x rule (the test's verdicts, not recomputed from rounded numbers).
"""
import collections
import re
import sys

ROW = re.compile(r"(\d+) \(([\d.]+)\)(?: (ok|FAIL))?")
SETS = ("tuning", "evaluation", "high-noise")


def parse(cell):
    m = ROW.match(cell.strip())
    return int(m.group(1)), float(m.group(2)), m.group(3)


def main():
    cases = collections.OrderedDict()
    for line in sys.stdin:
        if not line.startswith("row "):
            continue
        cells = line.split("|")
        seed_set, regularizer = cells[0].split()[1:3]
        key = (regularizer, cells[1].strip(), float(cells[2]))
        cases.setdefault(key, {s: [] for s in SETS})[seed_set].append(cells[4:7])
    print("| regularizer | problem | noise | set | best k (error) per seed | knot removal: k (error ratio) | "
          "adaptive pruning: k (error ratio) |")
    print("|---|---|---|---|---|---|---|")
    for (regularizer, problem, noise), sets in cases.items():
        for seed_set in SETS:
            rows = sets[seed_set]
            if not rows:
                continue
            best, knot, prune = [], [], []
            passed = [0, 0]
            for b, k, p in rows:
                bk, be, _ = parse(b)
                best.append(f"{bk} ({be:.3f})")
                for i, (cell, out) in enumerate(((k, knot), (p, prune))):
                    ck, ce, verdict = parse(cell)
                    out.append(f"{ck} ({ce / be:.1f}×)" if be > 0 else f"{ck}")
                    passed[i] += verdict == "ok"
            print(f"| {regularizer} | {problem} | {noise * 100:g} % | {seed_set} | {', '.join(best)} | "
                  f"{', '.join(knot)}: **{passed[0]}/{len(rows)}** | {', '.join(prune)}: **{passed[1]}/{len(rows)}** |")


if __name__ == "__main__":
    main()
