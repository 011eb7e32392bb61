# FREZKA_VERSION_STRING: the project version, and the git description when built from a git
# checkout ("0.1.0 (v0.1.0-12-gabc1234-dirty)"); read at configure time, so a rebuild after new
# commits shows the old description until CMake runs again (it does on every CMakeLists change).
set(FREZKA_VERSION_STRING "${PROJECT_VERSION}")
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
    execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --tags
        WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
        OUTPUT_VARIABLE _frezka_git OUTPUT_STRIP_TRAILING_WHITESPACE
        RESULT_VARIABLE _frezka_git_result ERROR_QUIET)
    if(_frezka_git_result EQUAL 0 AND _frezka_git)
        set(FREZKA_VERSION_STRING "${PROJECT_VERSION} (git ${_frezka_git})")
    endif()
endif()

# frezka_version: the one generated source defining frezka::app::versionString()
# (app/common/version.h); configure_file rewrites it only when the text changes.
function(frezka_add_version_library)
    set(source ${CMAKE_BINARY_DIR}/generated/frezka_version.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT
"#include \"app/common/version.h\"\n\nconst char *frezka::app::versionString()\n{\n    return \"@FREZKA_VERSION_STRING@\";\n}\n"
        @ONLY)
    add_library(frezka_version STATIC ${source})
    frezka_module_includes(frezka_version app/common)
endfunction()
