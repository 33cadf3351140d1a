#!/usr/bin/python3
"""make_blended_ramp_rasters.py - CAM-style ball-end finishing rasters over a "blended ramp" transition surface.

usage: python3 make_blended_ramp_rasters.py --seed 20261209 --count 8 --out programs/

Surface family (own design): floor z=0, then a ramp whose two transitions (floor->ramp and
ramp->plateau) are cubic-curvature blends (z'' = 6 s/L u(1-u), i.e. curvature rises and falls
smoothly, slope z' = s (3u^2 - 2u^3): a clothoid-like, curvature-continuous blend), then a
plateau at height H carrying a sinusoidal bump band (Hann-windowed). Along the cross (Y)
direction the blend start x0, blend lengths L1/L2 and the ramp angle vary smoothly, and the bump
phase drifts, so neighbouring passes differ slightly.

Cutter location: exact ball-end offset (centre = contact point + R * unit normal; tip = centre - R)
solved per CL point by fixed-point iteration on the contact point (valid since every concave
radius of the surface is kept > 1.5 R). Chords: greedy, each chord's max deviation (sagitta) from
the densely sampled CL curve <= chord tolerance; flat stretches become one long move.
"""
import sys, os
try:
    import numpy as np
except ImportError:                       # the pyenv python has no numpy: use the Debian one
    if sys.executable != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise
import argparse, json, math


def smoothstep_int(u):
    """integral of (3u^2-2u^3) from 0 to u"""
    return u**3 - 0.5 * u**4


class Surface:
    def __init__(self, rng, W):
        self.W = W
        self.x0 = rng.uniform(6.0, 10.0)          # blend start (mean)
        self.x0_amp = rng.uniform(0.5, 2.0)       # waviness of the blend start line
        self.x0_lam = rng.uniform(15.0, 40.0)
        self.x0_ph = rng.uniform(0, 2 * math.pi)
        self.L1a, self.L1b = rng.uniform(6.0, 9.0), rng.uniform(9.0, 13.0)   # blend 1 length y=0..W
        if rng.random() < 0.5:
            self.L1a, self.L1b = self.L1b, self.L1a
        self.L2a, self.L2b = rng.uniform(5.0, 8.0), rng.uniform(8.0, 11.0)
        self.tha = math.radians(rng.uniform(12.0, 22.0))   # ramp angle at y=0
        self.thb = math.radians(rng.uniform(15.0, 28.0))   # at y=W
        self.H = rng.uniform(5.0, 8.0)                      # plateau height
        self.bump_A = rng.uniform(0.15, 0.45)
        self.bump_lam = rng.uniform(6.0, 10.0)
        self.bump_n = int(rng.integers(1, 3))              # periods in the band
        self.bump_gap = rng.uniform(2.0, 5.0)             # after the ramp-top blend
        self.bump_drift = rng.uniform(0.5, 2.0) * rng.choice([-1, 1])   # phase drift (rad over W)

    def params(self, y):
        t = y / self.W
        x0 = self.x0 + self.x0_amp * math.sin(2 * math.pi * y / self.x0_lam + self.x0_ph)
        L1 = self.L1a + (self.L1b - self.L1a) * t
        L2 = self.L2a + (self.L2b - self.L2a) * t
        s = math.tan(self.tha + (self.thb - self.tha) * t)
        rise_blends = s * (L1 + L2) / 2
        Lr = max(0.0, (self.H - rise_blends) / s)     # straight ramp length
        return x0, L1, L2, s, Lr

    def extent_x(self):
        """x where the bump band ends, max over y"""
        ends = []
        for y in np.linspace(0, self.W, 21):
            x0, L1, L2, s, Lr = self.params(y)
            ends.append(x0 + L1 + Lr + L2 + self.bump_gap + self.bump_n * self.bump_lam)
        return max(ends)


