#!/usr/bin/env python3
"""Every relative link and image of README.md and docs/*.md resolves.

Usage: docLinks.py ROOT
Prints one line per broken link ("FILE: TARGET") and a summary; exits 1 if
any is broken.  Links to web addresses (with a scheme) and pure in-page
anchors are not checked; "path#anchor" checks the path.
"""
import glob
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def main(root):
    pages = [os.path.join(root, "README.md")] + sorted(
        glob.glob(os.path.join(root, "docs", "*.md")))
    broken, n = [], 0
    for page in pages:
        text = open(page).read()
        # links inside code blocks are examples, not links
        text = re.sub(r"```.*?```", "", text, flags=re.S)
        for target in LINK.findall(text):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            n += 1
            path = os.path.normpath(os.path.join(os.path.dirname(page),
                                                 target.split("#")[0]))
            if not os.path.exists(path):
                broken.append(f"{os.path.relpath(page, root)}: {target}")
    for b in broken:
        print("broken:", b)
    print(f"{n} relative links in {len(pages)} pages, {len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
