"""The rules of the public header's contract, checked on the header itself, run by ctest:

    python3 tests/header/check_contract.py include/polymass/polymass.h <project version> \
        [tests/header/c99_pedantic.c tests/header/cxx17_pedantic.cpp]

The rules (the header's STABILITY and ERRORS sections promise them):
  - every public struct (`typedef struct polymass_X {`) starts with
    `uint32_t struct_size;` and has polymass_sizeof_X, polymass_X_init and
    POLYMASS_X_INIT;
  - every POLYMASS_API function's comment (the one before it, or before the
    group of declarations it belongs to) says "Since N.M", a version no later
    than the project's;
  - every function returning int32_t (a status) has a "Returns" sentence
    naming its statuses, each a status the header defines (POLYMASS_OK,
    POLYMASS_ERROR_X or its short form _X);
  - no name ends in `_with_options`: options are per call, one way;
  - the header's compile tests (the files given after the version) name
    every function, so that a function added to the header is compiled at
    its type too.

The checker must be able to fail: the same run breaks copies of the real
header one rule at a time (each struct, each function in turn) and requires
the checker to reject every broken copy for the rule that was broken.
"""

import re
import sys
import tempfile
import unittest
from dataclasses import dataclass
from pathlib import Path

HEADER = Path()
PROJECT_VERSION = (0, 0)
COMPILE_TESTS = []


@dataclass
class Item:
    kind: str  # "comment", "directive" or "statement"
    text: str


def _comment_end(text, start):
    end = text.find("*/", start + 2)
    return len(text) if end < 0 else end + 2


def _directive_end(text, start):
    end = start
    while True:
        newline = text.find("\n", end)
        if newline < 0:
            return len(text)
        if text[newline - 1] != "\\":
            return newline
        end = newline + 1


def _statement_end(text, start):
    """End of a declaration: its `;` outside braces, comments skipped."""
    depth = 0
    position = start
    while position < len(text):
        if text.startswith("/*", position):
            position = _comment_end(text, position)
            continue
        character = text[position]
        if character == "{":
            depth += 1
        elif character == "}":
            depth -= 1
        elif character == ";" and depth == 0:
            return position + 1
        position += 1
    return len(text)


def scan(text):
    """The header as a list of comments, preprocessor lines and statements."""
    items = []
    position = 0
    while position < len(text):
        if text[position].isspace():
            position += 1
        elif text.startswith("/*", position):
            end = _comment_end(text, position)
            items.append(Item("comment", text[position:end]))
            position = end
        elif text[position] == "#":
            end = _directive_end(text, position)
            items.append(Item("directive", text[position:end]))
            position = end
        elif text.startswith('extern "C" {', position):
            position += len('extern "C" {')
        elif text[position] == "}":  # the end of extern "C"
            position += 1
        else:
            end = _statement_end(text, position)
            items.append(Item("statement", text[position:end]))
            position = end
    return items


def strip_comments(text):
    return re.sub(r"/\*.*?\*/", " ", text, flags=re.S)


FUNCTION = re.compile(r"^POLYMASS_API\s+(.*?)\b(polymass_\w+)\s*\(", re.S)
STRUCT = re.compile(r"^typedef\s+struct\s+polymass_(\w+)\s*\{(.*)\}", re.S)
STATUS_NAME = re.compile(r"\bPOLYMASS_(?:OK|ERROR_\w+)\b|(?<![\w])_[A-Z][A-Z_]*[A-Z]\b")
SINCE = re.compile(r"\bSince (\d+)\.(\d+)\b")


def functions(items):
    """(return type, name, comment or None) of every POLYMASS_API declaration."""
    found = []
    for index, item in enumerate(items):
        match = item.kind == "statement" and FUNCTION.match(item.text)
        if not match:
            continue
        comment = None
        for earlier in reversed(items[:index]):
            if earlier.kind == "statement" and FUNCTION.match(earlier.text):
                continue  # a group of declarations shares the comment before it
            if earlier.kind == "comment":
                comment = earlier.text
            break
        return_type = " ".join(match.group(1).split())
        found.append((return_type, match.group(2), comment))
    return found


