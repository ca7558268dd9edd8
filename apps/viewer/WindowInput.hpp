#pragma once

#include "CameraController.hpp"

#include <map>

struct GLFWwindow;

namespace penumbra::viewer {

// Turns GLFW's mouse, scroll and keys into CameraInput: left drag orbits, right drag looks,
// scroll zooms, W A S D Q E fly, + and - change the fly speed, F frames the scene, R resets the camera; Tab
// shows or hides the panel; Space, `,` `.` and `[` `]` play, scrub and pick animations (AnimationKeys). Input the UI
// takes (mouse over the panel, typing) is left out.
// The animation keys pressed since the last poll (AnimationPlayer says what they do).
struct AnimationKeys {
    bool playPause = false; // Space
    int scrubSteps = 0; // `.` forward, `,` back
    int pickSteps = 0; // `]` next animation, `[` previous
};

class WindowInput {
public:
    // Installs the scroll callback; create it before ImGuiSession, which chains to it.
    explicit WindowInput(GLFWwindow* window);

    CameraInput poll(bool uiWantsMouse, bool uiWantsKeyboard, float seconds);
    // Whether Tab was pressed since the last poll: show or hide the panel.
    bool togglePanel() const { return togglePanel_; }
    // The animation keys of the last poll.
    const AnimationKeys& animationKeys() const { return animationKeys_; }

private:
    static void onScroll(GLFWwindow* window, double x, double y);
    // Whether `key` went down since the last poll (a held key counts once).
    bool pressed(int key);

    GLFWwindow* window_;
    double cursorX_ = 0.0;
    double cursorY_ = 0.0;
    float scroll_ = 0.0f;
    std::map<int, bool> down_; // keys read by pressed(), as they were at the last poll
    bool togglePanel_ = false;
    AnimationKeys animationKeys_;
};

} // namespace penumbra::viewer
