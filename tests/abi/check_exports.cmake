# ctest: what libpolymass.so exports must be exactly the C API of the header.
#
#   cmake -DLIBRARY=<libpolymass.so> -DHEADER=<polymass.h> -DEXPECTED_SONAME=libpolymass.so.2
#         -DVERSION_NODE=POLYMASS_2 [-DNM=nm] [-DREADELF=readelf] -P check_exports.cmake
#
# 1. The expected list is read from the header (every `POLYMASS_API ... name(`),
#    so it cannot drift from the contract; it must not be empty.
# 2. Every defined dynamic symbol (`nm -D --defined-only`) must start with
#    polymass_: no Eigen, no libstdc++, no helper leaks (none is ignored).
# 3. The exported functions (type T) must be exactly the header's list, each
#    at the symbol version VERSION_NODE (polymass.map), the only node.
# 4. The SONAME must be EXPECTED_SONAME.

cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/../cmake_helpers/script_checks.cmake")
polymass_require_args(check_exports.cmake LIBRARY HEADER EXPECTED_SONAME VERSION_NODE)
polymass_default_arg(NM nm)
polymass_default_arg(READELF readelf)

# --- 1. the header's functions ----------------------------------------------
file(READ "${HEADER}" header_text)
# Join the header into one line per declaration is unnecessary: the name and
# its '(' are always on the POLYMASS_API line.
string(REGEX MATCHALL "POLYMASS_API[^;(]*[ *](polymass_[A-Za-z0-9_]+)[ \t]*\\("
       declarations "${header_text}")
set(expected)
foreach(declaration IN LISTS declarations)
    string(REGEX REPLACE ".*[ *](polymass_[A-Za-z0-9_]+)[ \t]*\\($" "\\1" name "${declaration}")
    list(APPEND expected ${name})
endforeach()
list(REMOVE_DUPLICATES expected)
list(SORT expected)
list(LENGTH expected expected_count)
if(expected_count EQUAL 0)
    message(FATAL_ERROR "FAIL: no `POLYMASS_API ... polymass_xxx(` declaration found in ${HEADER}")
endif()
# The regex must also see every POLYMASS_API use that declares something.
string(REGEX MATCHALL "\nPOLYMASS_API " api_lines "${header_text}")
list(LENGTH api_lines api_line_count)
if(NOT api_line_count EQUAL expected_count)
    fail("${api_line_count} lines start with POLYMASS_API but ${expected_count} declarations "
         "were parsed from ${HEADER}: fix the regex in check_exports.cmake")
endif()

# --- 2. + 3. the library's dynamic symbols ----------------------------------
execute_process(COMMAND "${NM}" -D --defined-only "${LIBRARY}"
    OUTPUT_VARIABLE nm_output ERROR_VARIABLE nm_error RESULT_VARIABLE nm_result)
if(NOT nm_result EQUAL 0)
    message(FATAL_ERROR "FAIL: ${NM} -D --defined-only ${LIBRARY}: ${nm_result}\n${nm_error}")
endif()
string(REPLACE "\n" ";" nm_lines "${nm_output}")
set(exported_functions)
set(leaks)
set(defined_count 0)
foreach(line IN LISTS nm_lines)
    if(line MATCHES "^[0-9a-fA-F]* *([A-Za-z]) ([^ ]+)$")
        set(type "${CMAKE_MATCH_1}")
        set(symbol "${CMAKE_MATCH_2}")
        # Symbol versions: nm prints name@@POLYMASS_2 (and the version node
        # itself as an absolute symbol POLYMASS_2).
        string(REGEX REPLACE "@.*$" "" name "${symbol}")
        set(version "")
        if(symbol MATCHES "@@?(.*)$")
            set(version "${CMAKE_MATCH_1}")
        endif()
        math(EXPR defined_count "${defined_count} + 1")
        if(type STREQUAL "A" AND name MATCHES "^POLYMASS_[0-9_.]+$")
            if(NOT name STREQUAL VERSION_NODE)
                fail("version node ${name}, expected ${VERSION_NODE} (polymass.map)")
            endif()
            continue() # the version node of polymass.map
        endif()
        if(name MATCHES "^polymass_" AND NOT symbol STREQUAL "${name}@@${VERSION_NODE}")
            fail("${symbol} is not versioned ${name}@@${VERSION_NODE} (polymass.map)")
        endif()
        if(NOT name MATCHES "^polymass_")
            list(APPEND leaks "${type} ${symbol}")
        elseif(type MATCHES "^[Tt]$")
            list(APPEND exported_functions "${name}")
        else()
            list(APPEND leaks "${type} ${symbol} (exported, but not a function)")
        endif()
    elseif(NOT line STREQUAL "")
        fail("unparsed nm line: '${line}'")
    endif()
endforeach()
list(SORT exported_functions)

if(defined_count EQUAL 0)
    fail("${LIBRARY} defines no dynamic symbol")
endif()
if(leaks)
    list(LENGTH leaks leak_count)
    list(JOIN leaks "\n  " leak_text)
    fail("${leak_count} exported symbol(s) outside the C API:\n  ${leak_text}")
endif()

set(missing ${expected})
list(REMOVE_ITEM missing ${exported_functions})
set(unexpected ${exported_functions})
list(REMOVE_ITEM unexpected ${expected})
if(missing)
    list(JOIN missing "\n  " text)
    fail("declared in the header but not exported:\n  ${text}")
endif()
if(unexpected)
    list(JOIN unexpected "\n  " text)
    fail("exported but not declared in the header:\n  ${text}")
endif()

# --- 4. SONAME ----------------------------------------------------------------
execute_process(COMMAND "${READELF}" -d "${LIBRARY}"
    OUTPUT_VARIABLE readelf_output RESULT_VARIABLE readelf_result)
if(NOT readelf_result EQUAL 0)
    fail("${READELF} -d ${LIBRARY} failed: ${readelf_result}")
elseif(readelf_output MATCHES "\\(SONAME\\)[^\n]*\\[([^]\n]*)\\]")
    if(NOT CMAKE_MATCH_1 STREQUAL EXPECTED_SONAME)
        fail("SONAME is ${CMAKE_MATCH_1}, expected ${EXPECTED_SONAME}")
    endif()
else()
    fail("${LIBRARY} has no SONAME")
endif()
if(readelf_output MATCHES "\\((RPATH|RUNPATH)\\)")
    # Only a note: the build tree's copy may carry a build RPATH; the installed
    # copy is checked by the package.install test.
    message(STATUS "note: the build tree's library has a ${CMAKE_MATCH_1}")
endif()

polymass_exit_if_failed(${LIBRARY})
list(JOIN expected ", " expected_text)
message(STATUS "OK: ${LIBRARY} (SONAME ${EXPECTED_SONAME}) exports exactly the "
               "${expected_count} functions of the header: ${expected_text}")
