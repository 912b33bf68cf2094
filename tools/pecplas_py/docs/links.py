#!/usr/bin/env python3
"""Checks the links of the Markdown pages (README.md, doc/*.md, doc/bench/*.md): every
relative link names a file that exists, every `#anchor` a heading of its page (GitHub's
anchors: the heading's text in lower case, punctuation dropped, blanks as hyphens, a repeated
heading numbered -1, -2, ...), every image a file that exists. Links to the web are not
followed. Code spans and fenced code blocks are skipped.

    python3 -m pecplas_py.docs.links [PAGE.md ...]   # exit 1 and the list of broken links
"""
import re
import sys
from pathlib import Path

from pecplas_py import ROOT

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML = re.compile(r"<(?:img|a)\s[^>]*(?:src|href)=\"([^\"]+)\"", re.I)


def pages():
    return [ROOT / "README.md", *sorted((ROOT / "doc").glob("*.md")),
            *sorted((ROOT / "doc" / "bench").glob("*.md"))]


def _prose(text):
    """The page without fenced code blocks and code spans (their brackets are no links)."""
    out, fenced = [], False
    for line in text.splitlines():
        if line.lstrip().startswith(("```", "~~~")):
            fenced = not fenced
            out.append("")
            continue
        out.append("" if fenced else re.sub(r"`[^`]*`", "", line))
    return out


def slug(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link: its text
    text = re.sub(r"<[^>]+>", "", text).replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(page):
    """The anchors of a page: its headings' (numbered when repeated) and <a name/id="...">."""
    seen, out = {}, set()
    for line in _prose_keep_code_spans(page.read_text()):
        m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m:
            s = slug(m.group(1))
            n = seen.get(s, 0)
            out.add(s if n == 0 else f"{s}-{n}")
            seen[s] = n + 1
        out.update(re.findall(r"<a\s+(?:name|id)=\"([^\"]+)\"", line))
    return out


def _prose_keep_code_spans(text):
    out, fenced = [], False
    for line in text.splitlines():
        if line.lstrip().startswith(("```", "~~~")):
            fenced = not fenced
            continue
        if not fenced:
            out.append(line)
    return out


def _name(path):
    """A path as the report writes it: relative to the repository when inside it."""
    try:
        return path.relative_to(ROOT)
    except ValueError:
        return path


def broken(page_list=None):
    """List of 'page:line: what' for every link that does not resolve."""
    problems, cache = [], {}
    for page in page_list or pages():
        rel = _name(page)
        for i, line in enumerate(_prose(page.read_text()), 1):
            for target in LINK.findall(line) + HTML.findall(line):
                if re.match(r"[a-z][a-z0-9+.-]*:", target, re.I):
                    continue  # http:, https:, mailto:
                path, _, anchor = target.partition("#")
                dest = (page.parent / path).resolve() if path else page
                if not dest.exists():
                    problems.append(f"{rel}:{i}: {target}: no file {path}")
                    continue
                if anchor and dest.suffix == ".md":
                    if dest not in cache:
                        cache[dest] = anchors(dest)
                    if anchor not in cache[dest]:
                        problems.append(f"{rel}:{i}: {target}: no heading #{anchor} in "
                                        f"{_name(dest)}")
    return problems


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    chosen = [Path(a).resolve() for a in argv] or None
    problems = broken(chosen)
    for p in problems:
        print(p)
    print(f"{len(chosen or pages())} pages, {len(problems)} broken links")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
