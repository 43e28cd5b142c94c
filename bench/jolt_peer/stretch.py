#!/usr/bin/env python3
"""Largest and mean structural stretch (length / spacing) of a row,col,x,y,z[,...] CSV dump."""
import csv, math, sys
path, spacing = sys.argv[1], float(sys.argv[2])
pos = {}
with open(path) as f:
    r = csv.reader(f); next(r)
    for row in r:
        pos[(int(row[0]), int(row[1]))] = tuple(map(float, row[2:5]))
n = 1 + max(k[0] for k in pos)
worst, total, count = 0.0, 0.0, 0
for (i, j), p in pos.items():
    for q in ((i + 1, j), (i, j + 1)):
        if q in pos:
            s = math.dist(p, pos[q]) / spacing
            worst = max(worst, s); total += s; count += 1
print(f"max {worst:.4f} mean {total / count:.5f}")
