#pragma once

namespace penumbra::viewer {

// glfwInit for the lifetime of this object. GLFW reports failures through a callback; the last
// message becomes the rhi::Error thrown here or by lastGlfwError(), so a missing display reads
// "GLFW: X11: The DISPLAY environment variable is missing" instead of a crash.
class GlfwSession {
public:
    GlfwSession();
    ~GlfwSession();
    GlfwSession(const GlfwSession&) = delete;
    GlfwSession& operator=(const GlfwSession&) = delete;
};

// The last error GLFW reported ("" when none), cleared by reading it.
const char* lastGlfwError();

} // namespace penumbra::viewer