def cl_curve(surf, xs, y, R):
    """ball-end tip z over the line (xs, y): centre = P + R n(P), solved for P per point"""
    h = 1e-4
    px = xs.copy(); py = np.full_like(xs, y)
    for _ in range(30):
        # gradient by central differences (surface is evaluated pointwise in y)
        zx = (zfun(surf, px + h, py) - zfun(surf, px - h, py)) / (2 * h)
        zy = (zfun(surf, px, py + h) - zfun(surf, px, py - h)) / (2 * h)
        nrm = np.sqrt(1 + zx**2 + zy**2)
        nx, ny = -zx / nrm, -zy / nrm
        qx, qy = xs - R * nx, y - R * ny
        d = max(np.abs(qx - px).max(), np.abs(qy - py).max())
        px, py = qx, qy
        if d < 1e-9:
            break
    zP = zfun(surf, px, py)
    nz = 1 / nrm
    return zP + R * nz - R


def zfun(surf, x, y):
    # y varies per point (contact points move off the pass line): evaluate pointwise-vectorised
    x0 = np.empty_like(x); L1 = np.empty_like(x); L2 = np.empty_like(x); s = np.empty_like(x); Lr = np.empty_like(x)
    t = y / surf.W
    x0 = surf.x0 + surf.x0_amp * np.sin(2 * np.pi * y / surf.x0_lam + surf.x0_ph)
    L1 = surf.L1a + (surf.L1b - surf.L1a) * t
    L2 = surf.L2a + (surf.L2b - surf.L2a) * t
    s = np.tan(surf.tha + (surf.thb - surf.tha) * t)
    Lr = np.maximum(0.0, (surf.H - s * (L1 + L2) / 2) / s)
    u = np.clip((x - x0) / L1, 0, 1)
    z = s * L1 * smoothstep_int(u) + s * np.clip(x - x0 - L1, 0, None)
    xa = x0 + L1 + Lr
    v = np.clip((x - xa) / L2, 0, 1)
    z -= s * L2 * smoothstep_int(v) + s * np.clip(x - xa - L2, 0, None)
    xb = xa + L2 + surf.bump_gap
    Lb = surf.bump_n * surf.bump_lam
    w = np.clip((x - xb) / Lb, 0, 1)
    env = np.where((x > xb) & (x < xb + Lb), np.sin(np.pi * w) ** 2, 0.0)
    ph = surf.bump_drift * y / surf.W
    z += surf.bump_A * env * np.sin(2 * np.pi * (x - xb) / surf.bump_lam + ph)
    return z


def max_concave_curv(surf, xs, y):
    z = zfun(surf, xs, np.full_like(xs, y))
    d1 = np.gradient(z, xs); d2 = np.gradient(d1, xs)
    k = d2 / (1 + d1**2) ** 1.5
    return max(0.0, k.max())


def chords(xs, zs, tol):
    """greedy chord fit: indices of kept points; each chord's max deviation <= tol"""
    n = len(xs); keep = [0]; i = 0
    def ok(i, j):
        if j <= i + 1:
            return True
        dx, dz = xs[j] - xs[i], zs[j] - zs[i]
        L = math.hypot(dx, dz)
        d = np.abs((xs[i + 1:j] - xs[i]) * dz - (zs[i + 1:j] - zs[i]) * dx) / L
        return d.max() <= tol
    while i < n - 1:
        # exponential then binary search for the farthest acceptable j
        step = 1; lo = i + 1
        while lo + step < n and ok(i, lo + step):
            lo += step; step *= 2
        hi = min(n - 1, lo + step)
        if ok(i, hi):
            lo = hi
        else:
            while hi - lo > 1:
                mid = (lo + hi) // 2
                if ok(i, mid): lo = mid
                else: hi = mid
        # the deviation is not monotone in j in general: walk forward while still ok (cheap)
        j = lo
        keep.append(j); i = j
    return keep


def fmt(v, nd):
    s = f"{v:.{nd}f}"
    if s.startswith("-") and float(s) == 0:
        s = s[1:]
    return s


