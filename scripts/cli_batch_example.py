#!/usr/bin/env python3
"""Writes the batch example of docs/cli.md: N `lac g1` problems (points,alpha), one per CSV row,
deterministic (seed 1), with every K-th row invalid in one of three ways (a non-number alpha, two
control points instead of three, the tangent intersection on the start point).

    python3 scripts/cli_batch_example.py [--rows 1000] [--invalid-every 250] > g1_rows.csv
"""
import argparse
import math
import random


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, default=1000)
    ap.add_argument("--invalid-every", type=int, default=250, help="0: no invalid rows")
    args = ap.parse_args()
    rng = random.Random(1)
    print("points,alpha")
    bad = ['"0,0 0.5,0 1,0.3",abc', '"0,0 0.5,0",1', '"0,0 0,0 1,0.3",1']
    for row in range(1, args.rows + 1):
        x, y, alpha = rng.uniform(0.3, 0.7), rng.uniform(0.1, 0.6), rng.uniform(-2, 2)
        if abs(alpha) < 0.1:  # the G1 solver takes alpha = 0 or 0.1 <= |alpha| <= 5
            alpha += math.copysign(0.1, alpha)
        if args.invalid_every and row % args.invalid_every == 0:
            print(bad[(row // args.invalid_every - 1) % len(bad)])
        else:
            print(f'"0,0 {x:.6g},0 1,{y:.6g}",{alpha:.6g}')


if __name__ == "__main__":
    main()
