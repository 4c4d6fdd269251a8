#!/usr/bin/python3
"""Checks the two exact limits of talus-cg --time-smoothing (Fields/TimeSmoothing.h) end to end,
on the text of the CSV files (12 significant digits, so bitwise equal sums print identically):

- Heaviside wider than the window: every output block (one per frame) holds the rows of the
  --time-average file (the same sums added in the same order and divided by the frame count);
- a kernel whose support is below the frame spacing: the file equals the per-frame output.

usage: checkTimeSmoothing.py AVERAGE.csv HEAVISIDE.csv FRAMES.csv NARROW.csv
"""
import sys


def rows(path):
    with open(path) as f:
        lines = [line.rstrip('\n') for line in f if not line.startswith('#')]
    return lines[0].split(','), lines[1:]


def main():
    average_path, heaviside_path, frames_path, narrow_path = sys.argv[1:5]
    failures = []
    names, average = rows(average_path)
    names_h, heaviside = rows(heaviside_path)
    if names_h != ['t'] + names:
        failures.append(f"{heaviside_path}: columns {names_h[:4]}... are not t and those of {average_path}")
    blocks = len(heaviside) // len(average)
    if blocks * len(average) != len(heaviside) or blocks < 2:
        failures.append(f"{heaviside_path}: {len(heaviside)} rows are not whole blocks of {len(average)}")
    for b in range(blocks):
        block = [row.split(',', 1)[1] for row in heaviside[b * len(average):(b + 1) * len(average)]]
        if block != average:
            failures.append(f"{heaviside_path}: block {b} differs from the time average")
    _, frames = rows(frames_path)
    _, narrow = rows(narrow_path)
    if frames != narrow:
        failures.append(f"{narrow_path}: differs from the per-frame output {frames_path}")
    if failures:
        sys.exit("time smoothing failed:\n" + "\n".join(failures))
    print(f"time smoothing ok: {blocks} Heaviside blocks = the time average, narrow kernel = the {len(frames)} frame rows")


main()
