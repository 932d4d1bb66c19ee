# ctest package.deb: CPack makes the two Debian packages and they hold what
# they should.
#
#   cmake -DBUILD_DIR=<build> -DWORK_DIR=<scratch> -DCONFIG=<config> -DVERSION=1.0.0
#         -DMAJOR=1 [-DEXPECT_SHLIBS=ON] [-DEXPECT_TOOLS=ON] -P check_deb.cmake
#
# libpolymass<MAJOR>: only /usr/lib/.../libpolymass.so.<MAJOR>{,.<minor>.<patch>},
#   a shlibs file and the ldconfig scripts.
# libpolymass-dev: the headers, the namelink, the archive, polymass.pc and the
#   CMake package; Depends on libpolymass<MAJOR> (= VERSION-release).
# polymass-tools (with EXPECT_TOOLS): /usr/bin/polymass only; Depends on
#   libpolymass<MAJOR> (= VERSION-release).

cmake_minimum_required(VERSION 3.25)

include("${CMAKE_CURRENT_LIST_DIR}/../cmake_helpers/script_checks.cmake")
polymass_require_args(check_deb.cmake BUILD_DIR WORK_DIR VERSION MAJOR)
find_program(DPKG_DEB dpkg-deb)
if(NOT DPKG_DEB)
    message(FATAL_ERROR "dpkg-deb not found")
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(cpack_args -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}")
if(CONFIG)
    list(APPEND cpack_args -C "${CONFIG}")
endif()
execute_process(COMMAND "${CMAKE_CPACK_COMMAND}" ${cpack_args}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "FAIL: cpack ${cpack_args}: ${rc}")
endif()

file(GLOB debs "${WORK_DIR}/*.deb")
list(LENGTH debs deb_count)
set(expected_deb_count 2)
if(EXPECT_TOOLS)
    set(expected_deb_count 3)
endif()
if(NOT deb_count EQUAL expected_deb_count)
    message(FATAL_ERROR "FAIL: expected ${expected_deb_count} .deb files, got: ${debs}")
endif()

function(deb_field deb field out_var)
    execute_process(COMMAND "${DPKG_DEB}" -f "${deb}" "${field}"
        OUTPUT_VARIABLE value OUTPUT_STRIP_TRAILING_WHITESPACE)
    set(${out_var} "${value}" PARENT_SCOPE)
endfunction()

foreach(deb IN LISTS debs)
    deb_field("${deb}" Package package)
    deb_field("${deb}" Depends depends)
    deb_field("${deb}" Description description)
    execute_process(COMMAND "${DPKG_DEB}" -c "${deb}" OUTPUT_VARIABLE listing)
    execute_process(COMMAND "${DPKG_DEB}" --ctrl-tarfile "${deb}" COMMAND tar -t
        OUTPUT_VARIABLE control_files)
    message(STATUS "${package}: Depends: ${depends}\n${listing}")
    # Every entry of the data archive, without the leading "./".
    string(REGEX MATCHALL "\\./usr/[^ \n]*[^/ \n]( -> [^\n]*)?\n" entries "${listing}")
    set(files)
    foreach(entry IN LISTS entries)
        string(REGEX REPLACE "^\\./(usr/[^ \n]*).*$" "\\1" file "${entry}")
        string(STRIP "${file}" file)
        list(APPEND files "${file}")
    endforeach()
    if(package STREQUAL "libpolymass${MAJOR}")
        set(expected "libpolymass\\.so\\.${MAJOR}" "libpolymass\\.so\\.${VERSION}")
        if(EXPECT_SHLIBS AND NOT control_files MATCHES "shlibs")
            fail("${package} has no shlibs control file")
        endif()
        if(EXPECT_SHLIBS AND NOT control_files MATCHES "postinst|triggers")
            fail("${package} runs no ldconfig (no postinst or triggers)")
        endif()
    elseif(package STREQUAL "libpolymass-dev")
        set(expected "polymass/polymass\\.h" "polymass/polymass_version\\.h" "libpolymass\\.so"
            "libpolymass\\.a" "pkgconfig/polymass\\.pc" "cmake/polymass/polymassConfig\\.cmake"
            "cmake/polymass/polymassConfigVersion\\.cmake" "cmake/polymass/polymassTargets\\.cmake"
            "cmake/polymass/polymassTargets-[a-z]+\\.cmake")
        if(NOT depends MATCHES "^libpolymass${MAJOR} \\(= ${VERSION}-[0-9]+\\)")
            fail("${package} should depend on libpolymass${MAJOR} (= ${VERSION}-...), not '${depends}'")
        endif()
    elseif(package STREQUAL "polymass-tools" AND EXPECT_TOOLS)
        set(expected "polymass")
        if(NOT depends MATCHES "^libpolymass${MAJOR} \\(= ${VERSION}-[0-9]+\\)")
            fail("${package} should depend on libpolymass${MAJOR} (= ${VERSION}-...), not '${depends}'")
        endif()
    else()
        fail("unexpected package ${package}")
        continue()
    endif()
    if(NOT description MATCHES "\n")
        fail("${package} has no extended description")
    endif()
    list(LENGTH expected expected_count)
    list(LENGTH files file_count)
    if(NOT file_count EQUAL expected_count)
        fail("${package} holds ${file_count} files, expected ${expected_count}: ${files}")
    endif()
    foreach(pattern IN LISTS expected)
        set(found FALSE)
        foreach(file IN LISTS files)
            if(file MATCHES "^usr/(include|lib|bin)/(.*/)?${pattern}$")
                set(found TRUE)
            endif()
        endforeach()
        if(NOT found)
            fail("${package} lacks a file matching ${pattern}")
        endif()
    endforeach()
endforeach()

polymass_exit_if_failed()
message(STATUS "OK: the ${expected_deb_count} Debian packages are as expected")
