#!/usr/bin/env python3
"""The atlas's code stays small: no file in filter_lowstretch/atlas/ over 400 lines, no function there
over 60 (from its signature's first line to its closing brace). Usage: code_shape.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

MOST_FILE_LINES = 400
MOST_FUNCTION_LINES = 60
CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|else|do|try)\b")


def code_only(text: str) -> str:
    """The text with comments, strings and character literals blanked (line breaks kept)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def long_functions(path: pathlib.Path):
    """(name, lines) of each function or method body longer than MOST_FUNCTION_LINES."""
    lines = code_only(path.read_text()).split("\n")
    stack = []  # (line of the block's header start, is a function)
    found = []
    header_start = 0
    for number, line in enumerate(lines):
        if not line.strip():
            continue
        for i, char in enumerate(line):
            if char == "{":
                before = "\n".join(lines[header_start:number]) + "\n" + line[:i]
                header = before.strip().split(";")[-1].split("}")[-1]
                is_function = bool(re.search(r"\)\s*(const|override|noexcept|final|\s)*(->[^{]*)?(:[^{]*)?$", header.strip())) \
                    and not CONTROL.match(header.strip()) and not re.search(r"\]\s*\([^()]*\)[^()]*$", header) \
                    and not any(kind for kind, _ in stack)  # a block inside a function is part of it
                stack.append((is_function, number - header.strip().count("\n")))
            elif char == "}" and stack:
                is_function, start = stack.pop()
                if is_function and number - start + 1 > MOST_FUNCTION_LINES:
                    found.append((start + 1, number - start + 1))
            if char in "{};":
                header_start = number
    return found


def main() -> int:
    atlas = pathlib.Path(sys.argv[1]) / "filter_lowstretch" / "atlas"
    wrong = []
    files = sorted(p for p in atlas.rglob("*") if p.suffix in (".h", ".cpp"))
    for path in files:
        count = len(path.read_text().splitlines())
        if count > MOST_FILE_LINES:
            wrong.append(f"{path}: {count} lines, more than {MOST_FILE_LINES}")
        for line, length in long_functions(path):
            wrong.append(f"{path}:{line}: a function of {length} lines, more than {MOST_FUNCTION_LINES}")
    print(f"{len(files)} files checked")
    for w in wrong:
        print("FAIL", w)
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
