#!/usr/bin/env python3
"""Where two text output files of a driver differ, and by how much.

    compareOutputFiles.py FILE_A FILE_B [LABEL_A LABEL_B]

Prints the first line that differs, as it reads in both files, and over all differing lines the
largest relative difference |a - b| / max(|a|, |b|) of the numbers that stand in the same place
(fields split at blanks, commas, semicolons, quotes and the <, >, = of XML), and their largest
absolute difference |a - b| (numbers near zero, such as a resting particle's velocity, make the
relative one large for a small change). Fields that are not
both numbers and differ as text are counted apart, as are lines with a different number of
fields and lines one file has beyond the other's end. Used by compareCommits.sh on the files
that `cmp` found different.

Exit status: 0 the files are equal, 1 they differ, 2 a file cannot be read.
"""
import itertools
import math
import re
import sys

FIELD_SEPARATORS = re.compile(rb'[\s,;"<>=]+')
SHOWN_CHARACTERS = 160


def as_number(field):
    try:
        return float(field)
    except ValueError:
        return None


def relative_difference(a, b):
    """|a - b| / max(|a|, |b|): 0 for equal numbers, 1 for opposite signs or one of them 0."""
    if a == b:
        return 0.0
    if math.isnan(a) or math.isnan(b) or math.isinf(a) or math.isinf(b):
        return math.inf
    return abs(a - b) / max(abs(a), abs(b))


def shown(line):
    text = line.rstrip(b'\r\n').decode('latin-1')
    return text if len(text) <= SHOWN_CHARACTERS else text[:SHOWN_CHARACTERS] + ' ...'


class Differences:
    def __init__(self):
        self.first = None  # (line number, line of A, line of B)
        self.lines = 0  # differing lines both files have
        self.largest = 0.0
        self.largest_at = None  # (line number, field number, field of A, field of B)
        self.largest_absolute = 0.0
        self.text_fields = 0  # differing fields that are not both numbers
        self.field_count_lines = 0  # differing lines with a different number of fields
        self.beyond = [0, 0]  # lines only A has, only B has

    def add(self, number, line_a, line_b):
        if self.first is None:
            self.first = (number, line_a, line_b)
        if line_a is None or line_b is None:
            self.beyond[0 if line_b is None else 1] += 1
            return
        self.lines += 1
        fields_a = [f for f in FIELD_SEPARATORS.split(line_a) if f]
        fields_b = [f for f in FIELD_SEPARATORS.split(line_b) if f]
        if len(fields_a) != len(fields_b):
            self.field_count_lines += 1
        for k, (fa, fb) in enumerate(zip(fields_a, fields_b), start=1):
            if fa == fb:
                continue
            a, b = as_number(fa), as_number(fb)
            if a is None or b is None:
                self.text_fields += 1
                continue
            difference = relative_difference(a, b)
            if not abs(a - b) <= self.largest_absolute:  # NaN counts as larger
                self.largest_absolute = abs(a - b)
            if difference > self.largest or self.largest_at is None:
                self.largest = difference
                self.largest_at = (number, k, fa.decode('latin-1'), fb.decode('latin-1'))


def compare(path_a, path_b):
    found = Differences()
    total = 0
    with open(path_a, 'rb') as a, open(path_b, 'rb') as b:
        for number, (line_a, line_b) in enumerate(itertools.zip_longest(a, b), start=1):
            total = number
            if line_a != line_b:
                found.add(number, line_a, line_b)
    return found, total


def report(found, total, label_a, label_b):
    width = max(len(label_a), len(label_b)) + 1
    number, line_a, line_b = found.first
    print(f'    first difference at line {number}:')
    for label, line in ((label_a, line_a), (label_b, line_b)):
        print(f'      {label + ":":<{width}} ' + ('(the file ends before)' if line is None else shown(line)))
    parts = [f'{found.lines} of {total} lines differ']
    if found.largest_at is not None:
        line, field, fa, fb = found.largest_at
        parts.append(f'largest relative difference of their numbers {found.largest:.3g} '
                     f'(line {line}, field {field}: {fa} against {fb}), largest absolute {found.largest_absolute:.3g}')
    else:
        parts.append('no numbers differ')
    if found.text_fields:
        parts.append(f'{found.text_fields} differing fields not numbers')
    if found.field_count_lines:
        parts.append(f'{found.field_count_lines} lines with another number of fields')
    for label, extra in zip((label_a, label_b), found.beyond):
        if extra:
            parts.append(f'{extra} more lines in {label}')
    print('    ' + '; '.join(parts))


def main(argv):
    if len(argv) not in (3, 5):
        print('usage: compareOutputFiles.py FILE_A FILE_B [LABEL_A LABEL_B]', file=sys.stderr)
        return 2
    label_a, label_b = (argv[3], argv[4]) if len(argv) == 5 else (argv[1], argv[2])
    try:
        found, total = compare(argv[1], argv[2])
    except OSError as error:
        print(f'compareOutputFiles.py: {error.filename}: {error.strerror}', file=sys.stderr)
        return 2
    if found.first is None:
        return 0
    report(found, total, label_a, label_b)
    return 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
