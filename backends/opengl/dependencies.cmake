# What the OpenGL backend links: EGL and OSMesa for headless contexts, GLFW for window contexts,
# SPIRV-Cross for GLSL.
find_package(PkgConfig REQUIRED)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(OSMesa REQUIRED IMPORTED_TARGET osmesa)
find_package(glfw3 REQUIRED)
find_package(spirv_cross_core REQUIRED)
find_package(spirv_cross_glsl REQUIRED)
