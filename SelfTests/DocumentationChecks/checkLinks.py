#!/usr/bin/env python3
"""Every relative link of README.md and Documentation/**/*.md must resolve, as on GitHub: the
file or folder exists inside the repository, and an #anchor names a heading of the target page
(GitHub's anchors: see markdownPages.github_slug) or, in a source file, a line (#L12, #L12-L20).
A link must also lead to a file that a clone has: one git tracks (when the repository is a git
work tree), not one that only the local build or an uncommitted change left there. And every
page of Documentation/ must be reachable from README.md by following links, so that the index
leads a reader to all of them.
Prints file:line of each broken link and exits 1; otherwise "links ok: N links in M files".

Usage: checkLinks.py REPOSITORY"""
import os
import re
import subprocess
import sys
import urllib.parse

import markdownPages

LINE_ANCHOR = re.compile(r"^L[0-9]+(-L[0-9]+)?$")


def pages(repository):
    found = [os.path.join(repository, "README.md")]
    for folder, _, files in os.walk(os.path.join(repository, "Documentation")):
        found += [os.path.join(folder, f) for f in files if f.endswith(".md")]
    return sorted(found)


class Page:
    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            self.lines = f.read().split("\n")
        _, in_code = markdownPages.split_fences(self.lines)
        self.anchors = markdownPages.anchors(self.lines, in_code)
        self.links = markdownPages.links(self.lines, in_code)


def tracked(repository):
    """The paths git tracks and their folders, or None outside a git work tree."""
    try:
        out = subprocess.run(["git", "-C", repository, "ls-files", "-z"], capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    paths = set()
    for f in out.stdout.decode("utf-8").split("\0"):
        while f:
            paths.add(os.path.join(repository, f))
            f = os.path.dirname(f)
    paths.add(repository)
    return paths


def main(repository):
    repository = os.path.realpath(repository)
    cache = {}
    known = tracked(repository)
    edges = {}

    def page(path):
        if path not in cache:
            cache[path] = Page(path)
        return cache[path]

    broken, count = [], 0
    sources = pages(repository)
    for source in sources:
        where = os.path.relpath(source, repository)
        for line, target in page(source).links:
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):  # http:, https:, mailto: ...
                continue
            count += 1
            path, _, anchor = urllib.parse.unquote(target).partition("#")
            resolved = os.path.realpath(os.path.join(os.path.dirname(source), path)) if path else source
            if os.path.commonpath([resolved, repository]) != repository:
                broken.append(f"{where}:{line}: '{target}' leads outside the repository")
            elif not os.path.exists(resolved):
                broken.append(f"{where}:{line}: '{target}': no file {os.path.relpath(resolved, repository)}")
            elif known is not None and resolved not in known:
                broken.append(f"{where}:{line}: '{target}': {os.path.relpath(resolved, repository)} is not "
                              f"tracked by git (a clone would not have it)")
            elif anchor and resolved.endswith(".md"):
                if anchor not in page(resolved).anchors:
                    broken.append(f"{where}:{line}: '{target}': no heading with anchor #{anchor} in "
                                  f"{os.path.relpath(resolved, repository)}")
            elif anchor and not (os.path.isfile(resolved) and LINE_ANCHOR.match(anchor)):
                broken.append(f"{where}:{line}: '{target}': #{anchor} is not a line anchor (#L12) of a file")
            if path and resolved.endswith(".md"):
                edges.setdefault(source, set()).add(resolved)
    # Every page reachable from README.md.
    seen, todo = set(), [os.path.join(repository, "README.md")]
    while todo:
        here = todo.pop()
        if here not in seen:
            seen.add(here)
            todo += sorted(edges.get(here, ()))
    for source in sources:
        if source not in seen and (known is None or source in known):
            broken.append(f"{os.path.relpath(source, repository)}: no chain of links from README.md "
                          f"leads to this page (add it to Documentation/README.md)")
    return markdownPages.report(broken, f"links ok: {count} links in {len(sources)} files")

if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
