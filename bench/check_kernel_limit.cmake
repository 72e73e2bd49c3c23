# Runs kernel-limit and jtracer-cli on bench/tests/silhouette_check.jts: every
# mode must trace rays, and as many as JTracer (within 1%: Embree's round curve
# ends and float hits move a few shadow and mirror rays).
execute_process(COMMAND ${CLI} ${SCENE} -o ${OUT} --threads 2 RESULT_VARIABLE status
                OUTPUT_VARIABLE cli_output ERROR_VARIABLE cli_errors)
string(REGEX MATCH ", ([0-9]+) rays, " found "${cli_output}${cli_errors}")
if(NOT status EQUAL 0 OR NOT found)
    message(FATAL_ERROR "jtracer-cli failed or printed no ray count: ${cli_output}${cli_errors}")
endif()
set(jtracer_rays ${CMAKE_MATCH_1})
execute_process(COMMAND ${KERNEL_LIMIT} ${SCENE} --threads 2 --runs 1 RESULT_VARIABLE status
                OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "kernel-limit failed: ${status} ${output}${errors}")
endif()
foreach(mode ray1 ray8 ray16)
    if(NOT output MATCHES "mode ${mode}: ([0-9]+) rays, [0-9.]+ s, [0-9.]+ Mrays/s")
        message(FATAL_ERROR "no figure for ${mode}: ${output}")
    endif()
    math(EXPR difference "${CMAKE_MATCH_1} - ${jtracer_rays}")
    math(EXPR allowed "${jtracer_rays} / 100")
    if(difference GREATER allowed OR difference LESS -${allowed})
        message(FATAL_ERROR "${mode} traced ${CMAKE_MATCH_1} rays, JTracer ${jtracer_rays}")
    endif()
endforeach()
