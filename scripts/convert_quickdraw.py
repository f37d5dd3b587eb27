#!/usr/bin/env python3
"""Converts drawings of the Quick, Draw! dataset (Google Creative Lab, CC BY 4.0; raw format, one
ndjson file per category, each drawing a list of strokes [[x...], [y...], [t...]]) into the text
form of tests/data/unistrokes/ (see scripts/convert_unistroke_logs.py): one line per drawing,

    <category>,<countrycode>,<number>,x0 y0 t0;x1 y1 t1;...

Only drawings made in one stroke are kept (the recognizer reads one stroke); `number` counts them
from 1 in file order. x and y are the logged screen pixels and t the logged milliseconds, both
unchanged (t starts at 0 on the first sample in the raw format); no sample is dropped, moved or
reordered, and the "recognized" flag of the game's own classifier is not used to select.

    scripts/convert_quickdraw.py <dir of <category>.ndjson> tests/data/quickdraw/quickdraw.csv \
        circle square triangle line star zigzag hexagon octagon
"""
import json
import os
import sys


def fmt(v):
    return str(int(v)) if float(v).is_integer() else repr(float(v))


def convert(src_dir, out_path, categories):
    lines = []
    for cat in categories:
        kept = 0
        with open(os.path.join(src_dir, cat + ".ndjson")) as f:
            for raw in f:
                if not raw.strip():
                    continue
                d = json.loads(raw)
                if d["word"] != cat or len(d["drawing"]) != 1:
                    continue
                xs, ys, ts = d["drawing"][0]
                if not (len(xs) == len(ys) == len(ts)) or len(xs) < 2:
                    raise ValueError(f"{cat}: drawing {d['key_id']} has mismatched or too few samples")
                kept += 1
                body = ";".join(f"{fmt(x)} {fmt(y)} {fmt(t)}" for x, y, t in zip(xs, ys, ts))
                lines.append(f"{cat},{d['countrycode']},{kept},{body}")
        print(cat, kept, "one-stroke drawings")
    with open(out_path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    convert(sys.argv[1], sys.argv[2], sys.argv[3:])
