# Writes OUTPUT, the definition of jt::version_string(), from VERSION and the
# git revision of SOURCE_DIR (when it is a git checkout and git is installed).
# Run at every build; the file is replaced only when its text changes, so an
# unchanged revision rebuilds nothing.
set(text "${VERSION}")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE AND EXISTS "${SOURCE_DIR}/.git")
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse --short=10 HEAD
        OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE
        RESULT_VARIABLE revision_failed ERROR_QUIET)
    if(NOT revision_failed AND revision)
        execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" status --porcelain
                                --untracked-files=no
            OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
        if(changes)
            string(APPEND revision "-dirty")
        endif()
        set(text "${VERSION} (git ${revision})")
    endif()
endif()
file(WRITE "${OUTPUT}.new"
    "// Written by cmake/write_revision.cmake at build time.\n"
    "#include \"jtracer/version.hpp\"\n\n"
    "namespace jt {\n\n"
    "const char* version_string() {\n"
    "    return \"${text}\";\n"
    "}\n\n"
    "}  // namespace jt\n")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.new")
