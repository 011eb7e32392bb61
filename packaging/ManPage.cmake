# Writes a manual page from an executable's --help (run at build time by packaging/CMakeLists.txt,
# so the page never disagrees with the program):
#
#   cmake -DEXE=<executable> -DNAME=<name> -DSUMMARY=<one line> -DVERSION=<version>
#         [-DSEEALSO=<"a(1), b(1)">] [-DSERIAL=1] -DOUT=<file.1> -P ManPage.cmake
#
# The help text goes in verbatim (no fill), English (LC_ALL=C), escaped for troff; SERIAL adds
# how to get the permission to open a serial port.
cmake_minimum_required(VERSION 3.25)
foreach(var EXE NAME SUMMARY VERSION OUT)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "ManPage.cmake: pass -D${var}=...")
    endif()
endforeach()
set(ENV{LC_ALL} C)
set(ENV{LANGUAGE} "")
set(ENV{QT_QPA_PLATFORM} offscreen)
execute_process(COMMAND "${EXE}" --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR help STREQUAL "")
    message(FATAL_ERROR "ManPage.cmake: '${EXE} --help' failed (${rc})")
endif()
# Qt's parser prints the path it was started by: the page shows the name.
string(REPLACE "${EXE}" "${NAME}" help "${help}")
# troff: a backslash is \e, a line starting with . or ' needs \& before it, '-' is \-.
string(REPLACE "\\" "\\e" help "${help}")
string(REPLACE "-" "\\-" help "${help}")
string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
string(TIMESTAMP date "%Y-%m-%d" UTC) # SOURCE_DATE_EPOCH, when set, gives a reproducible date
string(TOUPPER "${NAME}" upper)
string(REPLACE "-" "\\-" name_escaped "${NAME}")
set(page ".TH ${upper} 1 \"${date}\" \"Frezka ${VERSION}\" \"User Commands\"\n")
string(APPEND page ".SH NAME\n${name_escaped} \\- ${SUMMARY}\n")
string(APPEND page ".SH SYNOPSIS\n.B ${name_escaped}\n.RI [ options ]\n")
string(APPEND page ".SH DESCRIPTION\nThe text below is what\n.B ${name_escaped} \\-\\-help\nprints.\n")
string(APPEND page ".PP\n.nf\n${help}.fi\n")
string(APPEND page ".SH VERSION\n.B ${name_escaped} \\-\\-version\nprints the version.\n")
if(SERIAL)
    string(APPEND page ".SH SERIAL PORTS\nOpening a serial port (/dev/ttyS*, /dev/ttyUSB*) needs membership of the\n.B dialout\ngroup:\n.B sudo usermod \\-aG dialout $USER\n, then log out and in again.\n")
endif()
if(SEEALSO)
    string(APPEND page ".SH SEE ALSO\n${SEEALSO}\n")
endif()
file(WRITE "${OUT}" "${page}")
