#!/usr/bin/env python3
"""Checks that the Markdown files name only files that exist, and that the READMEs stay short.

For every tracked *.md file (git ls-files; without git, every *.md outside .git and build*):
- a link target that is not a URL must exist relative to the document's folder, and a #anchor
  into a Markdown file must be one of its headings;
- a code span that is one word and looks like a path (has a '/' or ends in a source or document
  extension) must exist relative to the repository root, the document's folder or
  filter_lowstretch/ (a unit may omit its extension: core/stretch); a bare file name of a source
  extension may also be anywhere in the repository;
- a word of a longer code span or of a fenced block that has a '/' must exist when its first
  folder does (so `tests/x.py` and `atlas/x.h` are checked, `V/bin/python` is not).
Paths starting with build, ~, ../shared, / or $, and words with glob or placeholder characters,
are outputs, external or patterns: not checked. Exits 1 when a path is missing or README.md has
more than 150 lines or tests/bench/README.md more than 300.

usage: doc_paths.py [--root REPO]
"""
import argparse
import os
import re
import subprocess
import sys

SOURCE_EXTENSIONS = (".cpp", ".h", ".py", ".md", ".sh", ".mlx", ".txt", ".svg", ".png", ".dict")
MESH_EXTENSIONS = (".off", ".ply", ".obj")  # a bare mesh name is one of the external test meshes
NOT_CHECKED = ("build", "~", "../shared", "/", "$", "http:", "https:", "mailto:")
PATTERN_CHARS = set("*{}<>[]?|")
UNIT = ("", ".h", ".cpp", ".py")
MAX_LINES = {"README.md": 150, "tests/bench/README.md": 300}


def markdown_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "*.md"], capture_output=True, text=True, check=True)
        files = [f for f in out.stdout.split() if os.path.exists(os.path.join(root, f))]
        if files:
            return files, set(subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True,
                                             check=True).stdout.split())
    except (OSError, subprocess.CalledProcessError):
        pass
    files, every = [], set()
    for folder, dirs, names in os.walk(root):
        dirs[:] = [d for d in dirs if d != ".git" and not d.startswith("build")]
        for name in names:
            rel = os.path.relpath(os.path.join(folder, name), root)
            every.add(rel)
            if name.endswith(".md"):
                files.append(rel)
    return sorted(files), every


def slug(heading):
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path):
    with open(path, encoding="utf-8") as f:
        return {slug(line.lstrip("#")) for line in f if re.match(r"#{1,6} ", line)}


def looks_like_path(word):
    return "/" in word or word.endswith(SOURCE_EXTENSIONS + MESH_EXTENSIONS)


def skipped(word):
    return (not word or word.startswith(NOT_CHECKED) or any(c in PATTERN_CHARS for c in word)
            or word.startswith("-") or "..." in word or re.fullmatch(r"\.\w+", word))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    root = parser.parse_args().root
    docs, tracked = markdown_files(root)
    basenames = {os.path.basename(p) for p in tracked}
    problems, checked = [], 0

    for doc in docs:
        folder = os.path.dirname(doc)
        bases = [root, os.path.join(root, folder), os.path.join(root, "filter_lowstretch")]

        def exists(word):  # a unit may be named without its extension: core/stretch
            return any(os.path.exists(os.path.join(base, word + ext)) for base in bases for ext in UNIT)

        def first_folder_exists(word):
            return word.split("/")[0] not in ("", ".", "..") and exists(word.split("/")[0])

        with open(os.path.join(root, doc), encoding="utf-8") as f:
            lines = f.read().split("\n")
        count = len(lines) - (lines[-1] == "")
        if count > MAX_LINES.get(doc, count):
            problems.append(f"{doc}: {count} lines, more than {MAX_LINES[doc]}")

        # (line number, text) of prose, and fenced blocks' lines apart
        prose, fenced, in_fence = [], [], False
        for number, line in enumerate(lines, 1):
            if line.lstrip().startswith("```"):
                in_fence = not in_fence
            elif in_fence:
                fenced.append((number, line))
            else:
                prose.append((number, line))
        text = "\n".join(line for _, line in prose)
        line_of = [number for number, line in prose for _ in range(len(line) + 1)]

        names = []  # (line, word, how): how is "link", "span" or "word"
        for found in re.finditer(r"\]\(([^)\s]+)\)", text):
            names.append((line_of[found.start(1)], found.group(1), "link"))
        for found in re.finditer(r"(`+)(.+?)\1", text, re.S):
            span = found.group(2).strip()
            if not re.search(r"\s", span):
                names.append((line_of[found.start(2)], span, "span"))
            else:
                names += [(line_of[found.start(2)], w, "word") for w in re.split(r"[\s\"'(),=;]+", span)]
        for number, line in fenced:
            names += [(number, w, "word") for w in re.split(r"[\s\"'(),=;]+", line)]

        for number, name, how in names:
            if how == "link":
                if re.match(r"[a-z]+:", name):
                    continue
                target, _, anchor = name.partition("#")
                path = os.path.normpath(os.path.join(root, folder, target)) if target else os.path.join(root, doc)
                checked += 1
                if not os.path.exists(path):
                    problems.append(f"{doc}:{number}: names {target}, which does not exist")
                elif anchor and path.endswith(".md") and anchor not in anchors(path):
                    problems.append(f"{doc}:{number}: names {name}, which has no heading #{anchor}")
                continue
            word = name.split("::")[0].rstrip(".,:;")
            if skipped(word) or not looks_like_path(word):
                continue
            if how == "word" and not ("/" in word and first_folder_exists(word)):
                continue
            if how == "span" and "/" not in word and word.endswith(MESH_EXTENSIONS):
                continue
            checked += 1
            if exists(word) or ("/" not in word and word in basenames):
                continue
            problems.append(f"{doc}:{number}: names {word}, which does not exist")

    for problem in problems:
        print(problem)
    if problems:
        return 1
    sizes = ", ".join(f"{doc} {sum(1 for _ in open(os.path.join(root, doc), encoding='utf-8'))} lines"
                      for doc in MAX_LINES if os.path.exists(os.path.join(root, doc)))
    print(f"doc_paths: {len(docs)} Markdown files, {checked} paths named, all exist; {sizes}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
