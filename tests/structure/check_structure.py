#!/usr/bin/env python3
"""The shape of the code (issue 26), checked by ctest:

  - model::Effect has at most 10 virtual functions (include/kinergy/model/effect.hpp);
  - no function in src/ is over 120 lines (from its head to its closing brace);
  - no include cycle among the modules of src/ (a module: a directory under src/ with its headers
    under include/kinergy/ of the same name; src/*.cpp and include/kinergy/*.hpp are the top
    module, "top": the pipeline for one scene, problem.hpp).

What breaks a rule may be listed in KNOWN below with its present figure (while a change that
mends it is under way): the check fails when anything new breaks a rule, when a listed figure
grows, and when a listed entry no longer breaks it (so that the list only shrinks). It is empty. Usage: check_structure.py SOURCE_DIR [--report]
"""
import os
import re
import sys

MAX_VIRTUALS = 10
MAX_LINES = 120

# What still breaks a rule, with its present figure (lines, virtual functions, modules in a cycle).
KNOWN = {}


def strip(text):
    """The text with comments, strings and character literals blanked (newlines kept)."""
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
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            k = text.find("(", i)
            delim = text[i + 2:k]
            j = text.find(")" + delim + '"', k)
            j = n if j < 0 else j + len(delim) + 2
            out.append('""' + "".join(ch if ch == "\n" else " " for ch in text[i + 2:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # a digit separator (100'000)
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else|try)\b")
TYPE_HEAD = re.compile(r"\b(namespace|class|struct|union|enum)\b")


def functions(path, rel):
    """(name, first line, lines) of every function body in a file (lambdas count with their function)."""
    text = strip(open(path, encoding="utf-8").read())
    stack = []  # kinds of open blocks: "func", "type", "other"
    head_start = 0  # index where the current statement's text starts
    out = []
    line_of = [0] * (len(text) + 1)
    line = 1
    for i, ch in enumerate(text):
        line_of[i] = line
        if ch == "\n":
            line += 1
    line_of[len(text)] = line
    opened = []  # (kind, start index of its head, name)
    for i, ch in enumerate(text):
        if ch == ";":
            head_start = i + 1
        elif ch == "{":
            head = text[head_start:i]
            kind = "other"
            name = ""
            if "func" in stack:
                kind = "other"
            elif head.strip().startswith("#"):
                kind = "other"
            elif TYPE_HEAD.search(head) and "(" not in head.split("{")[0].split(":")[0]:
                kind = "type"
            elif head.strip() in ("", "extern") or head.strip().startswith('extern "'):
                kind = "type"
            elif ")" in head and not CONTROL.match(head) and "=" not in head[: head.find("(")]:
                kind = "func"
                m = re.search(r"([~\w:]+(?:<[^<>]*>)?)\s*\(", head)
                name = m.group(1) if m else "?"
            stack.append(kind)
            lead = len(head) - len(head.lstrip())
            opened.append((kind, head_start + lead, name))
            head_start = i + 1
        elif ch == "}":
            if stack:
                kind, start, name = opened.pop()
                stack.pop()
                if kind == "func":
                    out.append((name, line_of[start], line_of[i] - line_of[start] + 1))
            head_start = i + 1
    return out


def effect_virtuals(root):
    text = strip(open(os.path.join(root, "include/kinergy/model/effect.hpp"), encoding="utf-8").read())
    m = re.search(r"class Effect\s*\{", text)
    depth, j = 1, m.end()
    while depth:
        depth += {"{": 1, "}": -1}.get(text[j], 0)
        j += 1
    body = text[m.end():j]
    return len(re.findall(r"\bvirtual\b(?!\s*~)", body))


def module_of(root, path):
    rel = os.path.relpath(path, root).replace(os.sep, "/")
    parts = rel.split("/")
    if parts[0] == "src":
        return parts[1] if len(parts) > 2 else "top"
    if parts[0] == "include":
        return parts[2] if len(parts) > 3 else "top"
    return None


def include_graph(root):
    edges = {}
    for base in ("src", "include/kinergy"):
        for d, _, files in os.walk(os.path.join(root, base)):
            for f in files:
                if not f.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.join(d, f)
                mod = module_of(root, path)
                edges.setdefault(mod, set())
                for inc in re.findall(r'^\s*#\s*include\s*"([^"]+)"', open(path, encoding="utf-8").read(), re.M):
                    if inc.startswith("kinergy/"):
                        target = os.path.join(root, "include", inc)
                    else:
                        target = os.path.normpath(os.path.join(d, inc))
                    if not os.path.exists(target):
                        continue
                    other = module_of(root, target)
                    if other and other != mod:
                        edges[mod].add(other)
    return edges


def cycles(edges):
    """The strongly connected components of more than one module (Tarjan)."""
    index, low, on, stack, out = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def main():
    root = sys.argv[1]
    report = "--report" in sys.argv
    found = {}
    v = effect_virtuals(root)
    if v > MAX_VIRTUALS:
        found["virtuals model::Effect"] = v
    for d, _, files in os.walk(os.path.join(root, "src")):
        for f in sorted(files):
            if f.endswith((".cpp", ".hpp")):
                path = os.path.join(d, f)
                rel = os.path.relpath(path, root).replace(os.sep, "/")
                for name, first, lines in functions(path, rel):
                    if lines > MAX_LINES:
                        found["function " + rel + " " + name] = lines
    cyc = cycles(include_graph(root))
    if cyc:
        found["cycle"] = max(len(c) for c in cyc)
    print("model::Effect: %d virtual functions (at most %d)" % (v, MAX_VIRTUALS))
    for c in cyc:
        print("include cycle among %d modules: %s" % (len(c), ", ".join(c)))
    bad = []
    for key, figure in sorted(found.items()):
        known = KNOWN.get(key)
        if key.startswith("function"):
            print("%s: %d lines (at most %d)" % (key, figure, MAX_LINES))
        if known is None:
            bad.append("%s: %d — new; the rule is broken" % (key, figure))
        elif figure > known:
            bad.append("%s: %d — grew from %d" % (key, figure, known))
        elif figure < known and not report:
            bad.append("%s: %d — smaller than the %d listed in KNOWN: write the new figure there" % (key, figure, known))
    for key in sorted(KNOWN):
        if key not in found:
            bad.append("%s: no longer breaks its rule — remove it from KNOWN" % key)
    if bad:
        print("\n".join(["FAILED:"] + bad))
        return 0 if report else 1
    print("every rule holds" if not KNOWN else "still listed in KNOWN: %d" % len(KNOWN))
    return 0


if __name__ == "__main__":
    sys.exit(main())
