#!/usr/bin/env python3
"""Checks the output of `asvgf report` (standard library only).

  report_check.py check DIR [RUN,RUN,...]  every expected run is in report.csv with finite numbers
                                           on every frame; report.md has the headline and the seed's
                                           comparisons; every PNG is valid, non-empty, not flat
  report_check.py same DIR1 DIR2           report.csv equal except the GPU-time columns (*_ms)
  report_check.py differ DIR1 DIR2         the error columns differ (another seed)
  report_check.py noise SAME OTHER_BACKEND OTHER_SEED
                                           per run and error column (relMSE, SSIM, temporal error),
                                           the run means, summed over runs, move less between SAME
                                           and OTHER_BACKEND (same seed) than between SAME and
                                           OTHER_SEED: the backend is within the seed's noise
  report_check.py timed DIR                every row has a positive whole-frame GPU time
  report_check.py scenes DIR SCENES RUNS   asvgf report --scenes: each scene's folder passes `check`
                                           with RUNS; summary.csv has every scene x run with finite
                                           errors; summary.md has a table row per scene and shown
                                           method, linking the scene's report.md
  report_check.py runs DIR A B same|differ
                                           run A's error columns equal run B's on every frame, or
                                           differ in relMSE on some frame (asvgf report --run)
  report_check.py energy DIR               report.md's energy bias is a number for every run, and for
                                           runs without a history (raw, accum-*) the ratio of
                                           report.csv's mean to reference_mean over all frames, minus 1
  report_check.py corrects-energy DIR A B [FRACTION]  run B's |energy bias| in report.md is at most
                                           FRACTION (default 2/3) of run A's, and its mean relMSE in
                                           report.csv is lower
"""
import csv
import math
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from png_chunks import png_chunks  # noqa: E402

ERROR_COLUMNS = ["relmse", "ssim", "temporal", "mean", "reference_mean"]


def fail(msg):
    print("report_check: FAIL: " + msg)
    sys.exit(1)


def read_csv(directory):
    path = os.path.join(directory, "report.csv")
    if not os.path.isfile(path):
        fail(path + " is missing")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail(path + " has no rows")
    return rows


def decode_png(path):
    """Returns (width, height, set of distinct pixels); fails on anything but a valid 8-bit PNG."""
    try:
        chunks = png_chunks(open(path, "rb").read())
    except ValueError as e:
        fail(path + ": " + str(e))
    ihdr = next((struct.unpack(">IIBBBBB", body) for kind, body in chunks if kind == b"IHDR"), None)
    idat = b"".join(body for kind, body in chunks if kind == b"IDAT")
    if ihdr is None:
        fail(path + ": no IHDR")
    w, h, depth, colour = ihdr[:4]
    if w == 0 or h == 0:
        fail(path + ": IHDR size is %dx%d" % (w, h))
    channels = {6: 4, 2: 3, 0: 1, 4: 2}.get(colour)
    if depth != 8 or channels is None:
        fail(path + ": unexpected bit depth %d / colour type %d" % (depth, colour))
    raw = zlib.decompress(idat)
    stride = w * channels
    if len(raw) != h * (stride + 1):
        fail(path + ": image data has %d bytes, expected %d" % (len(raw), h * (stride + 1)))
    prev, pixels, i = bytearray(stride), set(), 0
    for _ in range(h):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += stride + 1
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
            elif f != 0:
                fail(path + ": unknown filter %d" % f)
        for x in range(0, stride, channels * 7):  # a sample of pixels is enough to see it is not flat
            pixels.add(bytes(line[x:x + channels]))
        prev = line
    return w, h, pixels


