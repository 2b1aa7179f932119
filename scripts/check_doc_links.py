#!/usr/bin/env python3
"""Checks the relative Markdown links of the docs: every `](x.md...)` or `](dir/x.md...)` link in
README.md, docs/*.md and docs/**/*.md must name a file that exists, and a `#anchor` after it (or
alone, for the same page) must be one of that file's headings as GitHub spells its anchors.

  python3 scripts/check_doc_links.py [ROOT]   prints each broken link as FILE:LINE: ..., exit 1 if any
                                              (ROOT: the tree to check, this checkout by default)

A ctest runs it on this tree (doc_links) and on a fixture of known breaches (doc_links_fixture).
"""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LINK = re.compile(r"\]\(([^)\s]+)\)")


def anchors(path):
    """The anchors GitHub gives the headings of a Markdown file (outside code fences)."""
    found, seen, fence = set(), {}, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                fence = not fence
            m = None if fence else re.match(r"#{1,6} (.*)", line)
            if not m:
                continue
            slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
            n = seen.get(slug, 0)
            seen[slug] = n + 1
            found.add(slug if n == 0 else f"{slug}-{n}")
    return found


def main():
    global ROOT
    if len(sys.argv) > 2 or (len(sys.argv) == 2 and sys.argv[1] in ("-h", "--help")):
        print(__doc__.strip())
        return 0 if len(sys.argv) == 2 else 2
    if len(sys.argv) == 2:
        ROOT = os.path.abspath(sys.argv[1])
        if not os.path.isfile(os.path.join(ROOT, "README.md")):
            print(f"{sys.argv[1]}: error: not a checkout (no README.md in it)", file=sys.stderr)
            return 2
    pages = [os.path.join(ROOT, "README.md")]
    pages += sorted(glob.glob(os.path.join(ROOT, "docs", "**", "*.md"), recursive=True))
    broken = 0
    for page in pages:
        with open(page, encoding="utf-8") as f:
            lines = f.read().split("\n")
        fence = False
        for number, line in enumerate(lines, 1):
            if line.startswith("```"):
                fence = not fence
            if fence:
                continue
            for target in LINK.findall(line):
                if re.match(r"[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                path, _, anchor = target.partition("#")
                if path and not path.endswith(".md"):
                    full = os.path.normpath(os.path.join(os.path.dirname(page), path))
                    problem = None if os.path.exists(full) else "no such file"
                elif path or anchor:
                    full = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
                    if not os.path.isfile(full):
                        problem = "no such file"
                    elif anchor and anchor not in anchors(full):
                        problem = f"no heading with anchor #{anchor}"
                    else:
                        problem = None
                else:
                    problem = None
                if problem:
                    broken += 1
                    print(f"{os.path.relpath(page, ROOT)}:{number}: ]({target}): {problem}")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
