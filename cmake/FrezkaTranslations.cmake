# frezka_embed_translations(TARGET): the project's .qm files (from translations/*.ts) embedded in
# TARGET under :/i18n/, for executables that do not link the GUI (which embeds its own).
function(frezka_embed_translations target)
    qt_add_lrelease(${target}
        TS_FILES ${PROJECT_SOURCE_DIR}/translations/frezka_cs.ts
                 ${PROJECT_SOURCE_DIR}/translations/frezka_en.ts
        QM_FILES_OUTPUT_VARIABLE qm_files)
    qt_add_resources(${target} ${target}_i18n PREFIX /i18n BASE ${CMAKE_CURRENT_BINARY_DIR}
        FILES ${qm_files})
endfunction()
