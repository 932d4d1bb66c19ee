"""Turn polymass.h into what cffi needs: declarations it can parse and the constants.

cffi's cdef understands plain C declarations and ``#define NAME <integer>``, not
a real header: it has include guards, ``#include``s, an export macro that
depends on the compiler, ``extern "C"`` for C++ and constants written as
expressions (``(1u << 2)``, ``1e-6``, ``UINT64_MAX``). The header is written
for C compilers, so rather than requiring one at install time (a user with the
library from a distribution package may have no compiler at all), this module
is the small preprocessor the header needs: conditionals on ``defined(NAME)``
with nothing predefined (no C++, no compiler-specific branch), object-like
macros, and constants evaluated with Python's own arithmetic. Anything it does
not understand is an error naming the line, so the header cannot drift away
from the binding unnoticed.

Run as a script (by the package's CMake build), it writes the package's two
generated modules: ``_polymass_cffi.py`` (cffi's out-of-line ABI-mode module:
no compiler needed) and ``_header.py`` (the constants)::

    python cdef_from_header.py OUTPUT_DIR HEADER INCLUDE_DIR...
"""

from __future__ import annotations

import argparse
import ast
import re
from dataclasses import dataclass, field
from pathlib import Path

# Limits the header's constants may refer to (from <stdint.h>).
_STDINT_LIMITS = {"UINT64_MAX": 2**64 - 1, "UINT32_MAX": 2**32 - 1, "INT32_MAX": 2**31 - 1}

_INCLUDE = re.compile(r'#\s*include\s*[<"]([^>"]+)[>"]')
_DEFINE = re.compile(r"#\s*define\s+([A-Za-z_]\w*)(\(.*?\))?\s*(.*)")
_CONDITION_DEFINED = re.compile(
    r"!?\s*defined\s*\(\s*([A-Za-z_]\w*)\s*\)|!?\s*defined\s+([A-Za-z_]\w*)"
)


class HeaderError(RuntimeError):
    """The header uses a construct this reader does not understand."""


@dataclass
class Header:
    """What cffi needs from polymass.h and the headers it includes."""

    declarations: list[str] = field(default_factory=list)
    constants: dict[str, int | float | str] = field(default_factory=dict)
    empty_macros: set[str] = field(default_factory=set)

    def cdef(self) -> str:
        """The declarations with the empty macros (the export macro) removed and
        integer constants (array sizes) replaced by their values."""
        text = "\n".join(self.declarations)
        for name in self.empty_macros:
            text = re.sub(rf"\b{name}\b", "", text)
        for name, value in self.constants.items():
            if isinstance(value, int) and not isinstance(value, bool):
                text = re.sub(rf"\b{name}\b", str(value), text)
        return text


def read_header(path: Path, include_dirs: list[Path]) -> Header:
    """Reads ``path`` and the project headers it includes (found in ``include_dirs``)."""
    header = Header()
    _read_file(path, include_dirs, header, seen=set())
    return header


