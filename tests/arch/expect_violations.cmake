# Proves that a check can fail: runs CHECKER (cmake/CheckModuleDeps.cmake or
# cmake/CheckDocCitations.cmake) on a fixture tree with deliberately wrong includes, a wrong
# table or citations of missing sections, and passes only when the check fails and reports
# exactly the violations listed in EXPECTED, no more and no fewer.
#
#   cmake -DCHECKER=<script> -DROOT=<fixture> -DEXPECTED=<file> [-DTABLE=<table>]
#         [-DQT_INCLUDE_DIR=<Qt include root>] -P expect_violations.cmake
cmake_minimum_required(VERSION 3.25)

execute_process(
    COMMAND ${CMAKE_COMMAND} -DROOT=${ROOT} -DTABLE=${TABLE} -DQT_INCLUDE_DIR=${QT_INCLUDE_DIR}
            -P ${CHECKER}
    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(output "${out}${err}")
message(NOTICE "---- output of the check (exit ${result}) ----\n${output}---- end ----")
if(result EQUAL 0)
    message(FATAL_ERROR "The check passed a tree it must refuse (${ROOT}).")
endif()

# Violation lines are "path:line: ..."; the rest is CMake's own error text.
function(violation_lines text out)
    string(REPLACE ";" "," text "${text}")
    string(REPLACE "\n" ";" lines "${text}")
    set(found "")
    foreach(line IN LISTS lines)
        if(line MATCHES "^[^ :]+:[0-9]+: ")
            list(APPEND found "${line}")
        endif()
    endforeach()
    set(${out} "${found}" PARENT_SCOPE)
endfunction()

violation_lines("${output}" reported)
file(READ ${EXPECTED} expectedText)
violation_lines("${expectedText}" expected)
if(NOT expected)
    message(FATAL_ERROR "${EXPECTED} lists no violation.")
endif()
set(missing "${expected}")
if(reported)
    list(REMOVE_ITEM missing ${reported})
endif()
set(unexpected "${reported}")
list(REMOVE_ITEM unexpected ${expected})
if(missing OR unexpected)
    list(JOIN missing "\n  " missingText)
    list(JOIN unexpected "\n  " unexpectedText)
    message(FATAL_ERROR "The check failed, but not as expected.\nNot reported:\n  ${missingText}\n"
        "Reported but not expected:\n  ${unexpectedText}")
endif()
list(LENGTH reported count)
message(NOTICE "The check refused the fixture with the ${count} expected violation(s).")
