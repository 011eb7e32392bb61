# Member-home check (issue 13, "Done when"): no source file of a folder defines members of a
# class declared in another file's header. A class's members are defined in the .cpp named like
# the header that declares it (jog.h -> jog.cpp), so a topic never spreads one class over
# several files again (MachineCore once was seven files sharing 60 fields).
#
#   cmake -DROOT=<project root> [-DDIRS=<folder>;<folder>] -P CheckMemberHomes.cmake
#
# DIRS defaults to driver/link. A declaration is a header line "class Name" or "struct Name"
# that is not a forward declaration (no ';' at its end). A definition is a line of a .cpp that
# starts at column 0 and reads "[return type] Name::member(" (constructors and destructors
# too). Each definition of a member of a class whose header is not the file's own is reported
# as "file:line: ..."; the script fails when there is any. Classes declared in no header of
# the folder (a .cpp's own helpers, other folders' classes) are not checked.
cmake_minimum_required(VERSION 3.25)

if(NOT ROOT)
    message(FATAL_ERROR "CheckMemberHomes.cmake: pass -DROOT=<project root>")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
if(NOT DIRS)
    set(DIRS driver/link)
endif()

set(violations 0)
set(definitions 0)
foreach(dir IN LISTS DIRS)
    # Which header of the folder declares each class.
    file(GLOB headers RELATIVE "${ROOT}/${dir}" "${ROOT}/${dir}/*.h")
    set(classes "")
    foreach(header IN LISTS headers)
        file(STRINGS "${ROOT}/${dir}/${header}" lines
             REGEX "^[ \t]*(class|struct)[ \t]+[A-Za-z_][A-Za-z0-9_]*")
        foreach(line IN LISTS lines)
            if(line MATCHES ";[ \t]*(//.*)?$")
                continue() # a forward declaration
            endif()
            string(REGEX REPLACE "^[ \t]*(class|struct)[ \t]+([A-Za-z_][A-Za-z0-9_]*).*" "\\2"
                   name "${line}")
            list(APPEND classes "${name}")
            list(APPEND "home_${name}" "${header}")
        endforeach()
    endforeach()
    # Every member definition of those classes, against the file's own header.
    file(GLOB sources RELATIVE "${ROOT}/${dir}" "${ROOT}/${dir}/*.cpp")
    foreach(source IN LISTS sources)
        string(REGEX REPLACE "\\.cpp$" ".h" own "${source}")
        file(STRINGS "${ROOT}/${dir}/${source}" lines)
        set(number 0)
        foreach(line IN LISTS lines)
            math(EXPR number "${number} + 1")
            if(NOT line MATCHES
               "^([A-Za-z_][A-Za-z0-9_:<>,*& ]*[ *&:])?([A-Za-z_][A-Za-z0-9_]*)::~?[A-Za-z_][A-Za-z0-9_]*[ \t]*\\(")
                continue()
            endif()
            set(name "${CMAKE_MATCH_2}")
            if(NOT name IN_LIST classes)
                continue()
            endif()
            math(EXPR definitions "${definitions} + 1")
            if(NOT own IN_LIST "home_${name}")
                list(JOIN "home_${name}" ", " where)
                message(NOTICE "${dir}/${source}:${number}: defines a member of ${name}, which "
                               "${where} declares (define it in its own .cpp)")
                math(EXPR violations "${violations} + 1")
            endif()
        endforeach()
    endforeach()
endforeach()

if(violations GREATER 0)
    message(FATAL_ERROR "${violations} member definition(s) outside their class's own file")
endif()
message(NOTICE "${definitions} member definitions in ${DIRS}: each in its class's own file")
