"""The header reader (cdef_from_header.py) understands the header and refuses the rest."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from cdef_from_header import HeaderError, read_header


def _read(tmp_path: Path, text: str):
    header = tmp_path / "polymass" / "polymass.h"
    header.parent.mkdir(exist_ok=True)
    header.write_text(text)
    return read_header(header, [tmp_path])


def test_constants_are_evaluated_and_the_export_branch_is_the_plain_one(tmp_path):
    header = _read(
        tmp_path,
        """
        #ifndef GUARD_H
        #define GUARD_H
        #include <stdint.h>
        #define POLYMASS_FLAG (1u << 3) /* a bit */
        #define POLYMASS_BOTH (POLYMASS_FLAG | 1u)
        #define POLYMASS_NEGATIVE (-1)
        #define POLYMASS_NONE UINT64_MAX
        #define POLYMASS_TOLERANCE 1e-6
        #define POLYMASS_NAME "1.2.3"
        #define POLYMASS_SUM \\
            (POLYMASS_FLAG * 100 + 2)
        #if defined(_WIN32)
        #define POLYMASS_API __declspec(dllexport)
        #elif defined(__GNUC__)
        #define POLYMASS_API __attribute__((visibility("default")))
        #else
        #define POLYMASS_API
        #endif
        #ifdef __cplusplus
        extern "C" {
        #endif
        POLYMASS_API uint32_t polymass_f(void); // declared
        #ifdef __cplusplus
        }
        #endif
        #endif
        """,
    )
    assert header.constants == {
        "POLYMASS_FLAG": 8,
        "POLYMASS_BOTH": 9,
        "POLYMASS_NEGATIVE": -1,
        "POLYMASS_NONE": 2**64 - 1,
        "POLYMASS_TOLERANCE": 1e-6,
        "POLYMASS_NAME": "1.2.3",
        "POLYMASS_SUM": 802,
    }
    assert header.cdef().split() == ["uint32_t", "polymass_f(void);"]


def test_integer_constants_in_declarations_become_their_values(tmp_path):
    # cffi cannot look up a macro in an array size: the reader writes the number.
    header = _read(
        tmp_path,
        """
        #define POLYMASS_PLACES 8
        #define POLYMASS_PLACES_TOO 9
        typedef struct s { uint64_t first[POLYMASS_PLACES][2]; int x[POLYMASS_PLACES_TOO]; } s;
        """,
    )
    assert "first[8][2]" in header.cdef() and "x[9]" in header.cdef()


def test_struct_initialisers_are_for_c_callers_not_constants(tmp_path):
    header = _read(
        tmp_path,
        """
        #define POLYMASS_S_INIT {.struct_size = sizeof(s), \\
                                 .density = 1.0}
        typedef struct s { uint32_t struct_size; double density; } s;
        """,
    )
    assert "POLYMASS_S_INIT" not in header.constants
    assert "POLYMASS_S_INIT" not in header.cdef()


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("#pragma once\n", "unsupported directive"),
        ("#define POLYMASS_X sizeof(int)\n", "unsupported constant"),
        ("#define POLYMASS_F(x) x\n", "unsupported #define"),
        ("#if VERSION > 2\n#endif\n", "unsupported #if"),
        ("#ifdef X\n", "unterminated"),
        ('#include "polymass/absent.h"\n', "not found"),
    ],
)
def test_what_it_does_not_understand_is_an_error_naming_the_line(tmp_path, text, message):
    with pytest.raises(HeaderError, match=message):
        _read(tmp_path, text)
