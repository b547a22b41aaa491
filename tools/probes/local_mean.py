#!/usr/bin/env python3
"""local_mean.py BASE FRAME K [K ...] [--gate]: the energy probe of docs/quality.md ("Energy: a
correction of the displayed frame's local mean"). Reads BASE/T/frame_FRAME.exr (the temporal result:
`asvgf render --history-tap -1 --atrous-iterations 0`) and BASE/F/frame_FRAME.exr (the same
histories filtered: `--history-tap -1`) and writes, for each K, BASE/C<K>/frame_FRAME.exr: F scaled
so that its K x K local mean of luminance is T's. With --gate (BASE/C<K>g/) the scale is shrunk
toward 1 where the box mean of T is not known better than its difference from F's:
1 + g (ratio - 1), g = d^2 / (d^2 + se^2), se^2 = the box's spatial variance of T / K^2."""
import os
import sys

import exr_min


def box1(row, r):
    """Running mean over a window of 2r + 1 clamped at the ends."""
    n = len(row)
    prefix = [0.0] * (n + 1)
    for i, v in enumerate(row):
        prefix[i + 1] = prefix[i] + v
    return [(prefix[min(n, i + r + 1)] - prefix[max(0, i - r)]) / (min(n, i + r + 1) - max(0, i - r)) for i in range(n)]


def box(img, w, h, r):
    rows = [box1(img[y * w:(y + 1) * w], r) for y in range(h)]
    cols = [box1([rows[y][x] for y in range(h)], r) for x in range(w)]
    return [cols[x][y] for y in range(h) for x in range(w)]


def luminance(c):
    return [0.2126 * r + 0.7152 * g + 0.0722 * b for r, g, b in zip(c["R"], c["G"], c["B"])]


def main():
    args = [a for a in sys.argv[1:] if a != "--gate"]
    gate = "--gate" in sys.argv
    if len(args) < 3:
        sys.exit(__doc__)
    base, frame, ks = args[0], int(args[1]), [int(k) for k in args[2:]]
    w, h, t = exr_min.read("%s/T/frame_%04d.exr" % (base, frame))
    fw, fh, f = exr_min.read("%s/F/frame_%04d.exr" % (base, frame))
    if (fw, fh) != (w, h):
        sys.exit("local_mean.py: T and F differ in size at frame %d" % frame)
    lt, lf = luminance(t), luminance(f)
    lt2 = [v * v for v in lt]
    for k in ks:
        bt, bf = box(lt, w, h, k // 2), box(lf, w, h, k // 2)
        bt2 = box(lt2, w, h, k // 2) if gate else bt
        scale = []
        for a, b, a2 in zip(bt, bf, bt2):
            if b <= 1e-6:  # nothing filtered to scale (the background)
                scale.append(1.0)
                continue
            g = 1.0
            if gate:
                d2, se2 = (a - b) ** 2, max(a2 - a * a, 0.0) / (k * k)
                g = d2 / (d2 + se2) if d2 + se2 > 0.0 else 0.0
            scale.append(1.0 + g * (a / b - 1.0))
        out = "%s/C%d%s" % (base, k, "g" if gate else "")
        os.makedirs(out, exist_ok=True)
        exr_min.write("%s/frame_%04d.exr" % (out, frame), w, h, {c: [v * s for v, s in zip(f[c], scale)] for c in "RGB"})


if __name__ == "__main__":
    main()
