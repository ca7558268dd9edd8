# What the Vulkan backend links: the loader and headers, and GLFW for window surfaces.
find_package(Vulkan REQUIRED)
find_package(glfw3 REQUIRED)