def violations(text, project_version):
    """Every breach of the rules in a header's text, one sentence each."""
    items = scan(text)
    defines = {
        match.group(1)
        for item in items
        if item.kind == "directive"
        for match in [re.match(r"#\s*define\s+(\w+)", item.text)]
        if match
    }
    statuses = {name for name in defines if re.fullmatch(r"POLYMASS_(OK|ERROR_\w+)", name)}
    declared = functions(items)
    names = {name for _, name, _ in declared}
    found = []

    for item in items:
        match = item.kind == "statement" and STRUCT.match(item.text)
        if not match:
            continue
        struct, body = match.group(1), strip_comments(match.group(2))
        first_member = " ".join(body.split(";")[0].split())
        if first_member != "uint32_t struct_size":
            found.append(
                f"struct polymass_{struct} starts with `{first_member};`, "
                "not `uint32_t struct_size;`"
            )
        for needed in (f"polymass_sizeof_{struct}", f"polymass_{struct}_init"):
            if needed not in names:
                found.append(f"struct polymass_{struct} has no function {needed}")
        if f"POLYMASS_{struct.upper()}_INIT" not in defines:
            found.append(f"struct polymass_{struct} has no macro POLYMASS_{struct.upper()}_INIT")

    for return_type, name, comment in declared:
        if comment is None:
            found.append(f"{name} has no comment")
            continue
        since = SINCE.search(comment)
        if not since:
            found.append(f'{name}: its comment does not say "Since N.M"')
        elif (int(since.group(1)), int(since.group(2))) > project_version:
            found.append(f"{name}: Since {since.group(1)}.{since.group(2)} is after this version")
        if return_type != "int32_t":
            continue
        returns = re.search(r"\bReturns\b(.*)", comment, re.S)
        if not returns:
            found.append(f'{name} returns a status but its comment has no "Returns" sentence')
            continue
        named = STATUS_NAME.findall(returns.group(1))
        if not named:
            found.append(f'{name}: its "Returns" sentence names no status')
        for status in named:
            full = "POLYMASS_ERROR" + status if status.startswith("_") else status
            if full not in statuses:
                found.append(f'{name}: its "Returns" sentence names {status}, not a status')

    for option_name in sorted(set(re.findall(r"\b\w+_with_options\b", text))):
        found.append(f"{option_name}: options are given per call, never by a *_with_options twin")
    return found


def check_file(path):
    return violations(Path(path).read_text(), PROJECT_VERSION)


class RealHeader(unittest.TestCase):
    def test_header_keeps_the_contract(self):
        self.assertEqual(check_file(HEADER), [])

    def test_header_is_read_whole(self):
        """The scan finds what a reader sees, so the rules are not vacuous."""
        items = scan(HEADER.read_text())
        structs = [item for item in items if item.kind == "statement" and STRUCT.match(item.text)]
        declared = functions(items)
        self.assertGreaterEqual(len(structs), 10)
        self.assertGreaterEqual(len(declared), 50)
        self.assertTrue(any(r == "int32_t" for r, _, _ in declared))
        self.assertIn("polymass_mesh_create", {name for _, name, _ in declared})


