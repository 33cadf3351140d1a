#!/usr/bin/env python3
"""Writes the reference programs recorded on LinuxCNC 2.9's planner (record.sh) into a folder.

Each program is made here, from geometry, the way a CAM system or a hand programmer writes one:
chords of a curve by a chord tolerance, rasters, waterlines with corner arcs, helices, exact stops.
Nothing here knows iSurface's planner. The programs are split, before any tuning, into a tuning
half and a checking half (manifest.json): a model of the control may be tuned on the first only.

    python3 make_programs.py OUTDIR
"""
import json
import math
import os
import sys

HEADER = "G21 G90 G17 G40 G49 G94\n"


def fmt(v):
    s = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def move(word, **axes):
    return word + "".join(f" {k.upper()}{fmt(v)}" for k, v in axes.items()) + "\n"


def chords(f, t0, t1, tolerance, longest=1e9):
    """Parameters of a curve f(t) -> (x, y, z) chosen so that no chord strays more than
    `tolerance` mm from the curve (checked at the chord's middle), as CAM systems sample."""
    ts = [t0]
    t = t0
    step = (t1 - t0) / 64
    while t < t1:
        h = min(step * 2, t1 - t)
        while True:
            a, b, m = f(t), f(t + h), f(t + h / 2)
            mid = [(a[i] + b[i]) / 2 for i in range(3)]
            error = math.dist(mid, m)
            length = math.dist(a, b)
            if (error <= tolerance and length <= longest) or h < 1e-6:
                break
            h /= 2
        t += h
        step = h
        ts.append(t)
    return ts


def polyline(points, feed=None):
    out = []
    for k, p in enumerate(points):
        line = move("G1", x=p[0], y=p[1], z=p[2])
        if k == 0 and feed:
            line = line.rstrip("\n") + f" F{feed}\n"
        out.append(line)
    return "".join(out)


def program(mode, body, start=(0, 0, 5)):
    return HEADER + mode + "\n" + move("G0", x=start[0], y=start[1], z=start[2]) + body + "G0 Z10\nM2\n"


def bump(x, y):
    return 2.0 * math.exp(-((x - 20) ** 2 + (y - 20) ** 2) / 60.0)


def raster(surface, width, height, stepover, tolerance, feed, along_x=True):
    body = []
    first = True
    passes = int(height / stepover) + 1
    for k in range(passes):
        c = k * stepover
        forward = k % 2 == 0
        if along_x:
            f = lambda t, c=c: (t, c, surface(t, c))
        else:
            f = lambda t, c=c: (c, t, surface(c, t))
        ts = chords(f, 0, width, tolerance)
        if not forward:
            ts = [width - t for t in reversed(ts)]
        pts = [f(t) for t in ts]
        if first:
            body.append(move("G0", x=pts[0][0], y=pts[0][1]))
            body.append(move("G1", z=pts[0][2]).rstrip("\n") + f" F{feed}\n")
            first = False
        body.append(polyline(pts[1:]))
    return "".join(body)


def fillet_surface(x, y):
    # A floor at z=0 rising to a wall through a fillet of radius 8 mm, then a 30-degree slope.
    r = 8.0
    if x < 10:
        return 0.0
    if x < 10 + r * math.sin(math.radians(30)):
        return r - math.sqrt(max(0.0, r * r - (x - 10) ** 2))
    x0 = 10 + r * math.sin(math.radians(30))
    z0 = r - r * math.cos(math.radians(30))
    return z0 + (x - x0) * math.tan(math.radians(30))


def rounded_rectangle(w, h, r, z, feed, direction=3):
    """A waterline: a rectangle with corner arcs of radius r, counter-clockwise."""
    body = [move("G1", x=r, y=0, z=z).rstrip("\n") + f" F{feed}\n"]
    corners = [(w - r, 0, w, r, -r, 0), (w, h - r, w - r, h, 0, -r), (r, h, 0, h - r, r, 0), (0, r, r, 0, 0, r)]
    for lx, ly, ex, ey, i, j in corners:
        body.append(move("G1", x=lx, y=ly))
        # centre relative to the start of the arc
        cx, cy = {(w - r, 0): (w - r, r), (w, h - r): (w - r, h - r), (r, h): (r, h - r), (0, r): (r, r)}[(lx, ly)]
        body.append(f"G{direction} X{fmt(ex)} Y{fmt(ey)} I{fmt(cx - lx)} J{fmt(cy - ly)}\n")
    return "".join(body)


