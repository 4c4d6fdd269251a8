#!/usr/bin/env python3
"""Reflows the // comment paragraphs of C++ files that hold a line longer than 100 columns, so
that comments keep to the project's width after an edit lengthened them.

Only whole-line comments are touched, and of a paragraph (consecutive comment lines of the same
indentation, up to a blank comment line, an indented line or a list item) only the lines from
the first long one on; a line never ends with an operator (=, +, -, ...) or a bare "eq.", so that
equations are not split at their signs. Indented comment lines (tables, code, aligned equations)
and comments after code are left alone. Prints the files it changed.

Check afterwards that only comments changed: g++ -fpreprocessed -E -P gives the same text for
each file before and after, blank lines aside.

Usage: Scripts/reflowComments.py FILE..."""
import re, sys, textwrap
WIDTH = 100
PURE = re.compile(r'^(\s*)(//+)( ?)(.*)$')

OPS = {"=", "+", "-", "*", "/", "<=", ">=", "<", ">", "~", "x", "->", "=>"}

def wrap(prefix, first, rest, words):
    """Greedy, but never ending a line with an operator or a bare 'eq.'/'sec.'."""
    out, line = [], prefix + first
    fresh = True
    tokens = words.split()
    for k, w in enumerate(tokens):
        cand = line + ("" if fresh else " ") + w
        if len(cand) <= WIDTH or fresh:
            line, fresh = cand, False
            continue
        # break before w; but if line ends with an operator, carry it over
        head, _, last = line.rpartition(" ")
        carry = []
        if (w in OPS or w[:1] in ")]") and head.strip() and not head.rstrip().endswith("//"):
            carry.insert(0, last)
            line = head
            head, _, last = line.rpartition(" ")
        while last in OPS or last in ("eq.", "sec.", "Eq.", "p.", "Fig.", "fig."):
            if not head.strip() or head.rstrip().endswith("//"):
                break
            carry.insert(0, last)
            line = head
            head, _, last = line.rpartition(" ")
            if last not in OPS and head.strip() and not head.rstrip().endswith("//"):
                carry.insert(0, last)  # the operator's left operand goes with it
                line = head
                head, _, last = line.rpartition(" ")
        out.append(line)
        line = prefix + rest + " ".join(carry + [w])
        fresh = False
    out.append(line)
    return out

def process(lines):
    out, i, changed = [], 0, False
    n = len(lines)
    while i < n:
        m = PURE.match(lines[i])
        if not m or not m.group(4).strip():
            out.append(lines[i]); i += 1; continue
        indent, slashes, sp, text = m.groups()
        prefix = indent + slashes + " "
        # a paragraph: this line, then following lines with the same prefix whose text is plain
        bullet = re.match(r'^(- |\* |\d+\. |\(\d+\) )', text)
        if text.startswith(" ") and not bullet:
            out.append(lines[i]); i += 1; continue
        first = bullet.group(1) if bullet else ""
        cont = " " * len(first)
        block = [lines[i]]
        j = i + 1
        while j < n:
            mj = PURE.match(lines[j])
            if not mj or mj.group(1) != indent or mj.group(2) != slashes:
                break
            t = mj.group(4)
            if not t.strip():
                break
            if re.match(r'^(- |\* |\d+\. |\(\d+\) )', t):
                break
            if cont:
                if not (t.startswith(cont) and not t[len(cont)].isspace()):
                    break
            elif t.startswith(" "):
                break
            block.append(lines[j]); j += 1
        if any(len(l) > WIDTH for l in block):
            k0 = next(k for k, l in enumerate(block) if len(l) > WIDTH)
            out.extend(block[:k0])
            if k0 > 0:
                first = ""
                ck = PURE.match(block[k0]).group(4)
                lead = ck[:len(ck) - len(ck.lstrip())]
                first, cont = lead, lead
            rest = block[k0:]
            words = " ".join(PURE.match(l).group(4).strip() for l in rest)
            if k0 == 0 and first:
                words = words[len(first):] if words.startswith(first) else words
            new = wrap(prefix, first, cont, words)
            if any(len(l) > WIDTH for l in new):
                pass  # a single word too long: leave as wrapped anyway
            out.extend(new); changed = True
        else:
            out.extend(block)
        i = j
    return out, changed

for path in sys.argv[1:]:
    with open(path) as f:
        text = f.read()
    lines = text.split("\n")
    new, changed = process(lines)
    if changed:
        with open(path, "w") as f:
            f.write("\n".join(new))
        print("reflowed", path)
