#!/usr/bin/env python3
"""Writes random RS274/NGC programs that use LinuxCNC's O-word control flow (subroutines with
arguments, local and global parameters, recursion, return values, calls before the definition,
if/elseif/else, while, do/while, repeat, break, continue), for the differential test against
LinuxCNC's rs274 (tests/gcode/rs274_differential_test.cpp). rs274's output is recorded beside
each program:

    tests/generators/make_control_flow_programs.py tests/data/rs274
    for f in tests/data/rs274/control-*.ngc; do rs274 -g "$f" "${f%.ngc}.canon" < /dev/null; done

Every loop counts to a bound drawn here, so every program ends."""
import os
import random
import sys


def num(rng, lo, hi, decimals=2):
    return f"{rng.uniform(lo, hi):.{decimals}f}"


def while_block(rng, k):
    n = rng.randint(2, 9)
    step = rng.choice([1, 2])
    lines = [f"#<i{k}> = 0", f"o{100 + k} while [#<i{k}> LT {n}]"]
    lines.append(f"  #<i{k}> = [#<i{k}> + {step}]")
    lines.append(f"  o{200 + k} if [#<i{k}> MOD 3 EQ {rng.randint(0, 2)}]")
    lines.append(f"    G1 X[#<i{k}> * {num(rng, 0.5, 3)}] Y{num(rng, -5, 5)}")
    lines.append(f"  o{200 + k} elseif [#<i{k}> GT {rng.randint(2, 6)}]")
    if rng.random() < 0.4:
        lines.append(f"    o{100 + k} break")
    else:
        lines.append(f"    G1 Y[#<i{k}> * {num(rng, -2, 2)}]")
    lines.append(f"  o{200 + k} else")
    if rng.random() < 0.4:
        lines.append(f"    o{100 + k} continue")
    lines.append(f"    G0 Z[#<i{k}> / {rng.randint(2, 5)}]")
    lines.append(f"  o{200 + k} endif")
    lines.append(f"  G1 X[#<i{k}> + #<_offset>] Z{num(rng, -1, 1)}")
    lines.append(f"o{100 + k} endwhile")
    return lines


def repeat_block(rng, k):
    lines = [f"#<r{k}> = {num(rng, 1, 4)}", f"o{300 + k} repeat [{rng.randint(1, 5)}]"]
    lines.append(f"  #<r{k}> = [#<r{k}> * {num(rng, 0.8, 1.3)}]")
    lines.append(f"  o<point> call [#<r{k}> * COS[#<r{k}> * {rng.randint(10, 90)}]] [#<r{k}> * SIN[#<r{k}> * 40]] [{num(rng, -2, 2)}]")
    lines.append(f"o{300 + k} endrepeat")
    return lines


def do_block(rng, k):
    return [f"#<d{k}> = {rng.randint(0, 3)}", f"o{400 + k} do",
            f"  G1 X[#<d{k}> * {num(rng, 1, 3)}] Y[#<d{k}> ** 2 / 4] F{rng.randint(100, 900)}",
            f"  #<d{k}> = [#<d{k}> + 1]", f"o{400 + k} while [#<d{k}> LT {rng.randint(1, 6)}]"]


def recursion_block(rng, k):
    return [f"o<zigzag> call [{rng.randint(1, 6)}] [{num(rng, 0.5, 3)}]", "G0 X#<_value>"]


def forward_block(rng, k):
    return [f"o<later> call [{num(rng, -10, 10)}] [{num(rng, -10, 10)}]"]


def program(rng):
    lines = ["(O-word control flow, for rs274)", "G21 G90 G17 G94 G40 G49 G80 F500",
             f"#<_offset> = {num(rng, -3, 3)}",
             "o<point> sub", "  G1 X#1 Y#2 Z#3", "o<point> endsub",
             "o<zigzag> sub",
             "  o<base> if [#1 LE 0]", "    o<zigzag> return [#2]", "  o<base> endif",
             "  G1 X[#1 * #2] Y[[#1 MOD 2] * #2]",
             "  o<zigzag> call [#1 - 1] [#2 * 1.1]",
             "  o<zigzag> return [#<_value> + #1]",
             "o<zigzag> endsub"]
    makers = [while_block, repeat_block, do_block, recursion_block, forward_block]
    for k in range(rng.randint(3, 7)):
        lines += rng.choice(makers)(rng, k)
    lines += ["M2", "o<later> sub", "  G1 X#1 Y#2", "  G0 Z#<_offset>", "o<later> endsub"]
    return "\n".join(lines) + "\n"


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for seed in range(1, 21):
        with open(os.path.join(out, f"control-{seed:02d}.ngc"), "w") as f:
            f.write(program(random.Random(seed)))


if __name__ == "__main__":
    main()
