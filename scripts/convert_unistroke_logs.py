#!/usr/bin/env python3
"""Converts the $1 unistroke gesture logs (Wobbrock, Wilson and Li, UIST 2007; XML, one file per
gesture) into the compact text form of tests/data/unistrokes/: one file per subject, one line per
recording:

    <gesture>,<speed>,<number>,x0 y0 t0;x1 y1 t1;...

x and y are the logged pixel coordinates (unchanged), t is milliseconds since the first point (the
logged T minus the first T). Points and their order are kept exactly; nothing is filtered.

    scripts/convert_unistroke_logs.py <xml_logs dir> tests/data/unistrokes
"""
import os
import re
import sys
import xml.etree.ElementTree as ET


def convert(xml_root, out_dir):
    for subject in sorted(os.listdir(xml_root)):
        sdir = os.path.join(xml_root, subject)
        if not os.path.isdir(sdir) or not re.fullmatch(r"s\d\d", subject):
            continue
        lines = []
        for speed in ("slow", "medium", "fast"):
            ddir = os.path.join(sdir, speed)
            for name in sorted(os.listdir(ddir)):
                if not name.endswith(".xml"):
                    continue
                g = ET.parse(os.path.join(ddir, name)).getroot()
                m = re.fullmatch(r"(.+?)(\d+)", g.get("Name"))
                pts = [(int(p.get("X")), int(p.get("Y")), int(p.get("T"))) for p in g.iter("Point")]
                t0 = pts[0][2]
                body = ";".join(f"{x} {y} {t - t0}" for x, y, t in pts)
                lines.append(f"{m.group(1)},{g.get('Speed')},{int(m.group(2))},{body}")
        with open(os.path.join(out_dir, subject + ".csv"), "w") as f:
            f.write("\n".join(lines) + "\n")
        print(subject, len(lines), "recordings")


if __name__ == "__main__":
    convert(sys.argv[1], sys.argv[2])
