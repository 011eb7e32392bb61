# Citation check: every "gve-protocol.md §N" in the sources and docs names a section that the
# reference has.
#
#   cmake -DROOT=<project root> [-DDOC=<reference>] [-DEXCLUDE=<dir>;<dir>]
#         -P CheckDocCitations.cmake
#
# DOC defaults to ROOT/docs/gve-protocol.md. A section is a Markdown heading that starts with
# its number ("## 2. Framing", "### 2.1 Checksums"). A citation is the document's name (with or
# without ".md") followed by section numbers: "gve-protocol.md §2.1", "§1, §3, §11", "§4-§13"
# (a range cites both ends). Each citation of a missing section is reported as "file:line: ...";
# the script fails when there is any. Files: C++ sources and headers, Markdown, CMake and text
# files under ROOT, without build trees (folders with a CMakeCache.txt), hidden folders and
# EXCLUDE.
cmake_minimum_required(VERSION 3.25)

if(NOT ROOT)
    message(FATAL_ERROR "CheckDocCitations.cmake: pass -DROOT=<project root>")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
if(NOT DOC)
    set(DOC "${ROOT}/docs/gve-protocol.md")
endif()
get_filename_component(DOC "${DOC}" ABSOLUTE)
get_filename_component(docName "${DOC}" NAME_WE)
file(RELATIVE_PATH docPath "${ROOT}" "${DOC}")

# The sections of the reference.
file(STRINGS "${DOC}" headings REGEX "^#+[ \t]+[0-9]+(\\.[0-9]+)*\\.?[ \t]")
set(sections "")
foreach(heading IN LISTS headings)
    string(REGEX REPLACE "^#+[ \t]+([0-9]+(\\.[0-9]+)*).*" "\\1" number "${heading}")
    list(APPEND sections "${number}")
endforeach()
if(NOT sections)
    message(FATAL_ERROR "${docPath} has no numbered section")
endif()

# The files to read.
set(files "")
file(GLOB entries LIST_DIRECTORIES true RELATIVE "${ROOT}" "${ROOT}/*")
foreach(entry IN LISTS entries)
    if(entry MATCHES "^\\." OR EXISTS "${ROOT}/${entry}/CMakeCache.txt")
        continue()
    endif()
    if(IS_DIRECTORY "${ROOT}/${entry}")
        set(globs "")
        foreach(ext h hpp cpp cc md txt cmake)
            list(APPEND globs "${ROOT}/${entry}/*.${ext}")
        endforeach()
        file(GLOB_RECURSE found RELATIVE "${ROOT}" ${globs})
    elseif(entry MATCHES "\\.(md|txt)$")
        set(found "${entry}")
    else()
        set(found "")
    endif()
    foreach(file IN LISTS found)
        set(skip FALSE)
        foreach(excluded IN LISTS EXCLUDE)
            string(FIND "${file}" "${excluded}/" at)
            if(at EQUAL 0)
                set(skip TRUE)
            endif()
        endforeach()
        if(NOT skip AND NOT file STREQUAL docPath AND NOT file MATCHES "(^|/)\\.")
            list(APPEND files "${file}")
        endif()
    endforeach()
endforeach()
list(SORT files)

# Every citation of every file.
set(sectionRegex "§[0-9]+(\\.[0-9]+)*")
set(citationRegex
    "${docName}(\\.md)?[ \t]+${sectionRegex}(([ \t]*(,|-|and)[ \t]*)${sectionRegex})*")
set(violations "")
set(citationCount 0)
foreach(file IN LISTS files)
    file(STRINGS "${ROOT}/${file}" lines REGEX "${docName}")
    if(NOT lines)
        continue()
    endif()
    # file(STRINGS) gives no line numbers: find each citing line's number in the whole text.
    file(READ "${ROOT}/${file}" content)
    string(REPLACE ";" "," content "${content}")
    string(REPLACE "[" "(" content "${content}")
    string(REPLACE "]" ")" content "${content}")
    string(REPLACE "\\" "/" content "${content}")
    string(REPLACE "\n" ";" all "${content}")
    set(number 0)
    foreach(line IN LISTS all)
        math(EXPR number "${number} + 1")
        if(NOT line MATCHES "${docName}")
            continue()
        endif()
        string(REGEX MATCHALL "${citationRegex}" citations "${line}")
        foreach(citation IN LISTS citations)
            string(REGEX MATCHALL "${sectionRegex}" cited "${citation}")
            foreach(section IN LISTS cited)
                string(SUBSTRING "${section}" 2 -1 id) # after the two bytes of "§"
                math(EXPR citationCount "${citationCount} + 1")
                if(NOT id IN_LIST sections)
                    list(APPEND violations
                        "${file}:${number}: cites ${docPath} §${id}, which it does not have")
                endif()
            endforeach()
        endforeach()
    endforeach()
endforeach()

foreach(text IN LISTS violations)
    message(NOTICE "${text}")
endforeach()
list(LENGTH violations violationCount)
if(violationCount GREATER 0)
    list(JOIN sections " " have)
    message(FATAL_ERROR "${violationCount} citation(s) of missing sections; ${docPath} has: "
        "${have}")
endif()
if(citationCount EQUAL 0)
    message(FATAL_ERROR "No file cites ${docName} by section: is ${docPath} the right document?")
endif()
message(STATUS "${docPath}: ${citationCount} section citations, every one exists")
