# Converts the showcase with jts-to-pov and checks what the POV-Ray scene says:
# one object per primitive, the lights, the camera mirrored in z, no gamma,
# glass and the checker; then the mesh scene's triangles and meshes as mesh2,
# and the globe scene's image maps on a plane, a sphere and a cylinder.
# Also checks that a missing scene is an I/O error (exit 3) and writes nothing.
include(${CMAKE_CURRENT_LIST_DIR}/converter_check.cmake)
convert(${SCENE} ${OUT})
expect_count("\n#version 3\\.7;" 1)
expect_count("assumed_gamma 1\\.0" 1)
expect_count("max_trace_level 5 " 1)             # recurse_depth 4, plus the primary ray
expect_count("\nsphere \\{" 5)
expect_count("\ncylinder \\{" 2)
expect_count("\nplane \\{" 2)
expect_count("\nlight_source \\{" 3)
expect_count("location <0, 2.4, -9>" 1)        # the camera "Main", z mirrored
expect_count("plane \\{ <0, 0, -1>, -7" 1)     # the backdrop, normal mirrored
expect_count("brilliance 1 phong" 8)           # diffuse_k 1 everywhere; 8 specular objects
expect_count("rgbt <" 1)                       # the glass ball transmits
expect_count("interior \\{ ior 1.5 \\}" 1)
expect_count("checker rgb" 1)                  # the backdrop
expect_count(" matrix <" 3)                    # the ellipsoid and the two cylinders

expect_missing_scene_fails(${SCENE} ${OUT})

if(DEFINED MESH_SCENE)
    convert(${MESH_SCENE} ${OUT}.mesh.pov)
    expect_count("\nmesh2 \\{" 6)                  # two meshes and four triangles
    expect_count(" normal_vectors \\{ " 1)          # only the smooth one
    expect_count(" face_indices \\{ 20020," 2)      # the knot, twice (one file)
    expect_count("uv_mapping pigment \\{ image_map \\{ png " 1)
endif()

if(DEFINED GLOBE_SCENE)
    convert(${GLOBE_SCENE} ${OUT}.globe.pov)
    expect_count("\nplane \\{ [^\n]* map_type 0 \\} matrix <0.5, 0, -0, 0, 0, 0.5," 1)  # map_size 0.5
    expect_count("\nsphere \\{ [^\n]* map_type 1 \\} matrix <0, 0, 1, 0, 1, 0, -1, 0, 0," 1)
    expect_count("\nunion \\{\n cylinder \\{ [^\n]* open [^\n]* map_type 2 \\} matrix <0, 0, 1, 0, 1.6, 0," 1)
    expect_count("\n disc \\{ [^\n]* map_type 0 \\} matrix <1.2, 0, 0, 0, 0, -1.2, 0, 1, 0, -0.6, 0, 0.6>" 2)
    expect_count("uv_mapping" 0)
endif()
