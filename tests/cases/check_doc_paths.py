"""Every repository path named in the documentation exists.

  check_doc_paths.py ROOT

Scans README.md, doc/**/*.md, the comments of prm/**/*.prm and of
benchmarks/*.sh under ROOT (the repository) for
  - markdown link and image targets, [text](target): resolved against the
    page's own folder, as a renderer does; a target '#anchor' (or
    'page.md#anchor') must name a heading of that page;
  - paths starting with a top-level folder of the repository (source/,
    include/, tests/, prm/, meshes/, benchmarks/, scripts/, doc/, preload/),
    in backticks or plain text: resolved against ROOT;
  - '../shared/...': resolved against ROOT; checked only where ROOT/../shared
    exists (CI), skipped otherwise;
  - a path with a '/' and a source extension (.cc, .h, .prm, .py, .sh, .geo)
    under no known folder (e.g. 'state/quadrature_history.h'): some file of
    the repository must end with it.
Placeholders match anything: '<name>', '{a,b}', '*', '?', runs of one
capital letter ('solution_SSSSS.vtu') and capitals inside a file name
('scaling-TAG.csv'); 'folder/...' (or '…') needs only the folder. A path
given at a git revision, 'abc1234:source/x.cc' (a file since removed, as
`git show` names it), is not checked. results/, build*/ and other generated
folders are not checked: a path is only taken where it starts at a word
boundary (so 'results/cup/prm/x.prm' is skipped whole), and paths without a
'/' (output files such as history.csv) are not checked.

Exit 1 with 'file:line: missing path' for each path that does not exist."""
import glob
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
TOP = ("source", "include", "tests", "prm", "meshes", "benchmarks", "scripts",
       "doc", "preload")
SRC_EXT = ("cc", "h", "prm", "py", "sh", "geo")
# Folders whose contents are generated (never in git) or outside the repo.
GENERATED = ("results", "build", "build-debug", "out", "OLD", "NEW", "tmp",
             "share", "bin", "lib", "opt", "usr", "etc", "home", "root")

PATH_CHARS = r"A-Za-z0-9_.\-/<>*?{},+~…"
# A path token: not preceded by a path character (so 'x/prm/a.prm' and
# 'results/...' are skipped whole), one of the known folders, then path chars.
TOP_RE = re.compile(r"(?<![A-Za-z0-9_.\-/<>*~$])((?:\.\./shared/|(?:%s)/)[%s]*)"
                    % ("|".join(TOP), PATH_CHARS))
SUFFIX_RE = re.compile(r"(?<![A-Za-z0-9_.\-/<>*~$])([A-Za-z0-9_\-]+(?:/[A-Za-z0-9_.\-]+)+\.(?:%s))\b"
                       % "|".join(SRC_EXT))
REV_RE = re.compile(r"[0-9a-f]{7,40}\^?:$")
LINK_RE = re.compile(r"\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")

problems = []
checked = 0


def placeholder_glob(path):
    """The path with its placeholders as glob wildcards, or None if it has none."""
    g = path
    for ell in ("...", "…"):
        if ell in g:
            g = g[:g.index(ell)]
            g = g + "*" if not g.endswith("/") else g + "*"
    g = re.sub(r"<[^<>/]*>", "*", g)
    g = re.sub(r"\{[^{}/]*\}", "*", g)
    g = re.sub(r"([A-Z])\1{2,}", "*", g)
    g = re.sub(r"(?<=[_\-.])[A-Z]{3,}(?=[_\-.])", "*", g)
    if g == path and not any(c in path for c in "*?"):
        return None
    return g


def exists(abs_path):
    if os.path.exists(abs_path):
        return True
    g = placeholder_glob(abs_path)
    return g is not None and bool(glob.glob(g))


def clean(tok):
    # Trailing sentence punctuation and unbalanced brackets are not the path's.
    while tok and tok[-1] in ".,;:!?)'\"`}>":
        if tok[-1] == ">" and tok.count("<") >= tok.count(">"):
            break
        if tok[-1] == "}" and tok.count("{") >= tok.count("}"):
            break
        if tok.endswith("...") or tok.endswith("…"):
            break
        tok = tok[:-1]
    if tok.endswith(",") or tok.endswith("="):
        tok = tok[:-1]
    return tok


def slug(heading):
    """GitHub's anchor for a heading."""
    h = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return h.replace(" ", "-")


