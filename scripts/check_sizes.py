#!/usr/bin/env python3
"""Checks the sizes docs/layers.md sets: no source file over 600 lines, no function over 60.

Runs in a second over src/, apps/, include/ and python/src (ctest's Sizes.FilesAndFunctions).
A function's size is what clang-tidy's readability-function-size counts: the line of its
closing brace minus the line of its opening brace. Functions are found by braces, not by a
compiler: comments, strings and character literals are blanked first, then every `{` at
namespace or class scope whose declaration has a parameter list opens a function body (a
constructor's member initialisers are skipped). Lambdas and local classes count toward the
function around them.

    scripts/check_sizes.py [ROOT]     exit 1 when something is over (each listed), else 0
"""
import pathlib
import re
import sys

MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 60
FOLDERS = ("src", "apps", "include", "python/src")
SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}

# A literal or comment, blanked to spaces (newlines kept, so line numbers stay).
_BLANKED = re.compile(
    r'//[^\n]*|/\*.*?\*/|R"([^(\s]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
    re.S)
_SCOPE = re.compile(r"\b(namespace|class|struct|union|enum)\b|\bextern\s*$")
_NAME = re.compile(r"([~\w:<>]+(?:operator\s*[^\s(]+)?)\s*\($")


def blank(text):
    def spaces(m):
        return re.sub(r"[^\n]", " ", m.group(0))
    return _BLANKED.sub(spaces, text)


def strip_preprocessor(text):
    # Directives (continued lines too) carry no braces of the code around them.
    out, continued = [], False
    for line in text.split("\n"):
        directive = continued or line.lstrip().startswith("#")
        continued = directive and line.rstrip().endswith("\\")
        out.append(" " * len(line) if directive else line)
    return "\n".join(out)


def function_name(header):
    # The declarator before the parameter list that opens the header.
    depth = 0
    for i, ch in enumerate(header):
        if ch in "<":
            depth += 1
        elif ch in ">" and depth:
            depth -= 1
        elif ch == "(" and depth == 0:
            m = _NAME.search(header[: i + 1].rstrip("(").rstrip() + "(")
            return m.group(1) if m else "(function)"
    return "(function)"


def opens_function(header):
    # A definition's header has a parameter list and is neither a scope nor an initialiser.
    h = " ".join(header.split())
    if not h or "(" not in h or _SCOPE.search(h.split("(")[0]):
        return False
    before_params = h.split("(")[0]
    return "=" not in before_params and not h.startswith(("=", ",", ":"))


def initialiser_brace(header):
    # `Foo::Foo(int x) : a_{x}` (the brace of a member initialiser, not the body).
    h = " ".join(header.split())
    return bool(re.search(r"\)\s*(noexcept\s*)?:\s*[^{]*$", h) or re.search(r"\}\s*,[^{]*$", h)
                or re.search(r"\)\s*,\s*[\w:]+\s*$", h))


def functions(code):
    """(name, first line, size) of every function body at namespace or class scope."""
    found = []
    scopes = []  # one entry per open brace: "scope", "function", "init" or "other"
    header_start = 0
    line = 1
    body_start = {}
    i = 0
    while i < len(code):
        ch = code[i]
        if ch == "\n":
            line += 1
        elif ch in ";":
            if not scopes or scopes[-1] == "scope":
                header_start = i + 1
        elif ch == "{":
            inside_function = "function" in scopes
            header = code[header_start:i]
            if inside_function:
                kind = "other"
            elif initialiser_brace(header) and "(" in header:
                kind = "init"
            elif opens_function(header):
                kind = "function"
                body_start[len(scopes)] = (line, function_name(" ".join(header.split())))
            elif scopes and scopes[-1] not in ("scope",):
                kind = "other"
            elif _SCOPE.search(" ".join(header.split())) or not header.strip():
                kind = "scope"
            else:
                kind = "other"
            scopes.append(kind)
            if kind in ("scope",):
                header_start = i + 1
        elif ch == "}":
            kind = scopes.pop() if scopes else "scope"
            if kind == "function":
                first, name = body_start.pop(len(scopes))
                found.append((name, first, line - first))
            if kind != "init" and (not scopes or scopes[-1] == "scope"):
                header_start = i + 1
        i += 1
    return found


def check(root):
    problems = []
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in SUFFIXES or not path.is_file():
                continue
            rel = path.relative_to(root)
            text = path.read_text(encoding="utf-8", errors="replace")
            lines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
            if lines > MAX_FILE_LINES:
                problems.append(f"{rel}: {lines} lines (file over {MAX_FILE_LINES})")
            code = strip_preprocessor(blank(text))
            for name, first, size in functions(code):
                if size > MAX_FUNCTION_LINES:
                    problems.append(f"{rel}:{first}: function {name}: {size} lines "
                                    f"(over {MAX_FUNCTION_LINES})")
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    problems = check(root.resolve())
    for p in problems:
        print(p)
    if problems:
        return 1
    print(f"check_sizes: no file over {MAX_FILE_LINES} lines, no function over "
          f"{MAX_FUNCTION_LINES}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
