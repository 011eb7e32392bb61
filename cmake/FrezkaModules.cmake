# Module walls (docs/architecture.md, "Walls").
#
# Every header is included by its module path ("gcode/parser.h", "driver/link/linkengine.h").
# Instead of exporting the project root (which lets any target include any header), each module
# target exports an include root of its own in the build tree:
#
#     ${CMAKE_BINARY_DIR}/include/<target>/<module path>  ->  ${PROJECT_SOURCE_DIR}/<module path>
#
# a symbolic link to the module's source folder. So "gcode/parser.h" resolves only for targets
# that link frezka_gcode (directly or through a PUBLIC link), edits to headers are seen at once
# (no copies), and AUTOMOC and lupdate see ordinary include directories.
#
# The compiler wall follows the link lists, which are transitive; which module may include
# which is stated in cmake/module-deps.txt and checked by the test arch.module_dependencies
# (cmake/CheckModuleDeps.cmake).

# frezka_module_includes(<target> <module path>)
# Gives <target> the include root of the module at <module path> (relative to the project
# root): PUBLIC for libraries, INTERFACE for interface libraries, PRIVATE for executables.
function(frezka_module_includes target module)
    set(root ${CMAKE_BINARY_DIR}/include/${target})
    set(link ${root}/${module})
    set(source ${PROJECT_SOURCE_DIR}/${module})
    if(NOT IS_DIRECTORY ${source})
        message(FATAL_ERROR "frezka_module_includes(${target} ${module}): no folder ${source}")
    endif()
    get_filename_component(parent ${link} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    if(IS_SYMLINK ${link})
        file(READ_SYMLINK ${link} current)
    endif()
    if(NOT current STREQUAL source)
        file(REMOVE ${link})
        file(CREATE_LINK ${source} ${link} SYMBOLIC RESULT failed)
        if(failed)
            message(FATAL_ERROR "frezka_module_includes: cannot link ${link}: ${failed}")
        endif()
    endif()
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE")
        set(scope PRIVATE)
    elseif(type STREQUAL "INTERFACE_LIBRARY")
        set(scope INTERFACE)
    else()
        set(scope PUBLIC)
    endif()
    target_include_directories(${target} ${scope} ${root})
endfunction()

# frezka_check_no_root_includes(): fails the configuration when a target of the build exports
# or uses the project root (or a module's parent folder such as driver/) as an include
# directory, which would open every wall again. Called once at the end of the top-level
# CMakeLists.txt.
function(frezka_check_no_root_includes)
    set(dirs ${PROJECT_SOURCE_DIR})
    set(offenders "")
    while(dirs)
        list(POP_FRONT dirs dir)
        get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
        list(APPEND dirs ${subdirs})
        get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
        foreach(target IN LISTS targets)
            get_target_property(type ${target} TYPE)
            set(props INTERFACE_INCLUDE_DIRECTORIES)
            if(NOT type STREQUAL "INTERFACE_LIBRARY")
                list(APPEND props INCLUDE_DIRECTORIES)
            endif()
            foreach(prop IN LISTS props)
                get_target_property(includes ${target} ${prop})
                foreach(include IN LISTS includes)
                    get_filename_component(include "${include}" ABSOLUTE)
                    if(include STREQUAL PROJECT_SOURCE_DIR
                            OR include STREQUAL "${PROJECT_SOURCE_DIR}/driver"
                            OR include STREQUAL "${PROJECT_SOURCE_DIR}/app")
                        list(APPEND offenders "${target} (${prop} ${include})")
                    endif()
                endforeach()
            endforeach()
        endforeach()
    endwhile()
    if(offenders)
        list(JOIN offenders "\n  " text)
        message(FATAL_ERROR "These targets use the project root as an include directory, which "
            "lets them include any header:\n  ${text}\nGive each module its own include root "
            "instead: frezka_module_includes(<target> <module path>) (cmake/FrezkaModules.cmake), "
            "and link the modules it may use (cmake/module-deps.txt).")
    endif()
endfunction()
