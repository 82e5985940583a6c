#!/usr/bin/env python3
"""Counts coverage buckets from an `oscsim batch` results table, independently of oscsim's
own count (crates/batch/src/coverage.rs): a check of coverage.csv by the table alone.

Usage: coverage_count.py RESULTS.csv SPEC...
  SPEC  NAME=range:LOW:HIGH:EVERY   buckets [LOW+k*EVERY, LOW+(k+1)*EVERY), the last ending at
                                    HIGH and including it (the item's unit, as the table's)
        NAME=members:A,B,...        one bucket per member
Prints one line per bucket, `NAME,LOW,HIGH,HITS` for a range bucket and `NAME,MEMBER,,HITS` for
a member, in the order of the specs; a sample of column `cover:NAME` (cells split at `;`) is
a hit of the bucket that holds it, counted in exact decimal arithmetic. Rows of failed
variants (a non-empty `error` cell) and `no value` samples count nowhere.
"""

import csv
import sys
from decimal import Decimal


def buckets(spec):
    name, _, rule = spec.partition("=")
    kind, _, args = rule.partition(":")
    if kind == "range":
        low, high, every = (Decimal(x) for x in args.split(":"))
        out, start = [], low
        while start < high:
            end = min(start + every, high)
            out.append((start, end, end == high))
            start = end
        return name, "range", out
    if kind == "members":
        return name, "members", args.split(",")
    raise SystemExit(f"expected NAME=range:… or NAME=members:…, found {spec!r}")


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    for spec in argv[2:]:
        name, kind, defs = buckets(spec)
        hits = [0] * len(defs)
        for row in rows:
            if row["error"]:
                continue
            cell = row[f"cover:{name}"]
            for sample in cell.split(";") if cell else []:
                if sample == "no value":
                    continue
                for k, d in enumerate(defs):
                    if kind == "members":
                        hit = sample == d
                    else:
                        x = Decimal(sample)
                        low, high, closed = d
                        hit = low <= x and (x < high or (closed and x == high))
                    if hit:
                        hits[k] += 1
                        break
        for d, h in zip(defs, hits):
            if kind == "members":
                print(f"{name},{d},,{h}")
            else:
                print(f"{name},{d[0].normalize():f},{d[1].normalize():f},{h}")


if __name__ == "__main__":
    main(sys.argv)
