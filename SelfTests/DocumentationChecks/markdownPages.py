"""Reading Markdown as GitHub renders it, for the documentation checks: fenced code blocks,
headings and the anchors GitHub makes of them, the links of a page's text; and the checks' report."""
import re
import unicodedata

FENCE = re.compile(r"^( {0,3})(`{3,}|~{3,})\s*([^`\s]*)")


class CodeBlock:
    def __init__(self, language, first_line, text):
        self.language = language      # the info string's first word, lower case ('' when none)
        self.first_line = first_line  # line number (1-based) of the block's first code line
        self.text = text


def split_fences(lines):
    """The fenced code blocks of a page, and per line whether it is inside one (fence lines too)."""
    blocks, in_code = [], [False] * len(lines)
    i = 0
    while i < len(lines):
        opening = FENCE.match(lines[i])
        if not opening:
            i += 1
            continue
        marker = opening.group(2)
        closing = re.compile(r"^ {0,3}" + re.escape(marker[0]) + "{" + str(len(marker)) + r",}\s*$")
        j = i + 1
        while j < len(lines) and not closing.match(lines[j]):
            j += 1
        for k in range(i, min(j + 1, len(lines))):
            in_code[k] = True
        blocks.append(CodeBlock(opening.group(3).lower(), i + 2, "\n".join(lines[i + 1:j]) + "\n"))
        i = j + 1
    return blocks, in_code


def _rendered_text(markdown):
    """The text of a heading as GitHub shows it: links by their text, code without backticks,
    emphasis and HTML tags dropped."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", markdown)
    text = re.sub(r"<[^>]+>", "", text)
    text = re.sub(r"`+([^`]*)`+", r"\1", text)
    text = text.replace("*", "")
    text = re.sub(r"(^|\W)_+([^_]+)_+(?=\W|$)", r"\1\2", text)
    return text.strip()


def github_slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation other than '-' and '_' removed,
    each space a '-'."""
    text = _rendered_text(heading).lower()
    kept = "".join(c for c in text if c in "-_ " or unicodedata.category(c)[0] in "LNM")
    return kept.replace(" ", "-")


def anchors(lines, in_code):
    """Every anchor of a page: its headings' (a repeated one gets -1, -2, ...) and explicit
    <a name=...> or id=... ones."""
    found, seen = set(), {}
    for line, code in zip(lines, in_code):
        if code:
            continue
        heading = re.match(r"^ {0,3}#{1,6}\s+(.*?)(\s+#+)?\s*$", line)
        if heading:
            slug = github_slug(heading.group(1))
            count = seen.get(slug, 0)
            seen[slug] = count + 1
            found.add(slug if count == 0 else f"{slug}-{count}")
        for explicit in re.finditer(r"<a\s[^>]*?(?:name|id)=\"([^\"]+)\"", line):
            found.add(explicit.group(1))
    return found


LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^ {0,3}\[[^\]]+\]:\s*<?(\S+?)>?(\s+\"[^\"]*\")?\s*$")


def links(lines, in_code):
    """(line number, target) of every inline link, image and reference definition outside code.
    A link's text may wrap onto the next line, so the text between code blocks is read whole."""
    found = []
    start = 0
    while start < len(lines):
        if in_code[start]:
            start += 1
            continue
        end = start
        while end < len(lines) and not in_code[end]:
            end += 1
        text = "\n".join(lines[start:end])
        # Inline code spans are not links: blank them, keeping the offsets and line breaks.
        text = re.sub(r"(`+)[\s\S]*?\1", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
        for number, line in enumerate(text.split("\n"), start=start + 1):
            reference = REFERENCE.match(line)
            if reference:
                found.append((number, reference.group(1)))
        for link in LINK.finditer(text):
            found.append((start + 1 + text.count("\n", 0, link.start(1)), link.group(1)))
        start = end
    return sorted(found)


def report(problems, success):
    """Prints the problems found, or the success line when there are none; the exit status."""
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} problems")
        return 1
    print(success)
    return 0