def make_program(k, rng, outdir):
    W = float(rng.uniform(15.0, 30.0))
    stepover = float(rng.uniform(0.3, 0.8))
    tol = float(rng.uniform(0.002, 0.010))
    g64p = bool(rng.random() < 0.5)
    nd = int(rng.choice([3, 4]))
    nnum = bool(rng.random() < 0.5)
    comments = bool(rng.random() < 0.5)
    R = float(rng.choice([1.5, 2.0, 2.5, 3.0]))
    surf = Surface(rng, W)
    # fit the plateau + bump band inside ~57 mm: lower H (keeping a straight ramp >= 0) if needed
    for _ in range(50):
        if surf.extent_x() <= 57.0:
            break
        hmin = max(math.tan(max(surf.tha, surf.thb)) * (max(surf.L1a, surf.L1b) + max(surf.L2a, surf.L2b)) / 2, 2.0)
        if surf.H * 0.95 < hmin:
            surf.bump_n = 1
            if surf.extent_x() <= 57.0:
                break
            surf.bump_gap = 2.0
            break
        surf.H *= 0.95
    xstart = 0.0
    xend = float(min(60.0, max(40.0 + rng.uniform(0, 5), surf.extent_x() + rng.uniform(2.0, 4.0))))
    # origin offset (work coordinates as posted)
    ox = float(np.round(rng.uniform(-30, 30), 1)); oy = float(np.round(rng.uniform(-30, 30), 1))
    # run time 30-70 s nominal: pick the feed in range for this raster, else widen the step-over
    for _ in range(100):
        npass = int(math.floor(W / stepover)) + 1
        plen = npass * (xend - xstart) * 1.03 + (npass - 1) * stepover
        fmin = max(1500.0, plen / 70.0 * 60); fmax = min(3500.0, plen / 30.0 * 60)
        if fmin <= fmax:
            break
        if fmin > fmax and plen / 70.0 * 60 > 3500:
            stepover = min(0.8, stepover * 1.05)
            if stepover >= 0.8: W *= 0.95
        else:
            W = min(30.0, W * 1.05)
    feed = int(round(rng.uniform(fmin, fmax) / 50) * 50)
    feed = min(max(feed, 1500), 3500)
    ys = np.arange(npass) * stepover
    W_eff = ys[-1]
    oneway = k in (2, 5)          # one-way with retract on two of the programs
    # concave curvature check: the ball must fit (scale bumps down if needed)
    xs = np.arange(xstart, xend + 1e-9, 0.002)
    for _ in range(20):
        kmax = max(max_concave_curv(surf, xs, y) for y in np.linspace(0, W, 9))
        if kmax * R < 1 / 1.5:
            break
        surf.bump_A *= 0.8
    safe = math.ceil(surf.H + 5)
    lines = []
    def emit(s):
        lines.append(s)
        return len(lines)              # 1-based physical line (before N numbering, same count)
    emit("%")
    emit(f"(T{k} - finishing, ball end mill R{R:g} - blended-ramp transition surface)")
    emit(f"(chord tol {tol*1000:.1f} um, stepover {stepover:.3f} mm, {'one-way' if oneway else 'zig-zag'} raster along X)")
    emit("G21 G90 G17 G40 G49 G80")
    emit("G64 P0.01" if g64p else "G64")
    emit(f"G0 Z{fmt(safe, nd)}")
    passes = []
    tot_len = 0.0
    prev_end = None
    for pi, y in enumerate(ys):
        zc = cl_curve(surf, xs, float(y), R)
        keep = chords(xs, zc, tol)
        px = xs[keep]; pz = zc[keep]
        rev = (not oneway) and (pi % 2 == 1)
        if rev:
            px = px[::-1]; pz = pz[::-1]
        X = px + ox; Y = float(y) + oy
        if comments:
            emit(f"(pass {pi + 1})")
        if pi == 0:
            emit(f"G0 X{fmt(X[0], nd)} Y{fmt(Y, nd)}")
            emit(f"G0 Z{fmt(pz[0] + 2.0, nd)}")
            emit(f"G1 Z{fmt(pz[0], nd)} F{int(feed/3)}")
        elif oneway:
            emit(f"G0 X{fmt(X[0], nd)} Y{fmt(Y, nd)}")
            emit(f"G0 Z{fmt(pz[0] + 2.0, nd)}")
            emit(f"G1 Z{fmt(pz[0], nd)} F{int(feed/3)}")
        else:
            # zig-zag link: step over at the pass end height (G1, at feed)
            emit(f"G1 Y{fmt(Y, nd)}" + (f" Z{fmt(pz[0], nd)}" if fmt(pz[0], nd) != fmt(prev_end, nd) else ""))
        first = None; lastz = pz[0]; lastx = X[0]
        for j in range(1, len(px)):
            words = f"G1 X{fmt(X[j], nd)}"
            if fmt(pz[j], nd) != fmt(lastz, nd):
                words += f" Z{fmt(pz[j], nd)}"
            if first is None:
                words += f" F{feed}"
            ln = emit(words)
            if first is None:
                first = ln
            lastz = pz[j]
        last = len(lines)
        tot_len += abs(X[-1] - X[0])
        passes.append({"pass": pi, "y": round(Y, nd), "first_line": first, "last_line": last,
                       "direction": "-X" if rev else "+X", "moves": last - first + 1})
        prev_end = pz[-1]
        if oneway:
            emit(f"G0 Z{fmt(safe, nd)}")
    if not oneway:
        emit(f"G0 Z{fmt(safe, nd)}")
    emit("M5")
    emit("M2")
    emit("%")
    # N numbers (physical line count unchanged: one block per line)
    if nnum:
        out = []
        n = 10
        for s in lines:
            if s == "%" or s.startswith("("):
                out.append(s)
            else:
                out.append(f"N{n} {s}"); n += 10
        lines = out
    name = f"T{k}"
    with open(os.path.join(outdir, name + ".ngc"), "w") as f:
        f.write("\n".join(lines) + "\n")
    meta = {"program": name + ".ngc", "lines": len(lines), "surface": "blended-ramp (cubic-curvature blends) + plateau bump band",
            "tool_radius": R, "chord_tol_mm": round(tol, 5), "feed": feed,
            "g64": "G64 P0.01" if g64p else "G64", "decimals": nd, "n_numbers": nnum,
            "raster": "one-way with retract" if oneway else "zig-zag", "stepover": round(stepover, 4),
            "n_passes": len(passes), "x_extent": round(xend - xstart, 3), "y_extent": round(float(W_eff), 3),
            "origin": [ox, oy], "safe_z": safe,
            "surface_params": {"x0": surf.x0, "x0_amp": surf.x0_amp, "x0_lam": surf.x0_lam,
                               "L1": [surf.L1a, surf.L1b], "L2": [surf.L2a, surf.L2b],
                               "ramp_deg": [math.degrees(surf.tha), math.degrees(surf.thb)],
                               "H": surf.H, "bump_A": surf.bump_A, "bump_lam": surf.bump_lam,
                               "bump_periods": surf.bump_n, "bump_drift_rad": surf.bump_drift},
            "nominal_cut_time_s": round(tot_len / feed * 60, 1),
            "passes": passes}
    with open(os.path.join(outdir, name + ".passes.json"), "w") as f:
        json.dump(meta, f, indent=1)
    return meta


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seed", type=int, default=20261209)
    ap.add_argument("--count", type=int, default=8)
    ap.add_argument("--out", default="programs/")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rng = np.random.default_rng(a.seed)
    for k in range(a.count):
        m = make_program(k, np.random.default_rng([a.seed, k]), a.out)
        print(f"T{k}: lines={m['lines']} tol={m['chord_tol_mm']*1000:.1f}um F{m['feed']} {m['g64']} "
              f"{m['raster']} passes={m['n_passes']} so={m['stepover']} X={m['x_extent']} Y={m['y_extent']} "
              f"nd={m['decimals']} N={m['n_numbers']} R={m['tool_radius']} nominal={m['nominal_cut_time_s']}s")


if __name__ == "__main__":
    main()