def finite(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def check(directory, expected):
    rows = read_csv(directory)
    runs = {}
    for row in rows:
        runs.setdefault(row["run"], []).append(row)
    for name in expected:
        if name not in runs:
            fail("run %s is not in report.csv (runs: %s)" % (name, ", ".join(runs)))
    frames = {len(v) for v in runs.values()}
    if len(frames) != 1:
        fail("runs have different frame counts: %s" % frames)
    for name, rs in runs.items():
        for row in rs:
            for col in ERROR_COLUMNS:
                if col == "temporal" and row["frame"] == "0":
                    if row[col] != "":
                        fail("%s frame 0: temporal error should be empty (no previous frame)" % name)
                    continue
                if not finite(row[col]):
                    fail("%s frame %s: %s is %r, not a finite number" % (name, row["frame"], col, row[col]))
            if row["gpu_ms"] != "" and not finite(row["gpu_ms"]):
                fail("%s frame %s: gpu_ms is %r" % (name, row["frame"], row["gpu_ms"]))
            # The pixel classes partition the frame: edges, coloured and grey surfaces hold at most
            # its relMSE (background holds the rest), and a class with pixels has a number.
            parts, shares = 0.0, 0.0
            for cls in ["edges", "coloured", "grey"]:
                share = float(row[cls + "_fraction"])
                if share > 0 and not finite(row["relmse_" + cls]):
                    fail("%s frame %s: relmse_%s is %r" % (name, row["frame"], cls, row["relmse_" + cls]))
                parts += share * float(row["relmse_" + cls]) if share > 0 else 0.0
                shares += share
            if shares > 1 + 1e-6 or parts > float(row["relmse"]) * (1 + 1e-6) + 1e-12:
                fail("%s frame %s: the pixel classes hold %g of relMSE %s over %g of the pixels"
                     % (name, row["frame"], parts, row["relmse"], shares))
    md_path = os.path.join(directory, "report.md")
    if not os.path.isfile(md_path):
        fail("report.md is missing")
    md = open(md_path, encoding="utf-8").read()
    for needle in ["of plain accumulation", "### 1 spp, EMA 0.2, EMA 0.05 (ghosting), SVGF, A-SVGF and the reference",
                   "### 9 against 15 à-trous iterations", "### Constant against adaptive α",
                   "### Where the error is: edges, coloured and grey surfaces", "## Definitions"]:
        if needle not in md:
            fail("report.md lacks %r" % needle)
    pngs = sorted(f for f in os.listdir(directory) if f.endswith(".png"))
    for want in ["error_vs_time.png", "relmse_per_frame.png", "temporal_per_frame.png", "ssim_per_frame.png",
                 "crops.png", "error_maps.png"]:
        if want not in pngs:
            fail(want + " is missing")
    for name in pngs:
        if "(" + name + ")" not in md:
            fail("report.md does not link " + name)
        w, h, pixels = decode_png(os.path.join(directory, name))
        if len(pixels) < 3:
            fail("%s (%dx%d) is flat: %d distinct colours" % (name, w, h, len(pixels)))
        print("%s: %dx%d, %d+ colours" % (name, w, h, len(pixels)))
    print("report_check: ok: %d runs x %d frames, %d plots" % (len(runs), frames.pop(), len(pngs)))


def scenes(directory, names, runs):
    for name in names:
        check(os.path.join(directory, name), runs)
    path = os.path.join(directory, "summary.csv")
    if not os.path.isfile(path):
        fail(path + " is missing")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    seen = {(row["scene"].split("/")[0], row["run"]) for row in rows}
    for name in names:
        for run in runs:
            if (name, run) not in seen:
                fail("summary.csv has no row for scene %s, run %s" % (name, run))
    for row in rows:
        for col in ["mean_relmse", "mean_ssim", "mean_temporal"]:
            if not finite(row[col]):
                fail("summary.csv %s %s: %s is %r" % (row["scene"], row["run"], col, row[col]))
    md_path = os.path.join(directory, "summary.md")
    if not os.path.isfile(md_path):
        fail("summary.md is missing")
    md = open(md_path, encoding="utf-8").read()
    shown = [r for r in runs if not r.startswith("accum")]
    for name in names:
        for run in shown:
            needle = "](%s/report.md) | %s |" % (name, run)
            if needle not in md:
                fail("summary.md has no row %r" % needle)
    # The material sections: their table has a finite asvgf row in the scene that has such materials,
    # and the room (neither) says it has none.
    sections = [("textured", "| relMSE textured | relMSE untextured |", 3, "has no albedo textures"),
                ("glossy", "| relMSE glossy | relMSE matte |", 3, "has no glossy materials")]
    for scene, header, columns, none in sections:
        if scene in names:
            md = open(os.path.join(directory, scene, "report.md"), encoding="utf-8").read()
            if header not in md:
                fail("%s/report.md has no %s table" % (scene, scene))
            table = md[md.index(header):].split("\n\n")[0]
            row = next((line for line in table.splitlines() if line.startswith("| `asvgf` | ")), None)
            if row is None or not all(finite(cell) for cell in row.split("|")[2:2 + columns]):
                fail("%s/report.md: the asvgf row of the %s table is %r" % (scene, scene, row))
            # Where raw ran, the glossy table's ratio less the reference's noise: a number, or n/a
            # where asvgf's error is within that noise.
            if "less the reference's noise" in table.splitlines()[0]:
                cell = row.split("|")[5].strip()
                if not (finite(cell) or cell == "n/a"):
                    fail("%s/report.md: asvgf's glossy / matte less the reference's noise is %r" % (scene, cell))
    if "glossy" in names:  # light-exit changes the scene: crops where the reflections change most
        decode_png(os.path.join(directory, "glossy", "crops_glossy.png"))
        if "cornell" in names:
            md = open(os.path.join(directory, "cornell", "report.md"), encoding="utf-8").read()
            if none not in md:
                fail("cornell/report.md does not say the scene %s" % none)
    print("report_check: ok: %d scenes x %d runs in summary.csv, %d table rows" % (
        len(names), len(runs), len(names) * len(shown)))


def numbers(directory):
    rows = read_csv(directory)
    keep = [c for c in rows[0].keys() if not c.endswith("_ms")]
    return keep, [[row[c] for c in keep] for row in rows]


def same(a, b):
    ka, ra = numbers(a)
    kb, rb = numbers(b)
    if ka != kb or len(ra) != len(rb):
        fail("columns or row counts differ")
    for i, (x, y) in enumerate(zip(ra, rb)):
        if x != y:
            diff = [c for c, u, v in zip(ka, x, y) if u != v]
            fail("row %d (%s frame %s) differs in %s" % (i + 2, x[0], x[ka.index("frame")], diff))
    print("report_check: ok: %d rows identical apart from the GPU-time columns" % len(ra))


def differ(a, b):
    """Compares the rows both reports have (same run and frame); b may hold fewer runs."""
    ra = {(r["run"], r["frame"]): r["relmse"] for r in read_csv(a)}
    rb = {(r["run"], r["frame"]): r["relmse"] for r in read_csv(b)}
    common = [k for k in rb if k in ra]
    if not common:
        fail("the reports share no run and frame")
    changed = sum(1 for k in common if ra[k] != rb[k])
    if changed == 0:
        fail("relMSE is identical in every shared row: the seed changes nothing")
    print("report_check: ok: %d of %d shared rows differ in relMSE" % (changed, len(common)))


def runs(directory, a, b, want):
    rows = read_csv(directory)
    columns = ["relmse", "ssim", "temporal", "mean"]
    ra = {r["frame"]: [r[c] for c in columns] for r in rows if r["run"] == a}
    rb = {r["frame"]: [r[c] for c in columns] for r in rows if r["run"] == b}
    if not ra or not rb or sorted(ra) != sorted(rb):
        fail("runs %s and %s are not both in report.csv over the same frames" % (a, b))
    equal = [f for f in ra if ra[f] == rb[f]]
    if want == "same" and len(equal) != len(ra):
        fail("%s and %s differ on %d of %d frames" % (a, b, len(ra) - len(equal), len(ra)))
    if want == "differ" and all(ra[f][0] == rb[f][0] for f in ra):
        fail("%s and %s have the same relMSE on every frame: the settings changed nothing" % (a, b))
    print("report_check: ok: %s and %s %s over %d frames" % (a, b, "equal" if want == "same" else "differ", len(ra)))


def noise(same_dir, backend_dir, seed_dir):
    def means(directory):
        sums = {}
        for r in read_csv(directory):
            for column in ("relmse", "ssim", "temporal"):
                if r[column] == "":  # no temporal error on a run's first frame
                    continue
                total, n = sums.get((r["run"], column), (0.0, 0))
                sums[(r["run"], column)] = (total + float(r[column]), n + 1)
        return {k: total / n for k, (total, n) in sums.items()}

    base, backend, seed = means(same_dir), means(backend_dir), means(seed_dir)
    keys = sorted(k for k in base if k in backend and k in seed)
    if not keys:
        fail("the reports share no run")
    by_column = {}
    for run, column in keys:
        moved, noise_scale = by_column.get(column, (0.0, 0.0))
        by_column[column] = (moved + abs(base[(run, column)] - backend[(run, column)]),
                             noise_scale + abs(base[(run, column)] - seed[(run, column)]))
    for column, (moved, noise_scale) in sorted(by_column.items()):
        if noise_scale == 0.0:
            fail(column + ": another seed changes nothing, so there is no noise to compare with")
        print("report_check: %s: the backend moves the run means by %.3g in all, another seed by %.3g (ratio %.2f)"
              % (column, moved, noise_scale, moved / noise_scale))
        if moved >= noise_scale:
            fail(column + ": the backend moves the numbers as much as another seed or more")
    print("report_check: ok: %d runs within noise" % len({run for run, _ in keys}))


def timed(directory):
    """Every row of report.csv has a finite, positive whole-frame GPU time."""
    rows = read_csv(directory)
    for row in rows:
        if not finite(row["gpu_ms"]) or float(row["gpu_ms"]) <= 0:
            fail("%s frame %s: gpu_ms is %r, not a positive time" % (row["run"], row["frame"], row["gpu_ms"]))
    print("report_check: ok: %d rows timed" % len(rows))


def shown_energy(directory):
    """Each run's energy bias in percent, as report.md's run table shows it."""
    md = open(os.path.join(directory, "report.md"), encoding="utf-8").read()
    header = next((l for l in md.splitlines() if l.startswith("| run |") and "energy bias" in l), None)
    if header is None:
        fail("report.md has no run table with an energy bias column")
    col = [c.strip() for c in header.split("|")].index("energy bias")
    shown = {}
    for line in md.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > col and cells[1].startswith("`") and "%" in cells[col]:
            shown[cells[1].strip("`")] = float(cells[col].split("%")[0])
    return shown


def energy(directory):
    rows = read_csv(directory)
    shown = shown_energy(directory)
    runs = {r["run"] for r in rows}
    for name in sorted(runs):
        if name not in shown:
            fail("run %s has no energy bias in report.md" % name)
        if name == "raw" or name.startswith("accum-"):
            rs = [r for r in rows if r["run"] == name and float(r["reference_mean"]) > 0]
            want = 100.0 * (sum(float(r["mean"]) for r in rs) / sum(float(r["reference_mean"]) for r in rs) - 1.0)
            if abs(want - shown[name]) > 0.006:
                fail("%s: energy bias %.2f%% in report.md, %.4f%% from report.csv" % (name, shown[name], want))
    print("report_check: ok: energy bias of %d runs: %s" % (len(shown), ", ".join(
        "%s %+.2f%%" % (n, shown[n]) for n in sorted(shown))))


def corrects_energy(directory, a, b, fraction=2.0 / 3.0):
    """Run b's |energy bias| in report.md is at most `fraction` of run a's, and its mean relMSE in
    report.csv is lower."""
    shown = shown_energy(directory)
    rows = read_csv(directory)
    for name in (a, b):
        if name not in shown:
            fail("run %s has no energy bias in report.md" % name)
    relmse = {n: sum(float(r["relmse"]) for r in rows if r["run"] == n) for n in (a, b)}
    if not abs(shown[b]) <= abs(shown[a]) * fraction:
        fail("%s's energy bias %+.2f%% is not within %.2f of %s's %+.2f%%" % (b, shown[b], fraction, a, shown[a]))
    if not relmse[b] < relmse[a]:
        fail("%s's relMSE (sum over frames %.4g) is not below %s's (%.4g)" % (b, relmse[b], a, relmse[a]))
    print("report_check: ok: energy bias %s %+.2f%%, %s %+.2f%%; relMSE summed over frames %.4g, %.4g" % (
        a, shown[a], b, shown[b], relmse[a], relmse[b]))


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "check":
        check(sys.argv[2], sys.argv[3].split(",") if len(sys.argv) > 3 and sys.argv[3] else [])
    elif len(sys.argv) == 5 and sys.argv[1] == "noise":
        noise(sys.argv[2], sys.argv[3], sys.argv[4])
    elif len(sys.argv) == 3 and sys.argv[1] == "timed":
        timed(sys.argv[2])
    elif len(sys.argv) == 5 and sys.argv[1] == "scenes":
        scenes(sys.argv[2], sys.argv[3].split(","), sys.argv[4].split(","))
    elif len(sys.argv) == 6 and sys.argv[1] == "runs" and sys.argv[5] in ("same", "differ"):
        runs(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5])
    elif len(sys.argv) == 3 and sys.argv[1] == "energy":
        energy(sys.argv[2])
    elif len(sys.argv) in (5, 6) and sys.argv[1] == "corrects-energy":
        corrects_energy(sys.argv[2], sys.argv[3], sys.argv[4], *(float(x) for x in sys.argv[5:]))
    elif len(sys.argv) == 4 and sys.argv[1] in ("same", "differ"):
        (same if sys.argv[1] == "same" else differ)(sys.argv[2], sys.argv[3])
    else:
        print(__doc__)
        sys.exit(2)