def _logical_lines(path: Path):
    """Yields (line number, line) with comments removed and continuations joined."""
    text = path.read_text(encoding="utf-8")
    # Comments become spaces (keeping line numbers: newlines inside them stay).
    text = re.sub(r"/\*.*?\*/", lambda m: re.sub(r"[^\n]", " ", m.group()), text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    pending, start = "", 0
    for number, line in enumerate(text.split("\n"), start=1):
        if not pending:
            start = number
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        yield start, pending + line
        pending = ""


def _read_file(path: Path, include_dirs: list[Path], header: Header, seen: set[Path]) -> None:
    if path in seen:
        return
    seen.add(path)
    # One entry per open conditional: (this branch is active, some branch was taken).
    stack: list[tuple[bool, bool]] = []

    def active() -> bool:
        return all(branch for branch, _ in stack)

    for number, line in _logical_lines(path):
        where = f"{path.name}:{number}"
        stripped = line.strip()
        if not stripped.startswith("#"):
            if stripped and active():
                header.declarations.append(line)
            continue
        directive = stripped[1:].split(None, 1)
        keyword = directive[0] if directive else ""
        argument = directive[1].strip() if len(directive) > 1 else ""
        if keyword in ("ifdef", "ifndef"):
            value = (argument in header.constants or argument in header.empty_macros) == (
                keyword == "ifdef"
            )
            stack.append((value, value))
        elif keyword == "if":
            value = _condition(argument, header, where)
            stack.append((value, value))
        elif keyword == "elif":
            if not stack:
                raise HeaderError(f"{where}: #elif without #if")
            _, taken = stack.pop()
            value = not taken and _condition(argument, header, where)
            stack.append((value, taken or value))
        elif keyword == "else":
            if not stack:
                raise HeaderError(f"{where}: #else without #if")
            _, taken = stack.pop()
            stack.append((not taken, True))
        elif keyword == "endif":
            if not stack:
                raise HeaderError(f"{where}: #endif without #if")
            stack.pop()
        elif not active():
            continue
        elif keyword == "include":
            _include(stripped, include_dirs, header, seen, where)
        elif keyword == "define":
            _define(stripped, header, where)
        else:
            raise HeaderError(f"{where}: unsupported directive #{keyword}")
    if stack:
        raise HeaderError(f"{path.name}: unterminated #if")


def _condition(text: str, header: Header, where: str) -> bool:
    """Evaluates ``defined(A)``, ``!defined(A)`` joined by ``&&`` or ``||`` (not mixed)."""
    for joiner, combine in (("&&", all), ("||", any)):
        if joiner in text:
            if ("||" if joiner == "&&" else "&&") in text:
                raise HeaderError(f"{where}: mixed && and || in #if {text}")
            return combine(_condition(part, header, where) for part in text.split(joiner))
    match = _CONDITION_DEFINED.fullmatch(text.strip())
    if not match:
        raise HeaderError(f"{where}: unsupported #if condition {text!r}")
    name = match.group(1) or match.group(2)
    is_defined = name in header.constants or name in header.empty_macros
    return not is_defined if text.strip().startswith("!") else is_defined


def _include(line: str, include_dirs: list[Path], header: Header, seen: set, where: str) -> None:
    match = _INCLUDE.match(line)
    if not match:
        raise HeaderError(f"{where}: unsupported #include {line!r}")
    name = match.group(1)
    if name in ("stddef.h", "stdint.h"):
        return  # cffi knows size_t and the fixed-width integer types already
    for directory in include_dirs:
        candidate = directory / name
        if candidate.is_file():
            _read_file(candidate, include_dirs, header, seen)
            return
    searched = ", ".join(str(d) for d in include_dirs)
    raise HeaderError(f"{where}: {name} not found in {searched}")


def _define(line: str, header: Header, where: str) -> None:
    match = _DEFINE.match(line)
    if not match or match.group(2):
        raise HeaderError(f"{where}: unsupported #define {line!r}")
    name, value = match.group(1), match.group(3).strip()
    if not value:
        header.empty_macros.add(name)
        return
    if not name.startswith("POLYMASS_"):
        raise HeaderError(f"{where}: unexpected macro {name}")
    if value.startswith("{"):
        return  # a struct initialiser for C callers (POLYMASS_*_INIT): no constant
    header.constants[name] = _evaluate(value, header.constants, where)


def _evaluate(text: str, known: dict, where: str) -> int | float | str:
    """Evaluates a C constant expression of literals, names, unary -, + - * << |."""
    # C integer suffixes (1u, 2ull) mean nothing to Python's unbounded integers.
    python = re.sub(r"\b(0[xX][0-9a-fA-F]+|\d+)[uUlL]+\b", r"\1", text)
    try:
        tree = ast.parse(python, mode="eval")
    except SyntaxError as error:
        raise HeaderError(f"{where}: cannot read the value {text!r}") from error

    def value(node):
        if isinstance(node, ast.Expression):
            return value(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float, str)):
            return node.value
        if isinstance(node, ast.Name):
            if node.id in known:
                return known[node.id]
            if node.id in _STDINT_LIMITS:
                return _STDINT_LIMITS[node.id]
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            return -value(node.operand)
        if isinstance(node, ast.BinOp):
            operations = {
                ast.Add: lambda a, b: a + b,
                ast.Sub: lambda a, b: a - b,
                ast.Mult: lambda a, b: a * b,
                ast.LShift: lambda a, b: a << b,
                ast.BitOr: lambda a, b: a | b,
            }
            if type(node.op) in operations:
                return operations[type(node.op)](value(node.left), value(node.right))
        raise HeaderError(f"{where}: unsupported constant expression {text!r}")

    return value(tree)


def write_modules(header: Header, output_dir: Path) -> None:
    """Writes ``_polymass_cffi.py`` and ``_header.py`` of the package into ``output_dir``."""
    import cffi

    output_dir.mkdir(parents=True, exist_ok=True)
    builder = cffi.FFI()
    builder.cdef(header.cdef())
    builder.set_source("polymass._polymass_cffi", None)
    builder.emit_python_code(str(output_dir / "_polymass_cffi.py"))
    lines = [
        '"""Constants of polymass.h, generated at build time by cdef_from_header.py."""',
        "",
        *(f"{name} = {value!r}" for name, value in sorted(header.constants.items())),
    ]
    (output_dir / "_header.py").write_text("\n".join(lines) + "\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("output_dir", type=Path, help="where the two modules are written")
    parser.add_argument("header", type=Path, help="polymass/polymass.h")
    parser.add_argument("include_dirs", type=Path, nargs="+", help="where its includes are")
    arguments = parser.parse_args()
    write_modules(read_header(arguments.header, arguments.include_dirs), arguments.output_dir)


if __name__ == "__main__":
    main()
