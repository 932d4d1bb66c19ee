"""The README's quick start runs as written and computes what it says."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"


def test_the_quick_start_runs():
    text = README.read_text(encoding="utf-8")
    quick_start = re.search(r"```python\n(.*?)```", text, flags=re.S)
    assert quick_start, "the README has a Python snippet"
    namespace: dict = {}
    exec(compile(quick_start.group(1), str(README), "exec"), namespace)
    # The unit corner tetrahedron (volume 1/6) of aluminium.
    assert namespace["p"].mass == pytest.approx(2700.0 / 6, rel=1e-15)
