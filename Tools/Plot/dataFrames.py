"""Reading the frames of a .data file (Documentation/FileFormats/data.md) for the plotting and
conversion scripts, with errors that name the file and line."""
import sys

import numpy as np


def frames(path, program):
    """Every frame of `path` in turn, as (time, lines, header): lines the particle lines as text
    (parsed by the caller only where needed), header the 8 numbers of the frame's first line
    (N t xmin ymin zmin xmax ymax zmax). `program` names the caller in error messages."""
    with open(path) as f:
        line_number = 0
        while True:
            header = f.readline()
            line_number += 1
            if not header:
                return
            fields = header.split()
            if len(fields) != 8:
                sys.exit(f"{program}: {path} line {line_number}: expected a frame header of 8 fields")
            count, time = int(fields[0]), float(fields[1])
            lines = [f.readline() for _ in range(count)]
            if count and not lines[-1]:
                sys.exit(f"{program}: {path}: the frame at t = {time} is truncated")
            line_number += count
            yield time, lines, [float(v) for v in fields]


def rows_of(path, time, lines, program):
    """The particle lines of a frame as an array of 14 columns."""
    rows = np.loadtxt(lines, ndmin=2)
    if rows.shape[1] < 14:
        sys.exit(f"{program}: {path}: the frame at t = {time} has {rows.shape[1]} columns, not 14")
    return rows


def read_frame(path, wanted, program):
    """(time, rows, header) of the frame of `path` closest to time `wanted` (None: the last), rows
    as rows_of gives them."""
    best = None
    for time, lines, header in frames(path, program):
        if wanted is None or best is None or abs(time - wanted) <= abs(best[0] - wanted):
            best = (time, lines, header)
    if best is None:
        sys.exit(f"{program}: {path} holds no frame")
    return best[0], rows_of(path, best[0], best[1], program), best[2]