def anchors_of(md_path):
    out, seen = set(), {}
    in_code = False
    with open(md_path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_code = not in_code
            if in_code:
                continue
            m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                s = slug(m.group(1))
                n = seen.get(s, 0)
                seen[s] = n + 1
                out.add(s if n == 0 else "%s-%d" % (s, n))
    return out


_reported = set()


def report(rel, line, what, path):
    key = (rel, line, path.partition("#")[0])
    if key not in _reported:  # a link target is also a path token
        _reported.add(key)
        problems.append("%s:%d: %s %s" % (rel, line, what, path))


def check_token(rel, line, tok):
    global checked
    tok = clean(tok)
    if not tok or "/" not in tok:
        return
    if tok.startswith("../shared/"):
        shared = os.path.join(os.path.dirname(ROOT), "shared")
        if not os.path.isdir(shared):
            return
        checked += 1
        if not exists(os.path.normpath(os.path.join(ROOT, tok))):
            report(rel, line, "missing", tok)
        return
    if tok.split("/")[0] not in TOP:
        return
    checked += 1
    if not exists(os.path.join(ROOT, tok)):
        report(rel, line, "missing", tok)


_files = None


def repo_files():
    global _files
    if _files is None:
        _files = []
        for d, dirs, files in os.walk(ROOT):
            dirs[:] = [x for x in dirs
                       if not x.startswith(".") and x not in GENERATED
                       and not x.startswith("build")]
            for f in files:
                _files.append(os.path.relpath(os.path.join(d, f), ROOT))
    return _files


def check_suffix(rel, line, tok):
    global checked
    first = tok.split("/")[0]
    if first in TOP or first in GENERATED or first.startswith("build") \
            or first in ("..", "."):
        return
    checked += 1
    if not any(f == tok or f.endswith("/" + tok) for f in repo_files()):
        report(rel, line, "no file ends with", tok)


def check_link(rel, line, target):
    global checked
    if re.match(r"[a-z][a-z0-9+.\-]*:", target):  # http:, https:, mailto:
        return
    path, _, anchor = target.partition("#")
    page = os.path.join(ROOT, rel)
    checked += 1
    if path:
        abs_path = os.path.normpath(os.path.join(os.path.dirname(page), path))
        shared = os.path.join(os.path.dirname(ROOT), "shared")
        if abs_path.startswith(shared + os.sep) and not os.path.isdir(shared):
            return  # ../shared exists beside the repository in CI only
        if not exists(abs_path):
            report(rel, line, "broken link", target)
            return
        page = abs_path
    if anchor and page.endswith(".md") and os.path.isfile(page):
        if anchor not in anchors_of(page):
            report(rel, line, "no heading for anchor", target)


def comment_lines(abs_path):
    """(line number, comment text) of a .prm or shell file."""
    with open(abs_path, encoding="utf-8", errors="replace") as f:
        for n, line in enumerate(f, 1):
            s = line.lstrip()
            if s.startswith("#!"):
                continue
            i = line.find("#")
            if i >= 0:
                yield n, line[i + 1:]


def scan_text(rel, lines):
    for n, text in lines:
        for m in TOP_RE.finditer(text):
            if REV_RE.search(text[max(0, m.start() - 42):m.start()]):
                continue
            check_token(rel, n, m.group(1))
        for m in SUFFIX_RE.finditer(text):
            check_suffix(rel, n, m.group(1))


def scan_markdown(rel):
    abs_path = os.path.join(ROOT, rel)
    with open(abs_path, encoding="utf-8") as f:
        text = f.read()
    scan_text(rel, enumerate(text.split("\n"), 1))
    for m in LINK_RE.finditer(text):
        check_link(rel, text.count("\n", 0, m.start(1)) + 1, m.group(1))


def main():
    md = ["README.md"] + sorted(
        os.path.relpath(p, ROOT)
        for p in glob.glob(os.path.join(ROOT, "doc", "**", "*.md"), recursive=True))
    prm = sorted(os.path.relpath(p, ROOT)
                 for p in glob.glob(os.path.join(ROOT, "prm", "**", "*.prm"), recursive=True))
    sh = sorted(os.path.relpath(p, ROOT)
                for p in glob.glob(os.path.join(ROOT, "benchmarks", "*.sh")))
    for rel in md:
        if os.path.isfile(os.path.join(ROOT, rel)):
            scan_markdown(rel)
    for rel in prm + sh:
        scan_text(rel, comment_lines(os.path.join(ROOT, rel)))
    if problems:
        print("\n".join(problems))
        print("%d of %d paths named in README.md, doc/, prm/ and benchmarks/ "
              "do not exist" % (len(problems), checked))
        return 1
    print("all %d paths named in README.md, doc/, prm/ and benchmarks/ exist"
          % checked)
    return 0


if __name__ == "__main__":
    sys.exit(main())
