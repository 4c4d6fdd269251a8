#!/usr/bin/python3
"""The study runner's collection (studyRunner.collect): the result files of points written by
drivers of different versions (a column added later, as baseRoughness in the calibration's) go
into one results.csv with every column, in the order the columns first appear, each value under
its own name and a column a point lacks left empty. Prints "study runner: all checks passed".
"""
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import studyRunner  # noqa: E402
from checks import check, finish  # noqa: E402


def write_result(out, name, columns, values):
    path = studyRunner.result_path(out, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        writer.writerow(values)


with tempfile.TemporaryDirectory() as out:
    # old, new, old again: the header of neither the first nor the last file alone holds them all.
    write_result(out, "a", ["angle", "h"], ["24", "3.1"])
    write_result(out, "b", ["angle", "roughness", "h"], ["25", "0.25", "2.7"])
    write_result(out, "c", ["angle", "h"], ["26", "2.2"])
    count = studyRunner.collect(out, ["a", "b", "missing", "c"])
    check(count == 3, f"three lines collected (got {count})")
    with open(os.path.join(out, "results.csv"), newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        header = reader.fieldnames
    check(header == ["point", "angle", "h", "roughness"], f"every column once, in order of appearance (got {header})")
    check([r["point"] for r in rows] == ["a", "b", "c"], "the points in grid order")
    check([r["h"] for r in rows] == ["3.1", "2.7", "2.2"], "each value under its own column")
    check([r["roughness"] for r in rows] == ["", "0.25", ""], "a column a point lacks left empty")
    check(studyRunner.collect(out, ["missing"]) == 0, "no finished point: nothing collected")

finish("study runner")
