#!/usr/bin/env python3
"""Checks the repository's Markdown docs: every relative link resolves and every named source file exists.

    scripts/check-docs.py [REPO_ROOT] [FILE.md ...]

Docs checked (default): README.md, CHANGELOG.md, bench/README.md, features/README.md, docs/**/*.md,
python/**/*.md, data/**/README.md. For each file:

- every Markdown link or image `[text](target)` whose target is not a URL (http:, https:, mailto:)
  must name an existing file or directory relative to the Markdown file; a `#anchor` (alone or after a
  .md target) must be the GitHub-style slug of a heading in the target file;
- every path in backticks that ends in .hpp, .cpp, .h, .json, .py or .sh must exist:
  relative to the repository root, relative to the Markdown file, or (a bare file name, or a path
  whose trailing components match) somewhere in the tree. Brace lists (`boolean_*.{hpp,cpp}`) and `*`
  globs are expanded. Skipped: paths under build/, out/ or DIR/, the files the tools write
  (OUTPUT_NAMES), placeholders (`<id>`, an upper-case stem such as `STUDY.json`) and code blocks.

Exits 1 and prints one line per problem (file:line: message), else prints a summary and exits 0.
Standard library only.
"""
import fnmatch
import os
import re
import sys

SKIP_DIRS = {".git", "build", "build-asan", "build-fuzz", "out", "__pycache__", "node_modules"}
SOURCE_EXT = ("hpp", "cpp", "h", "json", "py", "sh")
# Files the tools write (named in the docs as outputs, not as files of the repository).
OUTPUT_NAMES = {"report.json", "grid_report.json", "status.json", "config.json", "network.json", "network_results.json"}
LINK_RE = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
CODE_SPAN_RE = re.compile(r"(`+)(.+?)\1")
PATH_RE = re.compile(r"^[A-Za-z0-9_.*{},/+-]+\.(?:%s)$" % "|".join(SOURCE_EXT + ("{hpp,cpp}",)))


def default_docs(root):
    docs = []
    for name in ("README.md", "CHANGELOG.md", "bench/README.md", "features/README.md"):
        if os.path.isfile(os.path.join(root, name)):
            docs.append(name)
    for top in ("docs", "python", "data"):
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS)
            for f in sorted(filenames):
                if f.endswith(".md") and (top != "data" or f == "README.md"):
                    docs.append(os.path.relpath(os.path.join(dirpath, f), root))
    return docs


def tree_files(root):
    files = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS]
        for f in filenames:
            files.append(os.path.relpath(os.path.join(dirpath, f), root).replace(os.sep, "/"))
    return files


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"`|\*\*|__", "", heading.strip()).lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen = {}
        result = set()
        in_fence = False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.lstrip().startswith("```"):
                    in_fence = not in_fence
                m = None if in_fence else re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
                if m:
                    s = slug(m.group(1))
                    n = seen.get(s, 0)
                    seen[s] = n + 1
                    result.add(s if n == 0 else "%s-%d" % (s, n))
        cache[path] = result
    return cache[path]


def expand(pattern):
    m = re.search(r"\{([^}]*)\}", pattern)
    if not m:
        return [pattern]
    out = []
    for alt in m.group(1).split(","):
        out.extend(expand(pattern[:m.start()] + alt + pattern[m.end():]))
    return out


def path_exists(name, doc_dir, root, files):
    for candidate in expand(name):
        if "*" in candidate:
            if any(fnmatch.fnmatch(f, candidate) or fnmatch.fnmatch(f, "*/" + candidate) for f in files):
                continue
            return False
        if os.path.exists(os.path.join(root, candidate)) or os.path.exists(os.path.join(doc_dir, candidate)):
            continue
        tail = candidate.lstrip("./")
        if any(f == tail or f.endswith("/" + tail) for f in files):
            continue
        return False
    return True


def check_doc(doc, root, files):
    problems = []
    path = os.path.join(root, doc)
    doc_dir = os.path.dirname(path)
    in_fence = False
    with open(path, encoding="utf-8") as f:
        lines = f.readlines()
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
            continue
        if in_fence or line.startswith("    "):
            continue  # code blocks: examples, not references
        where = "%s:%d" % (doc, number)
        text = CODE_SPAN_RE.sub(lambda m: " " * len(m.group(0)), line)
        for m in LINK_RE.finditer(text):
            target = m.group(1)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                continue
            file_part, _, anchor = target.partition("#")
            target_path = os.path.normpath(os.path.join(doc_dir, file_part)) if file_part else path
            if not os.path.exists(target_path):
                problems.append("%s: broken link '%s' (no file %s)" % (where, target, os.path.relpath(target_path, root)))
                continue
            if os.path.relpath(target_path, root).startswith(".."):
                problems.append("%s: link '%s' leaves the repository" % (where, target))
                continue
            if anchor and target_path.endswith(".md") and anchor not in anchors(target_path):
                problems.append("%s: link '%s': no heading with anchor #%s in %s" % (where, target, anchor, os.path.relpath(target_path, root)))
        for m in CODE_SPAN_RE.finditer(line):
            for token in m.group(2).split():
                token = token.strip(",;:()")
                if not PATH_RE.match(token) or "<" in token:
                    continue
                if token.startswith(("build/", "out/", "DIR/", "/")) or "://" in token:
                    continue
                stem = os.path.basename(token).split(".")[0]
                if os.path.basename(token) in OUTPUT_NAMES or (stem.isupper() and len(stem) > 1):
                    continue
                if not path_exists(token, doc_dir, root, files):
                    problems.append("%s: `%s` names no file in the repository" % (where, token))
    return problems


def main(argv):
    root = os.path.abspath(argv[1]) if len(argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    docs = argv[2:] or default_docs(root)
    files = tree_files(root)
    problems = []
    for doc in docs:
        if not os.path.isfile(os.path.join(root, doc)):
            problems.append("%s: no such document" % doc)
            continue
        problems.extend(check_doc(doc, root, files))
    for p in problems:
        print(p)
    if problems:
        print("check-docs: %d problem(s) in %d document(s)" % (len(problems), len(docs)))
        return 1
    print("check-docs: %d documents, every relative link and named file exists" % len(docs))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
