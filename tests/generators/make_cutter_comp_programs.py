#!/usr/bin/env python3
"""Writes random RS274/NGC programs that run contours under cutter radius compensation (G41 /
G42 with D from a tool table, G41.1 / G42.1 with a diameter; XY and XZ planes; inch and mm; lines,
arcs in both directions, inside and outside corners, a plunge along the plane's normal after the
entry move, rapids under compensation), for the differential test against LinuxCNC's rs274
(tests/gcode/rs274_differential_test.cpp). The tool table is written beside them; rs274's output
is recorded beside each program:

    tests/generators/make_cutter_comp_programs.py tests/data/rs274
    cd tests/data/rs274
    for f in comp-*.ngc; do
      rs274 -t comp.tbl -g "$f" "${f%.ngc}.canon" < /dev/null > out.txt 2>&1 ||
        { grep -v executing out.txt | head -1 > "${f%.ngc}.error"; rm "${f%.ngc}.canon"; }
    done; rm out.txt

A program rs274 refuses (its tool does not fit a corner) keeps rs274's message in a .error file
instead: the interpreter must refuse it too.

The contours are star-shaped about the origin: every corner the tool meets is one it fits (each
side at least four tool radii long, each arc's radius above the largest tool's)."""
import math
import os
import random
import sys

# rs274 standalone reads its tool table in inches.
TOOLS = {1: 0.125, 2: 0.25, 3: 0.0625}


def contour(rng, scale):
    n = rng.randint(4, 9)
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    # Far enough apart that no side is short.
    angles = [a for i, a in enumerate(angles) if i == 0 or a - angles[i - 1] > 0.35]
    if len(angles) < 3:
        angles = [0, 2.1, 4.2]
    return [(rng.uniform(12, 30) * scale * math.cos(a), rng.uniform(12, 30) * scale * math.sin(a)) for a in angles]


def segment(rng, here, there, u, v, scale, decimals):
    chord = math.dist(here, there)
    words = f"{u}{there[0]:.{decimals}f} {v}{there[1]:.{decimals}f}"
    if rng.random() < 0.6:
        return f"G1 {words}"
    radius = chord / 2 * rng.uniform(1.15, 3.0)
    radius = max(radius, 8 * scale)
    code = rng.choice(["G2", "G3"])
    if rng.random() < 0.5:
        return f"{code} {words} R{radius:.{decimals}f}"
    # Centre format: the centre on the chord's perpendicular bisector, on the side of a minor arc.
    mid = ((here[0] + there[0]) / 2, (here[1] + there[1]) / 2)
    offset = math.sqrt(max(radius * radius - chord * chord / 4, 0))
    nx, ny = -(there[1] - here[1]) / chord, (there[0] - here[0]) / chord
    side = 1 if code == "G3" else -1
    cx, cy = mid[0] + side * offset * nx, mid[1] + side * offset * ny
    i_word = "I" if u == "X" else "K"
    j_word = "J" if v == "Y" else "I"
    if u == "Z":  # G18: the plane's first axis is Z (K), its second X (I)
        i_word, j_word = "K", "I"
    return f"{code} {words} {i_word}{cx - here[0]:.{decimals}f} {j_word}{cy - here[1]:.{decimals}f}"


def program(rng, index):
    inch = rng.random() < 0.5
    scale = 1 / 25.4 if inch else 1.0
    decimals = 4 if inch else 3
    xz = rng.random() < 0.3
    u, v, w = ("Z", "X", "Y") if xz else ("X", "Y", "Z")
    lines = [f"(cutter compensation {index}, for rs274)",
             f"{'G20' if inch else 'G21'} {'G18' if xz else 'G17'} G90 G94 G40 G49 G80 F{rng.randint(200, 900) * (0.04 if inch else 1):.1f}"]
    points = contour(rng, scale)
    first = points[0]
    reach = 1.8 * max(math.hypot(*p) for p in points)
    angle = math.atan2(first[1], first[0]) + rng.uniform(-0.6, 0.6)
    start = (reach * math.cos(angle), reach * math.sin(angle))
    lines.append(f"G0 {u}{start[0]:.{decimals}f} {v}{start[1]:.{decimals}f} {w}{5 * scale:.{decimals}f}")
    lines.append(f"G1 {w}{-1 * scale:.{decimals}f}")
    side = rng.choice(["G41", "G42"])
    if rng.random() < 0.2:
        comp = f"{side}.1 D{rng.choice([0.1, 0.2]) if inch else rng.choice([2.5, 5.0]):.3f}"
    else:
        comp = f"{side} D{rng.choice(list(TOOLS))}"
    lines.append(comp)
    lines.append(f"G1 {u}{first[0]:.{decimals}f} {v}{first[1]:.{decimals}f}")
    if rng.random() < 0.5:
        lines.append(f"G1 {w}{-2 * scale:.{decimals}f}")
    here = first
    laps = points[1:] + [points[0]]
    if rng.random() < 0.4:
        laps.append(points[1])
    for there in laps:
        if rng.random() < 0.08:
            lines.append(f"G0 {u}{there[0]:.{decimals}f} {v}{there[1]:.{decimals}f}")
        else:
            lines.append(segment(rng, here, there, u, v, scale, decimals))
        here = there
    lines.append("G40")
    lines.append(f"G0 {u}{start[0]:.{decimals}f} {v}{start[1]:.{decimals}f}")
    lines.append(f"G0 {w}{5 * scale:.{decimals}f}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


def main():
    out = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 30
    rng = random.Random(41)
    with open(os.path.join(out, "comp.tbl"), "w") as f:
        for t, d in TOOLS.items():
            f.write(f"T{t} P{t} D{d} Z0 ;tool {t}\n")
    for i in range(1, count + 1):
        with open(os.path.join(out, f"comp-{i:02d}.ngc"), "w") as f:
            f.write(program(rng, i))


if __name__ == "__main__":
    main()
