# Runs bench/check_silhouettes.py on bench/tests/silhouette_check.jts twice:
# with Tachyon as it is, the silhouettes must agree (exit 0); with a Tachyon
# that drops the cylinders, the check must say DISAGREE and exit 1. Then on a
# thousand random spheres at 96x54, most of them under a pixel across, which
# agree only when Tachyon's rays are taken through JTracer's pixel centres.
execute_process(COMMAND ${PYTHON} ${CHECK} --cli ${CLI} --converter ${CONVERTER} --tachyon ${TACHYON}
                        ${SCENE} ${WORK}/as_is
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT output MATCHES "silhouettes agree")
    message(FATAL_ERROR "the silhouettes should agree: ${status}\n${output}${errors}")
endif()
execute_process(COMMAND ${PYTHON} ${CHECK} --cli ${CLI} --converter ${CONVERTER}
                        --tachyon ${DROPPING_TACHYON} ${SCENE} ${WORK}/without_cylinders
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 1 OR NOT output MATCHES "silhouettes DISAGREE")
    message(FATAL_ERROR "missing cylinders should fail the check: ${status}\n${output}${errors}")
endif()
execute_process(COMMAND ${PYTHON} ${GENERATOR} ${WORK}/scenes --only spheres_1k
                RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_QUIET)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "generate_scenes.py failed: ${errors}")
endif()
execute_process(COMMAND ${PYTHON} ${CHECK} --cli ${CLI} --converter ${CONVERTER} --tachyon ${TACHYON}
                        --size 96x54 ${WORK}/scenes/spheres_1k.jts ${WORK}/subpixel
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT output MATCHES "silhouettes agree: 100.00%")
    message(FATAL_ERROR "sub-pixel spheres should agree on every pixel: ${status}\n${output}${errors}")
endif()
