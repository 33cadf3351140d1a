#!/usr/bin/env python3
"""Writes the five-axis reference programs (LinuxCNC dialect, xyzbc-trt: X Y Z the tool tip in the
table frame, B the tilting table, C the rotary table, degrees) recorded on LinuxCNC 2.9's planner.
Each exercises one thing a five-axis control must get right. Usage: make_programs.py OUTDIR"""
import math, os, sys

HEAD = ["G21 G90 G94 G17 G40 G49 G64", "T1 M6", "S10000 M3"]
TAIL = ["G0 Z50", "G0 B0 C0", "M5", "M2", "%"]


def program(name, body, comment):
    return name, ["%", "(%s)" % comment.replace("(", "").replace(")", "")] + HEAD + body + TAIL


def swarf_bc():
    # A straight tip path while B and C sweep together: the linear joints move through the table.
    b = ["G0 X-30 Y-10 Z20 B0 C0", "G1 Z5 F1000"]
    for k in range(1, 41):
        u = k / 40.0
        b.append("G1 X%.4f Y%.4f Z%.4f B%.4f C%.4f F1500" % (-30 + 60 * u, -10 + 20 * u, 5 + 3 * math.sin(math.pi * u),
                                                           35 * math.sin(math.pi * u), 120 * u))
    return program("swarf_bc", b, "swarf-like: tip along a line, B and C simultaneous")


def g93_sections():
    b = ["G0 X0 Y-20 Z10 B0 C0", "G1 Z2 F800", "G93"]
    for k in range(1, 25):
        b.append("G1 X%.4f Y%.4f B%.4f C%.4f F%.1f" % (10 * math.sin(k / 4.0), -20 + 1.6 * k, 2.5 * k, 7.5 * k,
                                                     60.0 + 20 * (k % 5)))
    b += ["G94", "G1 X5 Y20 B0 C180 F1200", "G93", "G1 X-5 Y10 B-20 C200 F30", "G94 G1 Z10 F600"]
    return program("g93_sections", b, "inverse-time feeds (G93) between G94 sections")


def c_half_turn():
    b = ["G0 X1 Y0 Z5 B30 C0", "G1 Z1 F600"]
    for k in range(1, 13):
        b.append("G1 X%.4f Y%.4f C%.4f F300" % (1 + 0.05 * k, 0.02 * k, 15.0 * k))
    b += ["G1 X2 Y1 C0 F300"]
    return program("c_half_turn", b, "C turns half a revolution while the tip barely moves")


def indexed_3plus2():
    b = []
    for (bb, cc) in ((30, 45), (-25, -120)):
        b += ["G0 Z40", "G0 B%d C%d" % (bb, cc), "G0 X-15 Y-15 Z10", "G1 Z0 F800"]
        for j in range(16):
            y = -15 + 2 * j
            xs = (-15, 15) if j % 2 == 0 else (15, -15)
            b.append("G1 X%d Y%.1f F2000" % (xs[0], y))
            b.append("G1 X%d Y%.1f Z%.4f" % (xs[1], y, 0.3 * math.sin(y / 5.0)))
    return program("indexed_3plus2", b, "3+2 indexed raster finishing at two orientations")


def rotary_only():
    b = ["G0 X10 Y5 Z10", "G1 B20 F2000", "G1 C90", "G1 B-40 C-30 F3000", "G1 C270 F1000", "G1 B0 C0 F4000"]
    return program("rotary_only", b, "moves of B and C alone (feed in deg/min)")


def near_singular():
    b = ["G0 X20 Y0 Z5 B0 C0", "G1 Z0 F900"]
    for k in range(1, 31):
        t = k / 30.0
        b.append("G1 X%.4f Y%.4f B%.4f C%.4f F1200" % (20 * math.cos(t), 20 * math.sin(t), 2.0 * math.sin(6 * t),
                                                     90 * t))
    return program("near_singular", b, "B through 0 (C axis along the tool) while C turns")


def tilted_arcs():
    b = ["G0 B25 C30", "G0 X10 Y0 Z5", "G1 Z0 F800", "G3 X-10 Y0 I-10 J0 F1500", "G3 X10 Y0 I10 J0",
         "G2 X0 Y10 Z-2 I-10 J0", "G1 B-25 C-60 F2000", "G2 X-10 Y0 I0 J-10 F1500"]
    return program("tilted_arcs", b, "arcs and a helix at a tilted table, rotary moves between")


def impeller_like():
    b = ["G0 X0 Y-25 Z15 B0 C0", "G1 Z5 F1000"]
    for k in range(1, 61):
        t = k / 60.0
        b.append("G1 X%.4f Y%.4f Z%.4f B%.4f C%.4f F1800" % (12 * math.sin(2 * math.pi * t), -25 + 50 * t,
                                                            5 + 4 * t, 60 * math.sin(2 * math.pi * t), 360 * t))
    return program("impeller_like", b, "B swinging +-60 while C turns a revolution along a blade")


def c_wrap():
    b = ["G0 X15 Y0 Z5 B10 C0", "G1 C200 F3000", "G1 C400", "G1 C-50 F6000", "G1 X10 C30 F1500"]
    return program("c_wrap", b, "C past a revolution and back, no wrap: C of LinuxCNC is a linear-like axis")


def g93_swarf():
    b = ["G0 X-20 Y0 Z8 B0 C0", "G1 Z3 F900", "G93"]
    for k in range(1, 31):
        u = k / 30.0
        b.append("G1 X%.4f Y%.4f B%.4f C%.4f F%.2f" % (-20 + 40 * u, 8 * math.sin(3 * u), -30 * math.sin(math.pi * u),
                                                     -90 * u, 90 + 30 * math.cos(5 * u)))
    b.append("G94")
    return program("g93_swarf", b, "inverse-time swarf: B and C with X Y")


def hemisphere_long():
    # A flowline finish over a hemisphere of radius 20, tool axis along the surface normal.
    b = ["G0 X0 Y0 Z40 B0 C0"]
    first = True
    for ring in range(1, 13):
        phi = math.radians(6 * ring)  # from the pole
        for k in range(0, 121):
            th = 2 * math.pi * k / 120.0
            nx, ny, nz = math.sin(phi) * math.cos(th), math.sin(phi) * math.sin(th), math.cos(phi)
            x, y, z = 20 * nx, 20 * ny, 20 * nz - 20
            # trt: the tool stays vertical in the machine; tilting the table by B about Y and turning C
            # brings the normal up: C = -theta, B = phi
            bb, cc = math.degrees(phi), -math.degrees(th)
            line = "G1 X%.4f Y%.4f Z%.4f B%.4f C%.4f F2400" % (x, y, z, bb, cc)
            if first:
                b += ["G0 X%.4f Y%.4f Z%.4f B%.4f C%.4f" % (x, y, z + 5, bb, cc), "G1 Z%.4f F600" % z]
                first = False
            b.append(line)
    return program("hemisphere_long", b, "flowline rings over a hemisphere, tool along the normal (long)")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    for make in (swarf_bc, g93_sections, c_half_turn, indexed_3plus2, rotary_only, near_singular, tilted_arcs,
                 impeller_like, c_wrap, g93_swarf, hemisphere_long):
        name, lines = make()
        with open(os.path.join(out, name + ".ngc"), "w") as f:
            f.write("\n".join(lines) + "\n")
        print(name)


if __name__ == "__main__":
    main()
