#!/usr/bin/env python3
"""Simulation stays the driver contract and little else (Documentation/Architecture.md, "The driver
contract"): Kernel/Simulation.h may declare at most MAX_FUNCTIONS public member functions and at
most MAX_MEMBERS data members; what grows beyond goes to a part of its own (Run/, Scene/,
Integration/, Parallel/, IO/).

Counted, by a small parser of the class body (comments and string literals removed first):
 - public functions: every declaration or definition of a member function in a public section,
   constructors, the destructor and each overload included; functions of nested classes not;
 - data members: every non-static data member of the class in any section (one per declarator:
   `double a = 0, b = 0;` is two); static constants, nested types, friends and aliases not.

Prints the counts and the names, and exits 1 when either is over its limit; otherwise
"driver contract ok: ...".

Usage: checkDriverContract.py HEADER [--max-functions N] [--max-members N]"""
import argparse
import re
import sys


def without_comments_and_strings(text):
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\])*"|\'(?:\\.|[^\'\\])*\'', re.DOTALL)
    return pattern.sub(lambda m: '""' if m.group(0).startswith('"') else " ", text)


def class_body(text, name):
    """The text between the braces of `class name ... {` ... `};`."""
    match = re.search(r"\bclass\s+" + name + r"\b[^;{]*\{", text)
    if not match:
        raise SystemExit(f"checkDriverContract: no class {name} found")
    depth, start = 1, match.end()
    for k in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[k], 0)
        if depth == 0:
            return text[start:k]
    raise SystemExit(f"checkDriverContract: class {name} is not closed")


def without_template_arguments(text):
    """`std::function<void()> f` -> `std::function f`: parentheses inside <...> are types."""
    previous = None
    while previous != text:
        previous = text
        text = re.sub(r"<[^<>]*>", "", text)
    return text


def split_top_level(text, separator):
    parts, depth, current = [], 0, ""
    for c in text:
        if c in "<({[":
            depth += 1
        elif c in ">)}]":
            depth -= 1
        if c == separator and depth == 0:
            parts.append(current)
            current = ""
        else:
            current += c
    return parts + [current]


def declarations(body):
    """(access, text, has_body) for each declaration at the top level of the class body."""
    result, access, current, k = [], "private", "", 0
    while k < len(body):
        c = body[k]
        label = re.match(r"\s*(public|protected|private)\s*:(?!:)", current + body[k:])
        if not current.strip() and label:
            access = label.group(1)
            k += label.end() - len(current)
            current = ""
            continue
        if c == "{":
            depth, j = 1, k + 1
            while depth:
                depth += {"{": 1, "}": -1}.get(body[j], 0)
                j += 1
            head = current.strip()
            if head.count("(") > head.count(")"):  # a default argument `= {}` inside a parameter list
                current += body[k:j]
                k = j
                continue
            is_type = re.match(r"(struct|class|union|enum)\b", head)
            is_function = "(" in without_template_arguments(head) and not is_type
            if is_function:
                result.append((access, head, True))
                current, k = "", j
                continue
            if is_type:  # a nested type: skip its body and the declaration's end
                end = body.index(";", j)
                result.append((access, head, False))
                current, k = "", end + 1
                continue
            current += body[k:j]  # a brace initialiser of a data member
            k = j
            continue
        if c == ";":
            if current.strip():
                result.append((access, current.strip(), False))
            current = ""
        else:
            current += c
        k += 1
    return result


def count(header):
    body = class_body(without_comments_and_strings(open(header, encoding="utf-8").read()), "Simulation")
    functions, members = [], []
    for access, text, has_body in declarations(body):
        text = " ".join(text.split())
        if re.match(r"(friend|using|typedef|struct|class|union|enum)\b", text):
            continue
        bare = without_template_arguments(text)
        if "(" in bare.split("=")[0] or has_body:
            if access == "public":
                name = re.search(r"(~?\w+|operator\S+)\s*\(", bare)
                functions.append(name.group(1) if name else text)
            continue
        if re.match(r"(static|inline static|static inline)\b", text):
            continue
        for declarator in split_top_level(bare, ","):
            name = re.search(r"(\w+)\s*(=.*|\{.*\})?\s*$", declarator.strip())
            members.append(name.group(1) if name else declarator.strip())
    return functions, members


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("header")
    parser.add_argument("--max-functions", type=int, default=30)
    parser.add_argument("--max-members", type=int, default=10)
    args = parser.parse_args()
    functions, members = count(args.header)
    print(f"{len(functions)} public functions: {', '.join(functions)}")
    print(f"{len(members)} data members: {', '.join(members)}")
    over = []
    if len(functions) > args.max_functions:
        over.append(f"{len(functions)} public functions, more than {args.max_functions}")
    if len(members) > args.max_members:
        over.append(f"{len(members)} data members, more than {args.max_members}")
    if over:
        print(f"{args.header}: " + "; ".join(over) +
              ": move what grew into a part of its own (Documentation/Architecture.md, \"The driver contract\")")
        return 1
    print(f"driver contract ok: {len(functions)} public functions, {len(members)} data members")
    return 0


if __name__ == "__main__":
    sys.exit(main())
