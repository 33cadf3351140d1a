#!/usr/bin/env python3
"""Writes random RS274/NGC programs that use parameters and expressions (numbered, indirect,
named local and global parameters; every operator and function LinuxCNC knows), for the
differential test against LinuxCNC's rs274 (tests/gcode/rs274_differential_test.cpp). The
expected moves are rs274's own output, recorded beside each program:

    tests/generators/make_expression_programs.py tests/data/rs274
    for f in tests/data/rs274/*.ngc; do rs274 -g "$f" "${f%.ngc}.canon" < /dev/null; done

Values are kept finite and in range by construction (arguments of SQRT, LN, ASIN and ACOS are
brought into their domains, divisors are never zero, every setting is reduced MOD 200)."""
import os
import random
import sys

ARITHMETIC = ["+", "-", "*", "/", "MOD", "**"]
LOGIC = ["EQ", "NE", "GT", "GE", "LT", "LE", "AND", "OR", "XOR"]
LONGEST_LINE = 200  # rs274 refuses lines of 256 characters or more


def operand(rng, names, depth):
    kind = rng.random()
    if depth > 2 or kind < 0.3:
        return f"{rng.uniform(-50, 50):.{rng.choice([0, 1, 3])}f}"
    if kind < 0.5:
        return rng.choice(["#%d" % rng.randint(1, 9), "#<%s>" % rng.choice(names), "##9", "#[%d+1]" % rng.randint(0, 8)])
    if kind < 0.75:
        return expression(rng, names, depth + 1)
    return function(rng, names, depth + 1)


def function(rng, names, depth):
    a = expression(rng, names, depth)
    f = rng.choice(["SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "EXP", "LN", "ROUND", "FIX", "FUP", "EXISTS"])
    if f in ("ASIN", "ACOS"):
        return f"{f}[[{a} MOD 2] - 1]"
    if f == "ATAN":
        return f"ATAN[{a}]/[{expression(rng, names, depth)}]"
    if f == "SQRT":
        return f"SQRT[ABS[{a}]]"
    if f == "LN":
        return f"LN[ABS[{a}] + 1]"
    if f == "EXP":
        return f"EXP[[{a} MOD 4]]"
    if f == "TAN":
        return f"TAN[[{a} MOD 80]]"
    if f == "EXISTS":
        return "EXISTS[#<%s>]" % rng.choice(names + ["never_set"])
    return f"{f}[{a}]"


def expression(rng, names, depth):
    terms = [operand(rng, names, depth)]
    for _ in range(rng.randint(1, 3)):
        op = rng.choice(LOGIC) if rng.random() < 0.2 else rng.choice(ARITHMETIC)
        right = operand(rng, names, depth)
        if op == "/":
            right = f"[ABS[{right}] + 1]"
        if op == "MOD":
            right = f"[ABS[{right}] + 1]"
        if op == "**":
            terms = [f"ABS[[{' '.join(terms)}] MOD 10]"]
            right = rng.choice(["2", "3", "0.5", "1.5"])
        terms += [op, right]
    return "[" + " ".join(terms) + "]"


def program(rng):
    names = ["depth", "_safe", "step", "_width"]
    lines = ["(parameters and expressions, for rs274)", "G21 G90 G17 G94 G40 G49 G80 F500"]
    for n in range(1, 10):
        lines.append(f"#{n}={rng.randint(1, 9) if n == 9 else round(rng.uniform(-20, 20), 3)}")
    for name in names:
        lines.append(f"#<{name}>={round(rng.uniform(-20, 20), 2)}")
    while len(lines) < 70:
        if rng.random() < 0.4:
            target = rng.choice(["#%d" % rng.randint(1, 8), "#<%s>" % rng.choice(names)])
            line = f"{target}=[{expression(rng, names, 1)} MOD 200]"
        else:
            words = " ".join(f"{axis}[{expression(rng, names, 2)} MOD 100]" for axis in "XYZ")
            line = f"{rng.choice(['G0', 'G1'])} {words}"
        if len(line) <= LONGEST_LINE:
            lines.append(line)
    lines.append("M2")
    return "\n".join(lines) + "\n"


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for seed in range(1, 21):
        with open(os.path.join(out, f"expressions-{seed:02d}.ngc"), "w") as f:
            f.write(program(random.Random(seed)))


if __name__ == "__main__":
    main()
