#pragma once

struct GLFWwindow;

namespace penumbra::viewer {

// A Dear ImGui context fed by GLFW's input (ImGui's own GLFW platform backend, from Debian's
// libimgui-dev); drawing is ImGuiRenderer's. Writes no imgui.ini.
class ImGuiSession {
public:
    explicit ImGuiSession(GLFWwindow* window);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;

    void newFrame();
    bool wantsMouse() const;
    bool wantsKeyboard() const;
};

} // namespace penumbra::viewer
