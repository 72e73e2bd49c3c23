# Converts the showcase with jts-to-pov and checks what the POV-Ray scene says:
# one object per primitive, the lights, the camera mirrored in z, no gamma.
# Also checks that a missing scene is an I/O error (exit 3) and writes nothing.
execute_process(COMMAND ${CONVERTER} ${SCENE} ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "jts-to-pov failed on ${SCENE}: ${status}")
endif()
file(READ ${OUT} converted)
include(${CMAKE_CURRENT_LIST_DIR}/expect_count.cmake)
expect_count("\n#version 3\\.7;" 1)
expect_count("assumed_gamma 1\\.0" 1)
expect_count("max_trace_level 5 " 1)             # recurse_depth 4, plus the primary ray
expect_count("\nsphere \\{" 4)
expect_count("\ncylinder \\{" 2)
expect_count("\nplane \\{" 2)
expect_count("\nlight_source \\{" 3)
expect_count("location <0, 2.4, -9>" 1)        # the camera "Main", z mirrored
expect_count("plane \\{ <0, 0, -1>, -7" 1)     # the backdrop, normal mirrored
expect_count("brilliance 1 phong" 7)           # diffuse_k 1 everywhere; 7 specular objects
expect_count(" matrix <" 3)                    # the ellipsoid and the two cylinders

execute_process(COMMAND ${CONVERTER} ${SCENE}.missing ${OUT}.missing RESULT_VARIABLE status
                ERROR_VARIABLE message)
if(NOT status EQUAL 3 OR NOT message MATCHES "cannot read" OR EXISTS ${OUT}.missing)
    message(FATAL_ERROR "a missing scene should be exit 3 with a message: ${status} ${message}")
endif()
