#!/usr/bin/env python3
"""The flag list of the user guide (the first code block of WritingADriver.md's section
"Command-line flags", given there as the output of DRIVER --help) must be that output: every flag
the driver prints (the flags every driver has, and the driver's own) is listed, with the same
line, and no flag is listed that the driver does not print. So a new flag cannot go undocumented
and a removed or reworded one cannot linger. Prints each difference and exits 1; otherwise
"flag list ok: N flags".

Usage: checkDriverFlags.py WritingADriver.md DRIVER"""
import re
import subprocess
import sys

import markdownPages

FLAG_LINE = re.compile(r"^\s+(--[a-z0-9-]+)\b")


def flag_lines(text):
    """{flag: its line, trailing spaces dropped} of the lines of text that describe a flag."""
    found = {}
    for line in text.split("\n"):
        flag = FLAG_LINE.match(line)
        if flag:
            found[flag.group(1)] = line.rstrip()
    return found


def documented(page):
    with open(page, encoding="utf-8") as f:
        lines = f.read().split("\n")
    blocks, _ = markdownPages.split_fences(lines)
    heading = re.compile(r"^##\s+Command-line flags\s*$")
    section = next((i for i, line in enumerate(lines) if heading.match(line)), None)
    if section is None:
        sys.exit(f"{page}: no section '## Command-line flags'")
    block = next((b for b in blocks if b.first_line > section + 1), None)
    if block is None:
        sys.exit(f"{page}: no code block after '## Command-line flags'")
    return block, flag_lines(block.text)


def main(page, driver):
    block, listed = documented(page)
    run = subprocess.run([driver, "--help"], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        print(f"{driver} --help exited with {run.returncode}:\n{run.stdout}{run.stderr}")
        return 1
    printed = flag_lines(run.stdout)
    problems = []
    for flag, line in printed.items():
        if flag not in listed:
            problems.append(f"{page}:{block.first_line}: {flag} is missing from the flag list; "
                            f"--help prints\n{line}")
        elif listed[flag] != line:
            problems.append(f"{page}:{block.first_line}: the line of {flag} differs from --help's:\n"
                            f"listed: {listed[flag]}\nprinted: {line}")
    for flag in listed:
        if flag not in printed:
            problems.append(f"{page}:{block.first_line}: {flag} is listed but {driver} --help "
                            "does not print it")
    if not printed:
        problems.append(f"{driver} --help printed no flags:\n{run.stdout}")
    return markdownPages.report(problems, f"flag list ok: {len(printed)} flags")

if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
