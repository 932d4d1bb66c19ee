# ctest package.install (fixture of the package.* consumer tests): installs the
# build into a scratch prefix, component by component, and checks the layout.
#
#   cmake -DBUILD_DIR=... -DPREFIX=... -DCONFIG=... -DLIBDIR=lib -DINCLUDEDIR=include
#         -DCMAKEDIR=lib/cmake/polymass -DPKGCONFIGDIR=lib/pkgconfig
#         -DSONAME=libpolymass.so.2 [-DREADELF=readelf] -P install_and_check.cmake
#
# Checks: the runtime component is exactly the versioned shared library and
# its SONAME link; the development component is the headers, the namelink,
# the archive, polymass.pc and the CMake package; no installed binary has an
# RPATH/RUNPATH; no installed CMake or pkg-config file mentions Eigen3.

cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/../cmake_helpers/script_checks.cmake")
polymass_require_args(install_and_check.cmake
    BUILD_DIR PREFIX LIBDIR INCLUDEDIR CMAKEDIR PKGCONFIGDIR SONAME)
polymass_default_arg(READELF readelf)

function(install_into prefix) # [component]
    set(args --install "${BUILD_DIR}" --prefix "${prefix}")
    if(CONFIG)
        list(APPEND args --config "${CONFIG}")
    endif()
    if(ARGC GREATER 1)
        list(APPEND args --component "${ARGV1}")
    endif()
    file(REMOVE_RECURSE "${prefix}")
    execute_process(COMMAND "${CMAKE_COMMAND}" ${args}
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "FAIL: cmake ${args}: ${result}\n${output}")
    endif()
endfunction()

function(list_tree prefix out_var)
    file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE "${prefix}" "${prefix}/*")
    list(SORT files)
    set(${out_var} "${files}" PARENT_SCOPE)
endfunction()

function(expect_tree what prefix) # expected relative paths...
    list_tree("${prefix}" actual)
    set(expected ${ARGN})
    list(SORT expected)
    if(NOT actual STREQUAL expected)
        list(JOIN actual "\n  " actual_text)
        list(JOIN expected "\n  " expected_text)
        message(SEND_ERROR "FAIL: the ${what} component installs\n  ${actual_text}\n"
                           "expected\n  ${expected_text}")
        set(failed TRUE PARENT_SCOPE)
    endif()
endfunction()

string(REGEX REPLACE "^(libpolymass\\.so)\\..*$" "\\1" namelink "${SONAME}")
set(runtime_files
    ${LIBDIR}/${SONAME}
    # the real file: libpolymass.so.MAJOR.MINOR.PATCH
)
set(dev_files
    ${INCLUDEDIR}/polymass/polymass.h
    ${INCLUDEDIR}/polymass/polymass_version.h
    ${LIBDIR}/${namelink}
    ${LIBDIR}/libpolymass.a
    ${PKGCONFIGDIR}/polymass.pc
    ${CMAKEDIR}/polymassConfig.cmake
    ${CMAKEDIR}/polymassConfigVersion.cmake
    ${CMAKEDIR}/polymassTargets.cmake)

# --- the components one by one -------------------------------------------------
set(failed FALSE)
install_into("${PREFIX}-runtime" runtime)
file(GLOB real_so RELATIVE "${PREFIX}-runtime" "${PREFIX}-runtime/${LIBDIR}/${SONAME}.*")
list(LENGTH real_so real_so_count)
if(NOT real_so_count EQUAL 1)
    fail("the runtime component has no ${SONAME}.MINOR.PATCH file")
endif()
expect_tree(runtime "${PREFIX}-runtime" ${runtime_files} ${real_so})
if(NOT IS_SYMLINK "${PREFIX}-runtime/${LIBDIR}/${SONAME}")
    fail("${LIBDIR}/${SONAME} is not a symbolic link")
endif()

install_into("${PREFIX}-development" development)
file(GLOB dev_configs RELATIVE "${PREFIX}-development"
    "${PREFIX}-development/${CMAKEDIR}/polymassTargets-*.cmake")
expect_tree(development "${PREFIX}-development" ${dev_files} ${dev_configs})
if(NOT dev_configs)
    fail("no per-configuration polymassTargets-<config>.cmake installed")
endif()
if(NOT IS_SYMLINK "${PREFIX}-development/${LIBDIR}/${namelink}")
    fail("${LIBDIR}/${namelink} (the namelink) is not a symbolic link")
endif()
if(failed)
    math(EXPR failures "${failures} + 1")
endif()
file(REMOVE_RECURSE "${PREFIX}-runtime" "${PREFIX}-development")

# --- everything, as the consumer tests use it ---------------------------------
install_into("${PREFIX}")
list_tree("${PREFIX}" all_files)
list(JOIN all_files "\n  " all_text)
message(STATUS "installed into ${PREFIX}:\n  ${all_text}")

foreach(file IN LISTS all_files)
    set(path "${PREFIX}/${file}")
    if(file MATCHES "\\.so(\\.[0-9]+)*$" AND NOT IS_SYMLINK "${path}")
        execute_process(COMMAND "${READELF}" -d "${path}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
        if(NOT rc EQUAL 0)
            fail("${READELF} -d ${file} failed")
        elseif(dynamic MATCHES "\\((RPATH|RUNPATH)\\)[^\n]*")
            fail("installed ${file} has an ${CMAKE_MATCH_0}")
        endif()
        if(NOT dynamic MATCHES "\\(SONAME\\)[^\n]*\\[${SONAME}\\]")
            fail("installed ${file} does not have SONAME ${SONAME}")
        endif()
    endif()
    if(file MATCHES "\\.(cmake|pc|h)$")
        file(READ "${path}" text)
        if(file MATCHES "\\.(cmake|pc)$" AND text MATCHES "[Ee]igen3")
            fail("installed ${file} mentions Eigen: a private dependency leaks to consumers")
        endif()
        string(FIND "${text}" "${BUILD_DIR}" build_dir_at)
        if(NOT build_dir_at EQUAL -1)
            fail("installed ${file} refers to the build directory ${BUILD_DIR}")
        endif()
    endif()
endforeach()

file(STRINGS "${PREFIX}/${INCLUDEDIR}/polymass/polymass.h" includes REGEX "^#[ \t]*include")
foreach(line IN LISTS includes)
    if(NOT line MATCHES "<stddef\\.h>|<stdint\\.h>|[<\"](polymass/)?polymass_version\\.h[>\"]")
        fail("the installed header includes more than the C library: ${line}")
    endif()
endforeach()

polymass_exit_if_failed()
message(STATUS "OK: components runtime and development install as expected into ${PREFIX}")
