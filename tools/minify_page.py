#!/usr/bin/env python3
"""minify_page.py IN OUT [TERSER] — the page as the browser build ships it: web/index.html without its
comments, blank lines and indentation (the comments are for whoever reads the source; they were a
third of what the page's HTML cost a student's first load). Only whole-line // comments are
dropped from scripts, so code and strings are never cut; the build runs this after each link.
A `<script data-inline src="NAME"></script>` is replaced by the script NAME (beside IN) written
inline: one request, and the page's scripts stay in files of their own in the source. With TERSER
(Debian's terser), each script is then compacted and its local names shortened; its global names
stay, for lab.js and the page's HTML call them (1.1 KB less gzip)."""
import os
import re
import subprocess
import sys

text = open(sys.argv[1], encoding="utf-8").read()
folder = os.path.dirname(os.path.abspath(sys.argv[1]))


def inline(match):
    with open(os.path.join(folder, match.group(1)), encoding="utf-8") as script:
        return "<script>\n" + script.read() + "\n</script>"


text = re.sub(r'<script data-inline src="([A-Za-z0-9_.-]+)"></script>', inline, text)
text = re.sub(r"<!--.*?-->", "", text, flags=re.S)
# CSS comments: the page's scripts hold no "/*" (the check below keeps it so).
style = text.find("<style>"), text.find("</style>")
if "/*" in text[: style[0]] or "/*" in text[style[1]:]:
    sys.exit("minify_page.py: a /* outside <style>: comments there are not stripped safely")
text = text[: style[0]] + re.sub(r"/\*.*?\*/", "", text[style[0] : style[1]], flags=re.S) + text[style[1]:]
lines = [line.strip() for line in text.split("\n")]
out = "\n".join(line for line in lines if line and not line.startswith("//")) + "\n"


def terse(match):
    done = subprocess.run([sys.argv[3], "--compress", "--mangle"], input=match.group(1), capture_output=True, text=True)
    if done.returncode != 0 or not done.stdout.strip():
        sys.exit("minify_page.py: terser failed on a script of " + sys.argv[1] + ":\n" + done.stderr)
    return "<script>" + done.stdout.strip() + "</script>"


if len(sys.argv) > 3:
    out = re.sub(r"<script>\n(.*?)\n</script>", terse, out, flags=re.S)
with open(sys.argv[2], "w", encoding="utf-8") as f:
    f.write(out)
