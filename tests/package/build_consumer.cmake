# ctest package.find_package / package.pkg_config: builds and runs the consumer
# in consumer/ against the prefix that package.install filled.
#
# MODE=find_package: configures consumer/CMakeLists.txt with
#   CMAKE_PREFIX_PATH=PREFIX; it links polymass::polymass (shared) and
#   polymass::polymass_static.
# MODE=pkg_config: compiles consumer/main.c by hand with the flags of
#   `pkg-config --cflags --libs polymass` (shared) and of
#   `pkg-config --static --cflags --libs polymass` with -lpolymass pinned to the
#   archive (static), PKG_CONFIG_LIBDIR=PREFIX/PKGCONFIGDIR only.
# MODE=add_subdirectory: configures subproject/CMakeLists.txt, which builds
#   the library from POLYMASS_SOURCE_DIR with add_subdirectory() (so without
#   the tool and its libraries) and links the same consumer to it.
# Each program is run and must print "volume 1".
#
# C_FLAGS / LINK_FLAGS (space-separated) are the build's sanitizer flags: an
# instrumented library needs an instrumented (or at least sanitizer-linked)
# program.

cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/../cmake_helpers/script_checks.cmake")
polymass_require_args(build_consumer.cmake MODE PREFIX WORK_DIR SOURCE_DIR C_COMPILER)
separate_arguments(c_flags UNIX_COMMAND "${C_FLAGS}")
separate_arguments(link_flags UNIX_COMMAND "${LINK_FLAGS}")

function(run) # command...
    list(JOIN ARGN " " text)
    message(STATUS "$ ${text}")
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(out)
        message("${out}")
    endif()
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "FAIL (${rc}): ${text}")
    endif()
    set(run_output "${out}" PARENT_SCOPE)
endfunction()

function(run_consumer program) # [env assignments...]
    set(command "${program}")
    if(ARGN)
        set(command "${CMAKE_COMMAND}" -E env ${ARGN} "${program}")
    endif()
    run(${command})
    if(NOT run_output MATCHES "volume 1\n")
        message(FATAL_ERROR "FAIL: ${program} did not print 'volume 1'")
    endif()
endfunction()

function(expect_needed program want) # want: TRUE if it must need libpolymass.so.*
    execute_process(COMMAND readelf -d "${program}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        return() # no readelf: nothing to check
    endif()
    if(dynamic MATCHES "\\(NEEDED\\)[^\n]*\\[libpolymass\\.so")
        set(needs TRUE)
    else()
        set(needs FALSE)
    endif()
    if(want AND NOT needs)
        message(FATAL_ERROR "FAIL: ${program} is not linked to libpolymass.so")
    elseif(NOT want AND needs)
        message(FATAL_ERROR "FAIL: ${program} should be static but needs libpolymass.so")
    endif()
endfunction()

# The CMake consumers: configure (the command given), build, and run both
# programs, the shared one linked to libpolymass.so and the static one not.
function(configure_build_and_run) # configure command...
    set(configure ${ARGN})
    if(GENERATOR)
        list(APPEND configure -G "${GENERATOR}")
    endif()
    run(${configure})
    run("${CMAKE_COMMAND}" --build "${WORK_DIR}")
    expect_needed("${WORK_DIR}/consumer_shared" TRUE)
    expect_needed("${WORK_DIR}/consumer_static" FALSE)
    run_consumer("${WORK_DIR}/consumer_shared")
    run_consumer("${WORK_DIR}/consumer_static")
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

if(MODE STREQUAL "find_package")
    set(configure "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}"
        "-DCMAKE_PREFIX_PATH=${PREFIX}"
        "-DPOLYMASS_EXPECTED_PREFIX=${PREFIX}"
        "-DCMAKE_C_COMPILER=${C_COMPILER}"
        "-DCMAKE_C_FLAGS=${C_FLAGS}"
        "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}"
        -DCMAKE_BUILD_TYPE=Release
        # Only the scratch prefix: never a polymass installed on the machine.
        -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
        -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
    configure_build_and_run(${configure})

elseif(MODE STREQUAL "add_subdirectory")
    # PREFIX is unused: the library is built from the checkout, in WORK_DIR.
    polymass_require_args(build_consumer.cmake CXX_COMPILER POLYMASS_SOURCE_DIR)
    set(configure "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}"
        "-DPOLYMASS_SOURCE_DIR=${POLYMASS_SOURCE_DIR}"
        "-DCMAKE_C_COMPILER=${C_COMPILER}"
        "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
        "-DCMAKE_C_FLAGS=${C_FLAGS}"
        "-DCMAKE_CXX_FLAGS=${C_FLAGS}"
        "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}"
        "-DCMAKE_SHARED_LINKER_FLAGS=${LINK_FLAGS}"
        # No build type: neither optimisation nor debug information, the fastest
        # compile (a fifth less CPU than Debug's -g); what this checks is the
        # project's CMake as a subproject, not the code.
        "-DCMAKE_BUILD_TYPE=")
    configure_build_and_run(${configure})

elseif(MODE STREQUAL "pkg_config")
    polymass_require_args(build_consumer.cmake PKG_CONFIG PKGCONFIGDIR LIBDIR)
    # PKG_CONFIG_LIBDIR replaces the default search path: only our prefix.
    set(ENV{PKG_CONFIG_LIBDIR} "${PREFIX}/${PKGCONFIGDIR}")
    set(ENV{PKG_CONFIG_PATH} "")
    run("${PKG_CONFIG}" --modversion polymass)
    message(STATUS "pkg-config says polymass ${run_output}")
    run("${PKG_CONFIG}" --cflags --libs polymass)
    separate_arguments(shared_flags UNIX_COMMAND "${run_output}")
    run("${PKG_CONFIG}" --static --cflags --libs polymass)
    separate_arguments(static_flags UNIX_COMMAND "${run_output}")
    if(NOT "-lpolymass" IN_LIST static_flags OR NOT "-lstdc++" IN_LIST static_flags)
        message(FATAL_ERROR "FAIL: pkg-config --static --libs lacks -lpolymass or -lstdc++")
    endif()
    # A plain -lpolymass picks libpolymass.so when both are there: pin the archive.
    list(TRANSFORM static_flags REPLACE "^-lpolymass$" "-l:libpolymass.a")

    run("${C_COMPILER}" -std=c99 ${c_flags} "${SOURCE_DIR}/main.c" -o "${WORK_DIR}/consumer_shared"
        ${shared_flags} ${link_flags})
    run("${C_COMPILER}" -std=c99 ${c_flags} "${SOURCE_DIR}/main.c" -o "${WORK_DIR}/consumer_static"
        ${static_flags} ${link_flags})
    expect_needed("${WORK_DIR}/consumer_shared" TRUE)
    expect_needed("${WORK_DIR}/consumer_static" FALSE)
    run_consumer("${WORK_DIR}/consumer_shared" "LD_LIBRARY_PATH=${PREFIX}/${LIBDIR}")
    run_consumer("${WORK_DIR}/consumer_static")
else()
    message(FATAL_ERROR "build_consumer.cmake: unknown MODE=${MODE}")
endif()
message(STATUS "OK: the ${MODE} consumer builds and runs against ${PREFIX}")
