#include "WindowInput.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <utility>

namespace penumbra::viewer {

WindowInput::WindowInput(GLFWwindow* window) : window_(window)
{
    glfwSetWindowUserPointer(window_, this);
    glfwSetScrollCallback(window_, onScroll);
    glfwGetCursorPos(window_, &cursorX_, &cursorY_);
}

void WindowInput::onScroll(GLFWwindow* window, double, double y)
{
    static_cast<WindowInput*>(glfwGetWindowUserPointer(window))->scroll_ += float(y);
}

bool WindowInput::pressed(int key)
{
    const bool down = glfwGetKey(window_, key) == GLFW_PRESS;
    const bool was = std::exchange(down_[key], down);
    return down && !was;
}

CameraInput WindowInput::poll(bool uiWantsMouse, bool uiWantsKeyboard, float seconds)
{
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    const glm::vec2 drag{float(x - cursorX_), float(y - cursorY_)};
    cursorX_ = x;
    cursorY_ = y;

    CameraInput input;
    input.seconds = seconds;
    if (!uiWantsMouse) {
        if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS)
            input.orbit = drag;
        else if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS)
            input.look = drag;
        input.zoom = scroll_;
    }
    scroll_ = 0.0f;
    if (!uiWantsKeyboard) {
        const auto key = [&](int k) { return glfwGetKey(window_, k) == GLFW_PRESS ? 1.0f : 0.0f; };
        input.move = {key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                      key(GLFW_KEY_W) - key(GLFW_KEY_S)};
        const bool faster = pressed(GLFW_KEY_EQUAL) | pressed(GLFW_KEY_KP_ADD);
        const bool slower = pressed(GLFW_KEY_MINUS) | pressed(GLFW_KEY_KP_SUBTRACT);
        input.speedSteps = int(faster) - int(slower);
        input.frame = pressed(GLFW_KEY_F);
        input.reset = pressed(GLFW_KEY_R);
        animationKeys_.playPause = pressed(GLFW_KEY_SPACE);
        animationKeys_.scrubSteps = int(pressed(GLFW_KEY_PERIOD)) - int(pressed(GLFW_KEY_COMMA));
        animationKeys_.pickSteps = int(pressed(GLFW_KEY_RIGHT_BRACKET)) - int(pressed(GLFW_KEY_LEFT_BRACKET));
    } else {
        animationKeys_ = {};
    }
    // Tab also reaches the viewer while the panel has the keyboard, so the panel can always be hidden.
    togglePanel_ = pressed(GLFW_KEY_TAB);
    return input;
}

} // namespace penumbra::viewer
