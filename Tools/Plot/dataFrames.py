"""Reading one frame of a .data file (Documentation/FileFormats/data.md) for the plotting
scripts: the frame closest to a wanted time, with errors that name the file and line."""
import sys

import numpy as np


def read_frame(path, wanted, program):
    """(time, rows, header) of the frame of `path` closest to time `wanted` (None: the last):
    rows the particle lines as an array of 14 columns, header the 8 numbers of its first line
    (N t xmin ymin zmin xmax ymax zmax). `program` names the caller in error messages."""
    best = None
    with open(path) as f:
        line_number = 0
        while True:
            header = f.readline()
            line_number += 1
            if not header:
                break
            fields = header.split()
            if len(fields) != 8:
                sys.exit(f"{program}: {path} line {line_number}: expected a frame header of 8 fields")
            count, time = int(fields[0]), float(fields[1])
            lines = [f.readline() for _ in range(count)]
            if count and not lines[-1]:
                sys.exit(f"{program}: {path}: the frame at t = {time} is truncated")
            line_number += count
            if wanted is None or best is None or abs(time - wanted) <= abs(best[0] - wanted):
                best = (time, lines, [float(v) for v in fields])
    if best is None:
        sys.exit(f"{program}: {path} holds no frame")
    rows = np.loadtxt(best[1], ndmin=2)
    if rows.shape[1] < 14:
        sys.exit(f"{program}: {path}: the frame at t = {best[0]} has {rows.shape[1]} columns, not 14")
    return best[0], rows, best[2]
