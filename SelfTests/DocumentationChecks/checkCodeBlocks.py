#!/usr/bin/env python3
"""The C++ code blocks (```cpp) of the given Markdown pages must be real code:
 - a block with main() is a whole program: it is compiled against the build tree's Talus
   (find_package(Talus)) with the build's compiler and flags and -Wall -Wextra -Wpedantic -Werror,
   then run with --end-time 0.01 --files off, and must end with status 0 and say "finished";
 - any other block quotes the driver the page names on a line "Driver: `path`": its text,
   whitespace aside, must appear in that source file; a line "..." in the block stands for
   omitted code, and the pieces between such lines must appear in the source in their order.
Prints file:line of each block that fails and exits 1; otherwise "code blocks ok: ...".

Usage: checkCodeBlocks.py --repository DIR --talus-dir BUILD --cmake CMAKE --cxx CXX
                          [--cxx-flags FLAGS] [--link-flags FLAGS] PAGE..."""
import argparse
import os
import re
import subprocess
import sys

import markdownPages

CPP = {"cpp", "c++", "cxx", "cc"}
ELISION = re.compile(r"^\s*(\.\.\.|//\s*\.\.\.)\s*$")


def squeezed(text):
    return re.sub(r"\s+", "", text)


def quote_problem(block, source_text):
    """None when the block's pieces appear in the source in order, else which piece does not."""
    source = squeezed(source_text)
    position = 0
    piece, piece_line = [], block.first_line
    pieces = []
    for number, line in enumerate(block.text.split("\n"), start=block.first_line):
        if ELISION.match(line):
            pieces.append((piece_line, piece))
            piece, piece_line = [], number + 1
        else:
            piece.append(line)
    pieces.append((piece_line, piece))
    for line, text in pieces:
        wanted = squeezed("\n".join(text))
        if not wanted:
            continue
        found = source.find(wanted, position)
        if found < 0:
            first = next(t for t in text if t.strip()).strip()
            where = "anywhere" if source.find(wanted) < 0 else "after the block's earlier pieces"
            return line, f"the lines from '{first}' are not {where} in the driver"
        position = found + len(wanted)
    return None


def driver_of(lines, repository):
    for line in lines:
        named = re.match(r"^Driver:\s*`([^`]+)`", line)
        if named:
            return os.path.join(repository, named.group(1))
    return None


def write_if_changed(path, text):
    """Writes text to path unless it is there already (a second run compiles nothing); whether
    it wrote."""
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                return False
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return True


def build_and_run(programs, options):
    """programs: (name, where) pairs whose sources are in options.work; the failures, as text."""
    work = options.work
    project = ("cmake_minimum_required(VERSION 3.20)\nproject(DocumentationPrograms LANGUAGES CXX)\n"
               "set(CMAKE_CXX_STANDARD 20)\nfind_package(Talus REQUIRED)\n"
               "add_compile_options(-Wall -Wextra -Wpedantic -Werror)\n")
    for name, _ in programs:
        project += f"add_executable({name} {name}.cc)\ntarget_link_libraries({name} PRIVATE Talus::talus)\n"
    write_if_changed(os.path.join(work, "CMakeLists.txt"), project)
    configure_command = [options.cmake, "-S", work, "-B", os.path.join(work, "build"),
                         f"-DTalus_DIR={os.path.abspath(options.talus_dir)}",
                         f"-DCMAKE_CXX_COMPILER={options.cxx}", f"-DCMAKE_CXX_FLAGS={options.cxx_flags}",
                         f"-DCMAKE_EXE_LINKER_FLAGS={options.link_flags}"]
    # Configured again only when the command changed (finding Talus and MPI takes seconds); a
    # changed CMakeLists.txt or library is picked up by the build itself.
    if write_if_changed(os.path.join(work, "configure.txt"), "\n".join(configure_command)) or \
            not os.path.exists(os.path.join(work, "build", "CMakeCache.txt")):
        configure = subprocess.run(configure_command, capture_output=True, text=True)
        if configure.returncode != 0:
            os.remove(os.path.join(work, "configure.txt"))
            return ["configuring the programs failed:\n" + configure.stdout + configure.stderr]
    failures = []
    for name, where in programs:
        build = subprocess.run([options.cmake, "--build", os.path.join(work, "build"), "--target", name],
                               capture_output=True, text=True)
        if build.returncode != 0:
            failures.append(f"{where}: the program does not compile:\n{build.stdout}{build.stderr}")
            continue
        run = subprocess.run([os.path.join(work, "build", name), "--end-time", "0.01", "--files", "off"],
                             cwd=work, capture_output=True, text=True, timeout=120)
        if run.returncode != 0 or "finished" not in run.stdout:
            failures.append(f"{where}: the program, run with --end-time 0.01 --files off, exited with "
                            f"{run.returncode}:\n{run.stdout}{run.stderr}")
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repository", required=True)
    parser.add_argument("--talus-dir", required=True)
    parser.add_argument("--cmake", required=True)
    parser.add_argument("--cxx", required=True)
    parser.add_argument("--cxx-flags", default="")
    parser.add_argument("--link-flags", default="")
    parser.add_argument("--work", default=os.getcwd())
    parser.add_argument("pages", nargs="+")
    options = parser.parse_args()

    failures, programs, quotes = [], [], 0
    for page in options.pages:
        where_page = os.path.relpath(page, options.repository)
        with open(page, encoding="utf-8") as f:
            lines = f.read().split("\n")
        blocks, _ = markdownPages.split_fences(lines)
        driver = driver_of(lines, options.repository)
        for block in blocks:
            if block.language not in CPP:
                continue
            where = f"{where_page}:{block.first_line}"
            if re.search(r"\bint\s+main\s*\(", block.text):
                stem = re.sub(r"\W", "_", os.path.splitext(where_page)[0])
                name = f"program_{stem}_{block.first_line}"
                write_if_changed(os.path.join(options.work, name + ".cc"),
                                 f'#line {block.first_line} "{where_page}"\n' + block.text)
                programs.append((name, where))
            elif driver is None:
                failures.append(f"{where}: the block is neither a whole program (with main) nor a quote of "
                                "a driver (the page names none on a line \"Driver: `path`\")")
            elif not os.path.isfile(driver):
                failures.append(f"{where}: the page's driver {os.path.relpath(driver, options.repository)} "
                                "does not exist")
            else:
                quotes += 1
                with open(driver, encoding="utf-8") as f:
                    problem = quote_problem(block, f.read())
                if problem:
                    failures.append(f"{where_page}:{problem[0]}: {problem[1]} "
                                    f"{os.path.relpath(driver, options.repository)}")
    failures += build_and_run(programs, options) if programs else []
    return markdownPages.report(failures, f"code blocks ok: {len(programs)} programs compiled and run, "
                                     f"{quotes} quotes found in their drivers")

if __name__ == "__main__":
    sys.exit(main())