def make_all():
    p = {}
    # The six kinds of the control's disagreement list, made again from their descriptions.
    p["bump_raster_chords_p001_f3000"] = ("check", program("G64 P0.01",
        raster(bump, 40, 20, 2.0, 0.005, 3000)))
    p["segments_005mm_f6000"] = ("tune", program("G64",
        polyline([(0.05 * k, 2 * math.sin(0.05 * k / 6), 0) for k in range(1, 1201)], 6000), start=(0, 0, 0)))
    p["fillet_transition_default_g64"] = ("check", program("G64",
        raster(fillet_surface, 30, 16, 1.0, 0.01, 2000)))
    r600 = 600 * 0.2 / (2 * math.pi)
    p["circle_600_chords_02mm_g61"] = ("tune", program("G61",
        polyline([(r600 * math.cos(2 * math.pi * k / 600), r600 * math.sin(2 * math.pi * k / 600), 0)
                  for k in range(1, 601)], 1500), start=(r600, 0, 0)))
    mixed = [move("G1", x=10, y=0, z=0).rstrip("\n") + " F2400\n"]
    for k in range(10):
        mixed.append(move("G1", x=10 + 3 * k, y=5 * (k % 2)))
        mixed.append(f"G2 X{fmt(13 + 3 * k)} Y{fmt(5 * (k % 2))} R{fmt(2.0 + 0.3 * k)}\n")
        mixed.append(move("G1", x=13 + 3 * k, y=5 * ((k + 1) % 2)))
        mixed.append(move("G1", z=-0.5 * (k % 3)))
    mixed += [move("G1", x=0, y=20), move("G1", x=0, y=0)]
    p["moves_and_arcs_p001"] = ("check", program("G64 P0.01", "".join(mixed), start=(0, 0, 0)))
    water = []
    for k, r in enumerate([0.2, 0.35, 0.5, 1.0, 2.0, 5.0]):
        water.append(rounded_rectangle(30 - 2 * k, 20 - 2 * k, r, -0.5 * k, 2500))
    p["waterline_arcs_02_to_5mm_p001"] = ("tune", program("G64 P0.01", "".join(water), start=(0.2, 0, 0)))
    # CAM chords of 0.02-2 mm at several tolerances and feeds.
    wave = lambda t: (t, 8 * math.sin(t / 7), 0.5 * math.sin(t / 3))
    for name, tol, feed, mode, longest, sset in [
            ("chords_tol0002_f1000_g64", 0.002, 1000, "G64", 1e9, "tune"),
            ("chords_tol001_f3000_p001", 0.01, 3000, "G64 P0.01", 1e9, "check"),
            ("chords_tol005_f5000_p005", 0.05, 5000, "G64 P0.05", 2.0, "tune"),
            ("chords_tol001_f2000_p002_q001", 0.01, 2000, "G64 P0.02 Q0.01", 1e9, "check"),
            ("chords_02mm_f4000_p0005", 1.0, 4000, "G64 P0.005", 0.2, "tune")]:
        ts = chords(wave, 0, 120, tol, longest)
        p[name] = (sset, program(mode, polyline([wave(t) for t in ts[1:]], feed), start=(0, 0, 0)))
    arcs = [move("G1", x=0, y=0, z=0).rstrip("\n") + " F2000\n"]
    x = 0.0
    for r in [0.1, 0.3, 0.5, 1, 2, 5, 10, 25]:
        arcs.append(move("G1", x=x + 2, y=0))
        arcs.append(f"G3 X{fmt(x + 2 + 2 * r)} Y0 I{fmt(r)} J0\n")
        arcs.append(f"G3 X{fmt(x + 2)} Y0 I{fmt(-r)} J0\n")
        arcs.append(move("G1", x=x + 2 + 2 * r + 1))
        x += 2 * r + 3
    p["arcs_of_every_size_g64"] = ("check", program("G64", "".join(arcs), start=(0, 0, 0)))
    helix = [move("G1", x=20, y=0, z=0).rstrip("\n") + " F1800\n"]
    for k in range(3):
        helix.append(f"G3 X20 Y0 Z{fmt(-(k + 1) * 1.0)} I-20 J0\n")
    helix.append(move("G1", x=5, y=0))
    for k in range(4):
        helix.append(f"G2 X5 Y0 Z{fmt(-3 - (k + 1) * 0.5)} I-5 J0\n")
    p["helices_r20_r5_p001"] = ("tune", program("G64 P0.01", "".join(helix), start=(20, 0, 0)))
    zig = [move("G1", x=0, y=0, z=0).rstrip("\n") + " F3000\n"]
    for k in range(12):
        zig.append(move("G1", x=40 * ((k + 1) % 2), y=3 * (k + 1) // 2 * 1.0))
    p["zigzag_exact_stop_g611"] = ("check", program("G61.1", "".join(zig), start=(0, 0, 0)))
    p["zigzag_exact_path_g61"] = ("tune", program("G61", "".join(zig), start=(0, 0, 0)))
    p["zigzag_blended_g64"] = ("check", program("G64", "".join(zig), start=(0, 0, 0)))
    p["zigzag_blended_p05_q001"] = ("tune", program("G64 P0.5 Q0.01", "".join(zig), start=(0, 0, 0)))
    rap = []
    for k in range(8):
        rap.append(move("G0", x=30 * (k % 3), y=15 * (k % 2), z=2))
        rap.append(move("G1", z=0).rstrip("\n") + " F1200\n")
        rap.append(move("G1", x=30 * (k % 3) + 10, y=15 * (k % 2) + 5).rstrip("\n") + " F4000\n")
        rap.append(move("G0", z=5))
    p["rapids_and_plunges"] = ("check", program("G64 P0.01", "".join(rap)))
    sl = [move("G1", x=0, y=0, z=0).rstrip("\n") + " F5000\n"]
    x = 0.0
    for k in range(20):
        x += 0.1 if k % 2 == 0 else 40.0
        sl.append(move("G1", x=x, y=(k % 4) * 0.5))
    p["short_and_long_moves_p001"] = ("tune", program("G64 P0.01", "".join(sl), start=(0, 0, 0)))
    kinks = [move("G1", x=0, y=0, z=0).rstrip("\n") + " F3000\n"]
    x = y = heading = 0.0
    for k in range(60):
        heading += math.radians([0.5, 1, 2, 5][k % 4]) * (1 if (k // 8) % 2 == 0 else -1)
        x += 3 * math.cos(heading)
        y += 3 * math.sin(heading)
        kinks.append(move("G1", x=x, y=y))
    p["small_kinks_05_to_5deg_g64"] = ("check", program("G64", "".join(kinks), start=(0, 0, 0)))
    feeds = [move("G1", x=0, y=0, z=0).rstrip("\n") + " F600\n"]
    for k, f in enumerate([600, 1500, 3000, 6000, 900, 4500, 2000, 6000, 300, 3000]):
        feeds.append(move("G1", x=12 * (k + 1), y=4 * (k % 2)).rstrip("\n") + f" F{f}\n")
    p["feed_changes_p001"] = ("tune", program("G64 P0.01", "".join(feeds), start=(0, 0, 0)))
    link = []
    for k in range(12):
        y0 = 0.7 * k
        xs, xe = (0, 30) if k % 2 == 0 else (30, 0)
        if k == 0:
            link.append(move("G1", x=xs, y=y0, z=0).rstrip("\n") + " F1700\n")
        link.append(move("G1", x=xe, y=y0))
        d = "G3" if k % 2 == 0 else "G2"
        link.append(f"{d} X{fmt(xe)} Y{fmt(y0 + 0.7)} I0 J0.35\n")
    p["raster_small_arc_links_r035_p001"] = ("check", program("G64 P0.01", "".join(link), start=(0, 0, 0)))
    # A long program: some 20,000 lines of chords over a wavy surface.
    wavy = lambda x, y: 1.5 * math.sin(x / 9) * math.cos(y / 11)
    p["long_raster_20000_lines_p001"] = ("check", program("G64 P0.01", raster(wavy, 60, 60, 0.5, 0.0002, 4000)))
    return p


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    manifest = {}
    for name, (subset, text) in sorted(make_all().items()):
        with open(os.path.join(out, name + ".ngc"), "w") as f:
            f.write(text)
        manifest[name] = {"set": subset, "lines": text.count("\n")}
    with open(os.path.join(out, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=2, sort_keys=True)
        f.write("\n")
    for name, m in sorted(manifest.items()):
        print(f"{m['set']:5} {m['lines']:6} {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