class BrokenCopies(unittest.TestCase):
    """Copies of the real header, each broken in one place, must be rejected."""

    def setUp(self):
        self.text = HEADER.read_text()
        self.items = scan(self.text)
        self.scratch = tempfile.TemporaryDirectory()
        self.addCleanup(self.scratch.cleanup)

    def assert_rejected(self, old, new, expected, count=1):
        """Replaces `old` by `new` in a copy and requires a violation naming `expected`."""
        self.assertEqual(self.text.count(old), count, f"the break no longer applies: {old!r}")
        broken = Path(self.scratch.name) / "polymass.h"
        broken.write_text(self.text.replace(old, new))
        found = check_file(broken)
        self.assertTrue(
            any(expected in violation for violation in found),
            f"a copy without {old!r} was not rejected for {expected!r}: {found}",
        )

    def structs(self):
        for item in self.items:
            match = item.kind == "statement" and STRUCT.match(item.text)
            if match:
                yield match.group(1), item.text

    def test_struct_without_struct_size_first(self):
        for struct, text in self.structs():
            with self.subTest(struct=struct):
                first = re.search(r"uint32_t struct_size;[^\n]*\n", text).group(0)
                moved = text.replace(first, "", 1).replace("}", "    " + first + "}", 1)
                self.assert_rejected(text, moved, f"struct polymass_{struct} starts with")

    def test_struct_without_sizeof_init_or_macro(self):
        for struct, _ in self.structs():
            with self.subTest(struct=struct):
                sizeof = f"POLYMASS_API uint32_t polymass_sizeof_{struct}("
                self.assert_rejected(sizeof, sizeof.replace("sizeof", "size"), "no function")
                init = f"POLYMASS_API int32_t polymass_{struct}_init("
                self.assert_rejected(init, init.replace("_init", "_reset"), f"_{struct}_init")
                self.assert_rejected(
                    f"#define POLYMASS_{struct.upper()}_INIT",
                    f"#define POLYMASS_{struct.upper()}_GONE",
                    f"no macro POLYMASS_{struct.upper()}_INIT",
                )

    def test_new_struct_without_anything(self):
        anchor = "typedef struct polymass_options {"
        self.assert_rejected(
            anchor,
            "typedef struct polymass_widget {\n    double x;\n} polymass_widget;\n" + anchor,
            "struct polymass_widget starts with `double x;`",
        )

    def test_function_without_since(self):
        for _, name, comment in functions(self.items):
            with self.subTest(function=name):
                since = SINCE.search(comment).group(0)
                self.assert_rejected(comment, comment.replace(since, "Of old"), "Since N.M")

    def test_function_since_a_later_version(self):
        _, name, comment = functions(self.items)[0]
        major, minor = PROJECT_VERSION
        later = comment.replace(SINCE.search(comment).group(0), f"Since {major}.{minor + 1}")
        self.assert_rejected(comment, later, f"{name}: Since {major}.{minor + 1} is after")

    def test_status_function_without_returns(self):
        for return_type, name, comment in functions(self.items):
            if return_type != "int32_t":
                continue
            with self.subTest(function=name):
                without = re.sub(r"\bReturns\b.*?(?=\*/)", "", comment, flags=re.S)
                self.assert_rejected(comment, without, f"{name} returns a status but")

    def test_returns_naming_no_status_or_an_unknown_one(self):
        comment = next(c for r, n, c in functions(self.items) if n == "polymass_polygon_compute")
        returns = re.search(r"\bReturns\b.*?(?=\*/)", comment, re.S).group(0)
        self.assert_rejected(comment, comment.replace(returns, "Returns a status."), "names no")
        self.assert_rejected("_ZERO_AREA or", "_ZERO_AERA or", "names _ZERO_AERA, not a status")

    def test_with_options_name(self):
        anchor = "POLYMASS_API void polymass_mesh_destroy("
        twin = "POLYMASS_API void polymass_mesh_destroy_with_options(void);\n"
        self.assert_rejected(anchor, twin + anchor, "polymass_mesh_destroy_with_options")


class CompileTests(unittest.TestCase):
    def test_every_function_is_compiled_at_its_type(self):
        names = [name for _, name, _ in functions(scan(HEADER.read_text()))]
        for path in COMPILE_TESTS:
            text = path.read_text()
            missing = [name for name in names if not re.search(rf"\b{name}\b", text)]
            with self.subTest(file=path.name):
                self.assertEqual(missing, [], f"{path} does not name these functions")


def main():
    global HEADER, PROJECT_VERSION, COMPILE_TESTS
    if len(sys.argv) < 3:
        sys.exit(f"usage: {sys.argv[0]} <polymass.h> <project version> [compile tests...]")
    HEADER = Path(sys.argv[1])
    PROJECT_VERSION = tuple(int(part) for part in sys.argv[2].split(".")[:2])
    COMPILE_TESTS = [Path(path) for path in sys.argv[3:]]
    unittest.main(argv=sys.argv[:1], verbosity=1)


if __name__ == "__main__":
    main()
