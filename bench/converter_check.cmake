# What the converter checks (check_converter.cmake, check_tachyon_converter.cmake)
# share: run CONVERTER on a scene, count patterns in what it wrote, and check
# that a missing scene is an I/O error (exit 3) that writes nothing.

# convert(SCENE OUT): converts, failing the check unless it succeeds, and
# reads the result into `converted` in the caller's scope.
function(convert scene out)
    execute_process(COMMAND ${CONVERTER} ${scene} ${out} RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "${CONVERTER} failed on ${scene}: ${status}")
    endif()
    file(READ ${out} text)
    set(converted "${text}" PARENT_SCOPE)
endfunction()

# expect_count(PATTERN N): the converted text in `converted` has exactly N
# matches of the regular expression PATTERN.
function(expect_count pattern expected)
    string(REGEX MATCHALL "${pattern}" found "${converted}")
    list(LENGTH found count)
    if(NOT count EQUAL expected)
        message(FATAL_ERROR "expected ${expected} matches of '${pattern}', found ${count}")
    endif()
endfunction()

# expect_missing_scene_fails(SCENE OUT): SCENE.missing gives exit 3, a
# "cannot read" message and no OUT.missing.
function(expect_missing_scene_fails scene out)
    execute_process(COMMAND ${CONVERTER} ${scene}.missing ${out}.missing RESULT_VARIABLE status
                    ERROR_VARIABLE message)
    if(NOT status EQUAL 3 OR NOT message MATCHES "cannot read" OR EXISTS ${out}.missing)
        message(FATAL_ERROR "a missing scene should be exit 3 with a message: ${status} ${message}")
    endif()
endfunction()
