#!/usr/bin/python3
"""Re-scores a recorded session with a metric written in Python (docs/python.md).

`imasim run --record FILE.csv` writes each instrument's tip at 60 Hz (columns in FILE.json).
This reads it with numpy and scores each instrument by a metric the simulator does not have:
its path length, and its economy of motion (path length over the straight distance covered).

    /usr/bin/python3 python/examples/rescore.py FILE.csv
"""

import argparse
import csv

import numpy as np


def read_recording(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    return rows


def tips(rows, tool):
    return np.array([[float(r[f"{tool}_{c}"]) for c in "xyz"] for r in rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("recording", help="FILE.csv from imasim run --record")
    args = parser.parse_args()
    rows = read_recording(args.recording)
    duration = float(rows[-1]["t_s"]) - float(rows[0]["t_s"])
    print(f"{args.recording}: {len(rows)} rows over {duration:.2f} s")
    for tool in ("forceps", "hook"):
        x = tips(rows, tool)
        path = float(np.linalg.norm(np.diff(x, axis=0), axis=1).sum())
        straight = float(np.linalg.norm(x[-1] - x[0]))
        economy = path / straight if straight > 0 else float("inf")
        print(f"{tool}: path length {path * 1000:.1f} mm, straight {straight * 1000:.1f} mm, "
              f"economy of motion {economy:.2f}")


if __name__ == "__main__":
    main()
