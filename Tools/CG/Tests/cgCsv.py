"""Helpers of the CG check scripts: talus-cg's CSV output read as (column names, rows), and the
difference of two arrays relative to the largest magnitude of the expected one."""
import numpy as np


def read_csv(path):
    """The column names and an array of the rows of a talus-cg CSV file ('#' lines dropped)."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith('#')]
    names = lines[0].strip().split(',')
    return names, np.loadtxt(lines[1:], delimiter=',', ndmin=2)


def relative_difference(expected, found):
    """max |found - expected| / max |expected| (the CSV's %.12g digits bound it by about 5e-12)."""
    scale = max(np.max(np.abs(expected)), 1e-300)
    return np.max(np.abs(np.asarray(found) - expected)) / scale
