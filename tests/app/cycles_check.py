#!/usr/bin/env python3
"""cycles_check.py DIR: checks the relMSE that `asvgf denoise --from cycles` measured on the committed
Cycles sequence (tests/data/cycles: 8 frames, the light switches off at frame 5), with DIR/raw,
DIR/svgf and DIR/asvgf holding each run's metrics.csv (raw: svgf with no filtering). Measured on
lavapipe (frames 2-4 lit / 5-8 after the change, mean relMSE): raw 0.539 / 0.0030, svgf 0.183 /
9.42, asvgf 0.191 / 0.0134. Mutants: the colour taken as demodulated (no division by the albedo)
3.19 on the lit frames; asvgf without its gradient is svgf.
  - lit frames: svgf and asvgf at most half of raw's error (the filters work on Cycles' radiance);
  - after the light change: asvgf at most 1/100 of svgf's (the gradient drops the stale history).
"""
import csv
import os
import sys


def means(path):
    rows = list(csv.DictReader(open(os.path.join(path, "metrics.csv"))))
    errors = {int(r["frame"]): float(r["relmse"]) for r in rows}
    lit = sum(errors[f] for f in (2, 3, 4)) / 3
    dark = sum(errors[f] for f in (5, 6, 7, 8)) / 4
    return lit, dark


def main():
    base = sys.argv[1]
    raw, svgf, asvgf = (means(os.path.join(base, m)) for m in ("raw", "svgf", "asvgf"))
    print("cycles_check: lit frames raw %.4f svgf %.4f asvgf %.4f; after the light change raw %.4f svgf %.4f asvgf %.4f"
          % (raw[0], svgf[0], asvgf[0], raw[1], svgf[1], asvgf[1]))
    problems = []
    if not svgf[0] <= raw[0] / 2:
        problems.append("svgf's error on the lit frames is not below half of raw's")
    if not asvgf[0] <= raw[0] / 2:
        problems.append("asvgf's error on the lit frames is not below half of raw's")
    if not asvgf[1] <= svgf[1] / 100:
        problems.append("asvgf's error after the light change is not below 1/100 of svgf's")
    for p in problems:
        print("cycles_check: FAIL: " + p)
    if problems:
        sys.exit(1)
    print("cycles_check: ok")


if __name__ == "__main__":
    main()
