#!/usr/bin/env python3
"""Function lengths in C++ sources: every function body (free functions, member functions defined in
class bodies or out of line; lambdas count as part of the function they are written in) with its length
in lines, from the line of its name to its closing brace.

  check-function-length.py [--max N] [--top K] DIR_OR_FILE...

Lists the K longest functions (default 10); with --max, exits 1 when a function is longer than N lines
and names each one. A brace scanner, not a parser: comments, string and character literals are blanked
first; a '{' opens a function body when the text before it ends in a parameter list (optionally followed
by const / noexcept / override / a trailing return type or a constructor's initialiser list) that is not
a control statement's or a lambda's.
"""
import argparse
import os
import re
import sys

CONTROL = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "alignof", "static_assert",
           "defined", "throw", "new", "delete"}
SCOPES = re.compile(r"\b(namespace|class|struct|union|enum|extern)\b")


def blank(text):
    """Comments, string and character literals replaced by spaces (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i + 2)
            delim = text[i + 2:k]
            j = text.find(")" + delim + '"', k)
            j = n if j < 0 else j + len(delim) + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                out.append(c)
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def matching_open(s, close):
    """Index of the '(' matching the ')' at s[close]."""
    depth = 0
    for k in range(close, -1, -1):
        if s[k] == ")":
            depth += 1
        elif s[k] == "(":
            depth -= 1
            if depth == 0:
                return k
    return -1


TAIL = re.compile(r"\)\s*((const|noexcept|override|final|mutable|volatile|&|&&)\s*)*(->[^;{}()]*)?$")


def function_start(s, brace):
    """For the '{' at s[brace]: the index of the function's name if it opens a function body, else -1."""
    k = brace - 1
    while k >= 0 and s[k] not in ";{}":
        k -= 1
    head = s[k + 1:brace]
    if not head.strip():
        return -1
    # Constructor initialiser list: "Name(args) : a(x), b(y) {" -- the parameter list is the one
    # before the first single ':' at depth 0.
    m = None
    depth = 0
    for i, ch in enumerate(head):
        if ch in "([<":
            depth += 1
        elif ch in ")]>":
            depth -= 1
        elif ch == ":" and depth == 0 and head[i - 1:i] != ":" and head[i + 1:i + 2] != ":":
            m = i
            break
    sig = head[:m] if m is not None else head
    t = TAIL.search(sig.rstrip())
    if not t:
        return -1
    close = k + 1 + t.start()
    open_ = matching_open(s, close)
    if open_ < 0:
        return -1
    j = open_ - 1
    while j >= 0 and s[j].isspace():
        j -= 1
    if j < 0 or s[j] == "]":  # a lambda
        return -1
    e = j
    while j >= 0 and (s[j].isalnum() or s[j] in "_~:"):
        j -= 1
    name = s[j + 1:e + 1].split("::")[-1]
    if not name or name in CONTROL or not (name[0].isalpha() or name[0] in "_~"):
        if s[e] == ">" or s[e] in "=+-*/<!&|^%[]()":  # operator() / operator< / template
            pass
        else:
            return -1
    if SCOPES.search(head[:open_ - (k + 1)]) and "(" not in head[:open_ - (k + 1)]:
        return -1
    return j + 1


def functions(path):
    text = blank(open(path, encoding="utf-8", errors="replace").read())
    line_at = [0] * (len(text) + 1)
    line = 1
    for i, ch in enumerate(text):
        line_at[i] = line
        if ch == "\n":
            line += 1
    found = []
    i, n = 0, len(text)
    while i < n:
        if text[i] == "{":
            start = function_start(text, i)
            if start >= 0:
                depth, j = 0, i
                while j < n:
                    if text[j] == "{":
                        depth += 1
                    elif text[j] == "}":
                        depth -= 1
                        if depth == 0:
                            break
                    j += 1
                name = re.findall(r"[\w:~]+", text[start:i])
                found.append((line_at[j] - line_at[start] + 1, path, line_at[start], name[0] if name else "?"))
                i = j + 1
                continue
        i += 1
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--max", type=int, default=None, help="fail on a function longer than this many lines")
    ap.add_argument("--top", type=int, default=10, help="list this many of the longest functions")
    a = ap.parse_args()
    files = []
    for p in a.paths:
        if os.path.isdir(p):
            for root, _, names in os.walk(p):
                files += [os.path.join(root, f) for f in sorted(names) if f.endswith((".cpp", ".hpp", ".h", ".cc"))]
        else:
            files.append(p)
    all_functions = sorted((f for path in files for f in functions(path)), key=lambda f: -f[0])
    for length, path, line, name in all_functions[:a.top]:
        print(f"{length:5d}  {path}:{line}  {name}")
    if a.max is not None:
        over = [f for f in all_functions if f[0] > a.max]
        for length, path, line, name in over:
            print(f"error: {path}:{line}: {name} is {length} lines long (at most {a.max})", file=sys.stderr)
        return 1 if over else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
