#!/usr/bin/python3
"""measure_recording.py - speed figures of a LinuxCNC halsampler recording of a raster finishing program.

usage: python3 measure_recording.py REC.txt PASSES.json [--box X0,Y0,X1,Y1] [--program P.ngc] [--json OUT.json]

REC.txt: halsampler text, one row per 1 ms servo cycle: idx x y z line cur-vel req-vel running.
Only the positions (and the line column) are used; speeds are computed from positions.
PASSES.json: {"passes": [{"pass": k, "first_line": a, "last_line": b}, ...]} (1-based physical
lines of the pass's cutting moves); a bare list of such objects is accepted too.

Figures (all speeds in mm/min):
  machining_time_s   (last sample whose position differs from its predecessor) - (last sample
                     before the first change), times 1 ms
  path speed v[i]    |p[i+1]-p[i-1]| / 2 ms (one-sided at the two ends)
  fluctuation_rms    RMS of v - MA101(v) over cutting samples (MA101: centred 101-sample = 100 ms
                     moving average of v over the whole recording, shrunk at the recording ends)
  inconsistency      per cutting sample of pass k: |v - v(nearest XY sample of pass k-1)| and
                     the same for k+1 (where they exist); the larger; p99 (nearest rank) and mean
  cutting sample     a sample whose program line (shifted by one cycle to undo the line column's
                     one-cycle lag; --no-lag-shift keeps it raw) is within a pass's [first,last]
  --box              restricts fluctuation and inconsistency to samples with x0<=x<=x1, y0<=y<=y1
                     (the neighbour samples may be anywhere on their pass)
"""
import sys, os
try:
    import numpy as np
except ImportError:
    if sys.executable != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise
import argparse, json, math, re

DT = 0.001


def load_rec(path):
    rows = []; overruns = 0
    with open(path) as f:
        for s in f:
            p = s.split()
            if not p:
                continue
            if not p[0].lstrip("-").isdigit():
                overruns += 1; continue
            if len(p) < 5:
                continue
            rows.append([float(v) if v not in ("TRUE", "FALSE") else float(v == "TRUE") for v in p[:8]])
    a = np.array(rows)
    return a, overruns


def load_passes(path):
    d = json.load(open(path))
    ps = d["passes"] if isinstance(d, dict) else d
    out = []
    for i, p in enumerate(ps):
        out.append((int(p.get("pass", i)), int(p["first_line"]), int(p["last_line"])))
    out.sort()
    return out


def program_info(path):
    """physical line count and the final commanded XYZ (modal G0/G1 words, absolute mode)"""
    n = 0; pos = [0.0, 0.0, 0.0]
    for s in open(path):
        n += 1
        s = re.sub(r"\(.*?\)", "", s.split(";")[0]).upper()
        for ax, i in (("X", 0), ("Y", 1), ("Z", 2)):
            m = re.search(ax + r"\s*([-+]?\d*\.?\d+)", s)
            if m:
                pos[i] = float(m.group(1))
    return n, pos


