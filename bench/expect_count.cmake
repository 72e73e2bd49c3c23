# expect_count(PATTERN N): the converted text in `converted` has exactly N
# matches of the regular expression PATTERN. Shared by the converter checks.
function(expect_count pattern expected)
    string(REGEX MATCHALL "${pattern}" found "${converted}")
    list(LENGTH found count)
    if(NOT count EQUAL expected)
        message(FATAL_ERROR "expected ${expected} matches of '${pattern}', found ${count}")
    endif()
endfunction()
