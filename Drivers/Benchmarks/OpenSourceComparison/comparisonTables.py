"""Reading the comparison drivers' tables (ComparisonDrum's NAME.zones, ComparisonPenetration's
NAME.penetration, the LIGGGHTS inputs' equivalents): comment lines start with '#', every other
non-blank line holds the same number of finite numbers. A line that does not is named with its
file and number, and the script stops."""
import sys

import numpy as np


def read_rows(path, columns, what):
    """The rows of `path` as an array of `columns` columns; `what` names them in errors."""
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("#") or not line.strip():
                continue
            try:
                values = [float(v) for v in line.split()]
            except ValueError:
                sys.exit(f"{path}:{number}: expected numbers, got '{line.strip()}'")
            if len(values) != columns or not all(np.isfinite(values)):
                sys.exit(f"{path}:{number}: expected {columns} finite numbers ({what}), got '{line.strip()}'")
            rows.append(values)
    if len(rows) < 2:
        sys.exit(f"{path}: fewer than two rows")
    return np.array(rows)