def nearest_speed(qxy, nxy, nv, chunk=2000):
    """speed of the nearest (XY) neighbour sample for each query point (brute force, chunked)"""
    out = np.empty(len(qxy))
    for a in range(0, len(qxy), chunk):
        q = qxy[a:a + chunk]
        d2 = (q[:, None, 0] - nxy[None, :, 0]) ** 2 + (q[:, None, 1] - nxy[None, :, 1]) ** 2
        out[a:a + chunk] = nv[np.argmin(d2, axis=1)]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rec"); ap.add_argument("passes")
    ap.add_argument("--box", help="X0,Y0,X1,Y1")
    ap.add_argument("--program", help="the .ngc (line count, end-position check)")
    ap.add_argument("--json", help="output JSON file")
    ap.add_argument("--window", type=int, default=101, help="moving-average window, samples (default 101 = 100 ms centred)")
    ap.add_argument("--no-lag-shift", action="store_true")
    argv = sys.argv[1:]                          # allow "--box -8.3,..." (a negative first number)
    for i in range(len(argv) - 1):
        if argv[i] == "--box":
            argv[i:i + 2] = ["--box=" + argv[i + 1]]
            break
    a = ap.parse_args(argv)

    A, overruns = load_rec(a.rec)
    P = A[:, 1:4]; line = A[:, 4].astype(int); n = len(A)
    if not a.no_lag_shift:                      # line at row i+1 describes the motion of row i
        line = np.append(line[1:], line[-1])

    # machining time
    ch = np.any(P[1:] != P[:-1], axis=1)
    idx_ch = np.nonzero(ch)[0] + 1
    f, l = idx_ch[0], idx_ch[-1]
    mtime = (A[l, 0] - A[f - 1, 0]) * DT

    # path speed
    v = np.empty(n)
    v[1:-1] = np.linalg.norm(P[2:] - P[:-2], axis=1) / (2 * DT)
    v[0] = np.linalg.norm(P[1] - P[0]) / DT; v[-1] = np.linalg.norm(P[-1] - P[-2]) / DT
    v *= 60.0                                   # mm/min

    # centred moving average (shrinking window at the ends)
    h = a.window // 2
    cs = np.concatenate([[0.0], np.cumsum(v)])
    lo = np.clip(np.arange(n) - h, 0, n); hi = np.clip(np.arange(n) + h + 1, 0, n)
    ma = (cs[hi] - cs[lo]) / (hi - lo)
    resid = v - ma

    passes = load_passes(a.passes)
    pass_of = np.full(n, -1)
    for k, (pid, fl, ll) in enumerate(passes):
        pass_of[(line >= fl) & (line <= ll)] = k
    cut = pass_of >= 0

    if a.box:
        x0, y0, x1, y1 = [float(t) for t in a.box.split(",")]
        x0, x1 = min(x0, x1), max(x0, x1); y0, y1 = min(y0, y1), max(y0, y1)
        inbox = (P[:, 0] >= x0) & (P[:, 0] <= x1) & (P[:, 1] >= y0) & (P[:, 1] <= y1)
    else:
        inbox = np.ones(n, bool)
    sel = cut & inbox
    fluct = float(np.sqrt(np.mean(resid[sel] ** 2))) if sel.any() else None

    # inconsistency between neighbouring passes
    diffs = []
    samples_per_pass = []
    for k in range(len(passes)):
        mk = pass_of == k
        samples_per_pass.append(int(mk.sum()))
        q = np.nonzero(mk & inbox)[0]
        if len(q) == 0:
            continue
        best = np.full(len(q), -np.inf)
        for nb in (k - 1, k + 1):
            if nb < 0 or nb >= len(passes):
                continue
            mn = np.nonzero(pass_of == nb)[0]
            if len(mn) == 0:
                continue
            vn = nearest_speed(P[q, :2], P[mn, :2], v[mn])
            best = np.maximum(best, np.abs(v[q] - vn))
        diffs.append(best[np.isfinite(best)])
    diffs = np.concatenate(diffs) if diffs else np.array([])
    if len(diffs):
        ds = np.sort(diffs)
        p99 = float(ds[max(0, math.ceil(0.99 * len(ds)) - 1)])
        dmean = float(ds.mean())
    else:
        p99 = dmean = None

    res = {
        "recording": a.rec, "passes_file": a.passes, "box": a.box,
        "samples": int(n), "overruns": overruns,
        "machining_time_s": round(float(mtime), 3),
        "max_path_speed_mm_min": round(float(v.max()), 2),
        "fluctuation_rms_mm_min": None if fluct is None else round(fluct, 3),
        "inconsistency_p99_mm_min": None if p99 is None else round(p99, 3),
        "inconsistency_mean_mm_min": None if dmean is None else round(dmean, 3),
        "cutting_samples": int(cut.sum()), "selected_samples": int(sel.sum()),
        "inconsistency_samples": int(len(diffs)),
        "n_passes": len(passes), "passes_without_samples": [passes[k][0] for k, c in enumerate(samples_per_pass) if c == 0],
        "median_cut_speed_mm_min": round(float(np.median(v[cut])), 2) if cut.any() else None,
        "lag_shift": not a.no_lag_shift, "ma_window_samples": a.window,
        "end_position": [round(float(t), 4) for t in P[-1]],
    }
    if a.program:
        nl, endp = program_info(a.program)
        res["program"] = a.program
        res["program_lines"] = nl
        res["program_end_position"] = endp
        res["complete"] = bool(np.allclose(P[-1], endp, atol=1e-3))
    txt = json.dumps(res, indent=1)
    if a.json:
        with open(a.json, "w") as fo:
            fo.write(txt + "\n")
    print(txt)


if __name__ == "__main__":
    main()
