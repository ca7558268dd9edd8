#pragma once

#include "CameraController.hpp"

struct GLFWwindow;

namespace penumbra::viewer {

// Turns GLFW's mouse, scroll and keys into CameraInput: left drag orbits, right drag looks,
// scroll zooms, W A S D Q E fly. Input the UI takes (mouse over the panel, typing) is left out.
class WindowInput {
public:
    // Installs the scroll callback; create it before ImGuiSession, which chains to it.
    explicit WindowInput(GLFWwindow* window);

    CameraInput poll(bool uiWantsMouse, bool uiWantsKeyboard, float seconds);

private:
    static void onScroll(GLFWwindow* window, double x, double y);

    GLFWwindow* window_;
    double cursorX_ = 0.0;
    double cursorY_ = 0.0;
    float scroll_ = 0.0f;
};

} // namespace penumbra::viewer
