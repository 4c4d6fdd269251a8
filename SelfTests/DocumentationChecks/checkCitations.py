#!/usr/bin/env python3
"""The repository must stand on its own: a user who clones it has none of the team's working
notes that lived next to it. So no tracked file may cite those notes (the physics, design and
style notes by their file names, the folder beside the repository, or line numbers of the thesis's
extracted text, written as the word seed, a colon and a number): the physics and algorithms are
stated in Documentation/Theory/ and the architecture in Documentation/Architecture.md, which is
what comments and pages cite instead. The folder beside the repository may still appear as the
default of a path variable in code, built from the repository's top (`$top/..`, `${...}/..`):
the peers' start files of the benchmarks live there, and the variable names them.

And the user pages (Documentation/**/*.md) say what Talus is and does, not how it was worked on:
the word "session" is refused there (the dated history of the measured performance,
Performance/History.md, dates its rows instead).

Nor do the sources (Kernel/, Drivers/, Tools/, UnitTests/, SelfTests/, Scripts/) carry calendar
dates (YYYY-MM-DD or YYYY-MM): a measurement that a comment relies on is stated, with its date and
processor, in Documentation/Performance.md or Performance/History.md, and the comment cites it.

Prints file:line and the offending text of each finding and exits 1; otherwise
"citations ok: N files".

Usage: checkCitations.py REPOSITORY"""
import os
import re
import subprocess
import sys

import markdownPages

# Spelled in pieces, so that this file does not cite them itself.
NOTES = ["SPEC", "DESIGN", "STYLE"]
NOTE = re.compile(r"\b(" + "|".join(NOTES) + r")\.md\b")
SEED_LINE = re.compile(r"\bseed" + r":\s*[0-9]")
BESIDE = re.compile(r"\.\./" + "shared")
# The default of a path variable built from the repository's top, in code.
BESIDE_AS_DEFAULT = re.compile(r"(\$top|\$\{[A-Z_]+\}|\$\{?[A-Za-z_]+\}?)/\.\./" + "shared")
SESSION = re.compile(r"\bsessions?\b", re.IGNORECASE)
# A calendar date, year and month at least (YYYY-MM, YYYY-MM-DD).
DATE = re.compile(r"\b(19|20)[0-9]{2}" + r"-(0[1-9]|1[0-2])(-[0-3][0-9])?\b")
SOURCE_FOLDERS = ("Kernel", "Drivers", "Tools", "UnitTests", "SelfTests", "Scripts")


def tracked_files(repository):
    """The files git tracks (what a clone has); every file below the repository without git."""
    try:
        out = subprocess.run(["git", "-C", repository, "ls-files", "-z"], capture_output=True, check=True)
        return [f for f in out.stdout.decode("utf-8").split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        found = []
        for folder, dirs, files in os.walk(repository):
            dirs[:] = [d for d in dirs if not d.startswith(".") and not d.startswith("build")]
            found += [os.path.relpath(os.path.join(folder, f), repository) for f in files]
        return found


def findings(path, text):
    problems = []
    lines = text.split("\n")
    user_page = path.startswith("Documentation" + os.sep) and path.endswith(".md")
    source = path.split(os.sep)[0] in SOURCE_FOLDERS
    for number, line in enumerate(lines, start=1):
        for pattern, what in ((NOTE, "cites a note outside the repository"),
                              (SEED_LINE, "cites a line of the thesis's extracted text")):
            match = pattern.search(line)
            if match:
                problems.append(f"{path}:{number}: {what}: '{match.group(0)}'")
        for match in BESIDE.finditer(line):
            if not BESIDE_AS_DEFAULT.search(line[:match.end()]):
                problems.append(f"{path}:{number}: cites the folder beside the repository: "
                                f"'{line.strip()[:80]}'")
                break
        if source:
            match = DATE.search(line)
            if match:
                problems.append(f"{path}:{number}: a date in the sources (measurements belong in "
                                f"Documentation/Performance.md and its history): '{match.group(0)}'")
        if user_page:
            match = SESSION.search(line)
            if match:
                problems.append(f"{path}:{number}: a user page tells of work sessions: '{line.strip()[:80]}'")
    return problems


def main(repository):
    repository = os.path.realpath(repository)
    problems, count = [], 0
    for path in tracked_files(repository):
        try:
            with open(os.path.join(repository, path), encoding="utf-8") as f:
                text = f.read()
        except (UnicodeDecodeError, FileNotFoundError, IsADirectoryError):
            continue  # binary files (images), or deleted but not yet committed
        count += 1
        problems += findings(path, text)
    return markdownPages.report(problems, f"citations ok: {count} files")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
