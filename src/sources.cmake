# SPDX-License-Identifier: MIT
# The library's sources, one list per layer (src/README.md draws the layers),
# relative to src/. src/CMakeLists.txt builds each list as a layer of its
# own; web/CMakeLists.txt (the WebAssembly playground) and
# fuzz/CMakeLists.txt (through LITKIT_LOADER_SOURCES) take theirs from here,
# so that a new file is named once.
set(LITKIT_LAYER_SOURCES_core
    core/backend.cpp core/error.cpp core/files.cpp core/image.cpp core/portable_math.cpp
    core/thread_pool.cpp)
set(LITKIT_LAYER_SOURCES_lighting
    lighting/lighting.cpp)
set(LITKIT_LAYER_SOURCES_geometry
    geometry/closed_mesh.cpp geometry/convex.cpp geometry/mesh_data.cpp geometry/mesh_formats.cpp geometry/normals.cpp
    geometry/gltf.cpp geometry/obj.cpp geometry/obj_numbers.cpp geometry/ply.cpp geometry/shapes.cpp
    geometry/stl.cpp geometry/teapot.cpp geometry/tinygltf.cpp geometry/tinyobjloader.cpp
    geometry/weld.cpp)
set(LITKIT_LAYER_SOURCES_scene
    scene/camera.cpp scene/default_scene.cpp scene/float_range.cpp scene/load.cpp
    scene/nesting.cpp scene/read_tables.cpp scene/read_values.cpp scene/scene.cpp scene/toml.cpp
    scene/transparency.cpp scene/validate.cpp scene/words.cpp scene/write.cpp)
# trace: refraction's rays (docs/spec.md §10), the hierarchy and the ray tree.
set(LITKIT_LAYER_SOURCES_trace
    trace/accel.cpp trace/bvh_build.cpp trace/ray_tree.cpp)
set(LITKIT_LAYER_SOURCES_cpu
    cpu/clip.cpp cpu/fragment.cpp cpu/glass.cpp cpu/prepare.cpp cpu/rasterize.cpp cpu/render.cpp
    cpu/samples.cpp cpu/setup.cpp
    cpu/shade_kernel.cpp cpu/shade_kernel_avx2.cpp cpu/shade_kernel_avx512.cpp
    cpu/shade_kernel_portable.cpp cpu/vertex.cpp)
# codegen also compiles embedded_text.cpp, generated in the build tree.
set(LITKIT_LAYER_SOURCES_codegen
    codegen/export.cpp codegen/export_glass.cpp codegen/export_samples.cpp codegen/gl_glass.cpp codegen/gl_scene.cpp codegen/glsl.cpp
    codegen/glsl_expr.cpp codegen/glsl_functions.cpp codegen/glsl_glass.cpp)
set(LITKIT_LAYER_SOURCES_teach
    teach/compare.cpp teach/explain.cpp teach/explain_format.cpp teach/explain_tree.cpp
    teach/labels.cpp teach/turntable.cpp)
set(LITKIT_LAYER_SOURCES_gl
    gl/gl_renderer.cpp)

# What reading and checking a scene needs (the loader, validation and the
# meshes it builds), which fuzz/CMakeLists.txt compiles on its own: the
# layers up to scene/, less PNG writing, the thread pool and what only
# drawing or writing scenes uses.
set(LITKIT_LOADER_SOURCES
    ${LITKIT_LAYER_SOURCES_core} ${LITKIT_LAYER_SOURCES_lighting}
    ${LITKIT_LAYER_SOURCES_geometry} ${LITKIT_LAYER_SOURCES_scene})
list(REMOVE_ITEM LITKIT_LOADER_SOURCES
    core/backend.cpp core/image.cpp core/thread_pool.cpp
    scene/camera.cpp scene/default_scene.cpp scene/write.cpp)
