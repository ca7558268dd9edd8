#include "ImGuiSession.hpp"

#include "penumbra/rhi/Error.hpp"

#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

namespace penumbra::viewer {

ImGuiSession::ImGuiSession(GLFWwindow* window)
{
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    // Installing callbacks chains them to the ones set before (the viewer's scroll input).
    if (!ImGui_ImplGlfw_InitForOther(window, true)) {
        ImGui::DestroyContext();
        throw rhi::Error("Dear ImGui: the GLFW platform backend did not initialise");
    }
}

ImGuiSession::~ImGuiSession()
{
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiSession::newFrame()
{
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

bool ImGuiSession::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

bool ImGuiSession::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

} // namespace penumbra::viewer
