# Shared by the check scripts that ctest runs with `cmake -P` (tests/abi,
# tests/package): their -D arguments, and checks that count their failures so
# that one run reports every failure before the script fails.
#
#   include("${CMAKE_CURRENT_LIST_DIR}/../cmake_helpers/script_checks.cmake")
#   polymass_require_args(<script name> <var>...)  each -D<var>=... given, non-empty,
#                                                  not a NOTFOUND tool
#   polymass_default_arg(<var> <value>)            an optional -D<var> not given (or
#                                                  a NOTFOUND tool) becomes <value>
#   fail(<text>)                                   report one failed check, go on
#   polymass_exit_if_failed([<what>])              fatal error if any check failed

set(failures 0)

function(polymass_require_args script)
    foreach(var IN LISTS ARGN)
        if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "" OR "${${var}}" MATCHES "-NOTFOUND$")
            message(FATAL_ERROR "${script}: -D${var}=... is required")
        endif()
    endforeach()
endfunction()

macro(polymass_default_arg var value)
    if(NOT ${var})
        set(${var} "${value}")
    endif()
endmacro()

# A macro, not a function: the count is the including script's variable.
macro(fail text)
    message(SEND_ERROR "FAIL: ${text}")
    math(EXPR failures "${failures} + 1")
endmacro()

macro(polymass_exit_if_failed)
    if(failures GREATER 0)
        if(${ARGC} GREATER 0)
            message(FATAL_ERROR "${failures} check(s) failed for ${ARGV0}")
        endif()
        message(FATAL_ERROR "${failures} check(s) failed")
    endif()
endmacro()
