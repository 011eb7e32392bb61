# install.layout: `cmake --install` of the build tree into a temporary DESTDIR with the
# package's prefix (/usr), then the installed layout, the installed executables' --version
# (which must find the installed share/frezka, not the source tree), `frezka-cli check` of an
# installed sample with a shipped profile by name, and that running them wrote nothing under
# the prefix.
#   cmake -DBUILD=<build tree> -DWORK=<scratch folder> -P install_check.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
set(ENV{DESTDIR} "${WORK}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix /usr
    RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(root "${WORK}/usr")
set(expected
    bin/frezka bin/frezka-cli bin/gve-emu bin/k51-emu
    share/frezka/machines/gve64.json share/frezka/machines/gve84.json
    share/frezka/machines/gve114.json share/frezka/programs/frezka-demo.nc
    share/applications/org.frezka.Frezka.desktop share/metainfo/org.frezka.Frezka.metainfo.xml
    share/mime/packages/frezka-gcode.xml share/icons/hicolor/scalable/apps/frezka.svg
    share/icons/hicolor/48x48/apps/frezka.png share/icons/hicolor/256x256/apps/frezka.png
    share/man/man1/frezka.1.gz share/man/man1/frezka-cli.1.gz share/man/man1/gve-emu.1.gz
    share/man/man1/k51-emu.1.gz share/doc/frezka/copyright share/doc/frezka/README.Debian
    share/doc/frezka/changelog.gz)
set(missing "")
foreach(f ${expected})
    if(NOT EXISTS "${root}/${f}")
        list(APPEND missing ${f})
    endif()
endforeach()
if(missing)
    message(FATAL_ERROR "not installed: ${missing}")
endif()
file(GLOB_RECURSE before LIST_DIRECTORIES true "${WORK}/*")

set(ENV{LC_ALL} C.UTF-8)
set(ENV{LANGUAGE} "")
set(ENV{QT_QPA_PLATFORM} offscreen)
set(ENV{XDG_CONFIG_HOME} "${WORK}-home/config")
set(ENV{XDG_DATA_HOME} "${WORK}-home/data")
foreach(exe frezka frezka-cli gve-emu k51-emu)
    execute_process(COMMAND "${root}/bin/${exe}" --version
        OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0 OR NOT out MATCHES "^${exe} [0-9]+\\.[0-9]+\\.[0-9]+")
        message(FATAL_ERROR "${exe} --version: exit ${rc}, '${out}' '${err}'")
    endif()
    message(STATUS "${exe} --version: ${out}")
endforeach()
execute_process(COMMAND "${root}/bin/frezka-cli" --version OUTPUT_VARIABLE out)
if(NOT out MATCHES "data: ${root}/share/frezka\n")
    message(FATAL_ERROR "the installed frezka-cli does not use the installed data: '${out}'")
endif()
execute_process(COMMAND "${root}/bin/frezka-cli" check --machine gve84
        "${root}/share/frezka/programs/frezka-demo.nc"
    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "installed frezka-cli check: exit ${rc}\n${out}\n${err}")
endif()
message(STATUS "frezka-cli check --machine gve84 frezka-demo.nc: ${out}")

file(GLOB_RECURSE after LIST_DIRECTORIES true "${WORK}/*")
if(NOT before STREQUAL after)
    list(REMOVE_ITEM after ${before})
    message(FATAL_ERROR "written under the install prefix at run time: ${after}")
endif()
file(REMOVE_RECURSE "${WORK}" "${WORK}-home")
