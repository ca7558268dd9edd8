#include "Viewer.hpp"

#include "CameraController.hpp"
#include "Compositor.hpp"
#include "GlfwSession.hpp"
#include "ImGuiRenderer.hpp"
#include "ImGuiSession.hpp"
#include "SceneShadowDefaults.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "ViewState.hpp"
#include "ViewerScene.hpp"
#include "ToolDevices.hpp"
#include "ViewerWindow.hpp"
#include "WindowInput.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/render/AtlasPicture.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Image.hpp"
#include "penumbra/scene/Posing.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <imgui.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::viewer {
namespace {

rhi::DeviceDesc windowDeviceDesc(const std::string& configuration, bool validate, GLFWwindow* window)
{
    rhi::DeviceDesc desc = apps::toolDeviceDesc(configuration);
    desc.validation = validate;
    desc.validateUsage = desc.validateUsage || validate;
    desc.window.glfwWindow = window;
    return desc;
}

// Everything one viewer run owns, declared in the order it must be built (and torn down in reverse):
// the window outlives the device, the device every GPU object, the ImGui context its renderer.
class ViewerApp {
public:
    explicit ViewerApp(const ViewerOptions& options)
        : options_(options), window_(penumbra::parseConfiguration(options.configuration), options.width, options.height,
                                     fmt::format("Penumbra viewer: {} ({})", options.scene, options.configuration)),
          device_(createDevice(windowDeviceDesc(options.configuration, options.validate, window_.handle()))),
          swapchain_(device_->createSwapchain()), input_(window_.handle()), scene_([&] {
              ViewerScene loaded = loadViewerScene(options.scene, options.filter, options.lightSize);
              loaderNotes_ = std::move(loaded.notes);
              return std::move(loaded.scene);
          }()),
          camera_(scene_.camera, orbitTargetDistance(scene_)), renderer_(*device_, scene_), compositor_(*device_)
    {
        applied_ = viewStateOf(scene_);
        // The shadows `penumbra render` gives the scene without --settings: distance and atlases fitted to it.
        applied_.shadows = apps::sceneShadowSettings(scene_);
        const scene::Bounds bounds = scene_.worldBounds();
        if (!bounds.empty()) {
            sceneCenter_ = bounds.center();
            sceneRadius_ = std::max(0.5f * glm::length(bounds.size()), 1e-3f);
        }
        camera_.flySpeed = CameraController::flySpeedFor(sceneRadius_);
        applied_.cascadeView = options.cascadeView;
        applied_.atlasOverlay = options.atlasOverlay;
        applied_.maxAnisotropy = options.maxAnisotropy;
        for (const auto& [path, text] : options.settingsFields)
            shadows::setSettingsField(applied_.shadows, path, text);
        if (!options.baked.empty()) {
            renderer_.useBakedShadows(shadows::readStaticShadowBake(options.baked));
            applied_.shadows.staticMaps.update = shadows::StaticShadowUpdate::OnChange;
            // The bake's casters are not drawn into the realtime atlases every frame (as `render --baked`).
            applied_.shadows.staticMaps.realtimeCasters = shadows::RealtimeCasters::Dynamic;
        }
        applied_.msaa = options.msaa;
        applied_.shadowPath = options.shadowPath;
        applied_.environmentIntensity = options.environment.intensity;
        applied_.environmentRotation = options.environment.rotationDegrees;
        applied_.hasEnvironment = options.environment.image != nullptr;
        environment_ = options.environment.image;
        const std::array litTargets{render::kLitColorFormat, render::kLitDepthFormat};
        status_.msaaCounts = device_->capabilities().sampleCounts(litTargets);
        edited_ = applied_;
        if (options.ui) {
            imgui_.emplace(window_.handle());
            imguiRenderer_.emplace(*device_, Compositor::kFormat);
        }
    }

    void run()
    {
        std::uint32_t frame = 0;
        double totalMs = 0.0;
        rhi::Image windowPicture;
        while (!window_.shouldClose() && (!options_.frames || frame < *options_.frames)) {
            const auto start = std::chrono::steady_clock::now();
            // The last frame of a screenshot run is read back from the window itself.
            const bool last = options_.frames && frame + 1 == *options_.frames;
            drawFrame(last && !options_.screenshot.empty() ? &windowPicture : nullptr);
            status_.frameMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            totalMs += status_.frameMs;
            ++frame;
        }
        if (!options_.screenshot.empty()) {
            if (windowPicture.bytes.empty())
                throw rhi::Error(
                    fmt::format("--screenshot {}: no frame reached the window (minimised, or closed before "
                                "--frames)",
                                options_.screenshot));
            parity::writePng(options_.screenshot, windowPicture);
            fmt::print("screenshot: {}\n", options_.screenshot);
        }
        const std::vector<std::string> messages = device_->debugMessages();
        fmt::print("viewer: {} on {}, {} frames, {:.1f} ms per frame, {} validation / debug messages\n",
                   penumbra::configurationName(device_->desc()), device_->capabilities().device, frame,
                   frame ? totalMs / frame : 0.0, messages.size());
        if (!messages.empty())
            throw rhi::Error(fmt::format("{} validation / debug message(s), first: {}", messages.size(), messages[0]));
    }

private:
    void drawFrame(rhi::Image* windowPicture)
    {
        glfwPollEvents();
        const rhi::Extent size = swapchain_->drawableSize();
        const CameraInput input = input_.poll(imgui_ && imgui_->wantsMouse(), imgui_ && imgui_->wantsKeyboard(),
                                              float(status_.frameMs * 1e-3));
        camera_.update(input, sceneCenter_, sceneRadius_,
                       size.height > 0 ? float(size.width) / float(size.height) : 1.0f);
        if (input_.togglePanel())
            panelShown_ = !panelShown_;
        const AnimationKeys& keys = input_.animationKeys();
        animation_.playing = animation_.playing != keys.playPause;
        animation_.pick(keys.pickSteps, scene_.rig);
        animation_.scrub(keys.scrubSteps, scene_.rig);
        animation_.advance(float(status_.frameMs * 1e-3), scene_.rig);
        if (imgui_) {
            imgui_->newFrame();
            if (panelShown_ && drawSettingsPanel(edited_, status_, scene_))
                status_.error = applyViewState(edited_, applied_, scene_);
            if (panelShown_)
                drawAnimationPanel(animation_, scene_.rig);
            ImGui::Render();
        }
        if (!scene_.rig.animations.empty())
            scene::poseScene(scene_, animation_.animation, animation_.time);
        if (size.width == 0 || size.height == 0)
            return; // minimised
        render(size);
        const rhi::Texture& picture = applied_.cascadeView ? renderer_.cascadeImage() : renderer_.litImage();
        if (imgui_)
            compositor_.compose(picture, size, [&](rhi::CommandList& commands) {
                imguiRenderer_->record(commands, *ImGui::GetDrawData());
            });
        else
            compositor_.compose(picture, size);
        if (windowPicture)
            *windowPicture = swapchain_->presentAndReadBack(compositor_.image());
        else
            swapchain_->present(compositor_.image());
    }

    void render(rhi::Extent size)
    {
        render::FrameDesc frame;
        frame.width = size.width;
        frame.height = size.height;
        frame.shadows = applied_.shadows;
        frame.cascadeView = applied_.cascadeView;
        frame.maxAnisotropy = applied_.maxAnisotropy;
        frame.msaa = applied_.msaa;
        frame.shadowPath = applied_.shadowPath;
        frame.environment = {environment_, applied_.environmentIntensity, applied_.environmentRotation};
        if (applied_.redrawStaticMaps)
            renderer_.requestStaticShadowUpdate();
        applied_.redrawStaticMaps = edited_.redrawStaticMaps = false;
        status_.stats = renderer_.render(camera_.camera(), frame);
        status_.notes = loaderNotes_;
        status_.notes.push_back(fmt::format("fly speed {:.3g} units/s (+ and - change it); F frames the scene, R "
                                            "resets the camera, Tab hides this panel",
                                            camera_.flySpeed));
        const std::vector<std::string>& rendererNotes = renderer_.notes();
        status_.notes.insert(status_.notes.end(), rendererNotes.begin(), rendererNotes.end());
        status_.atlasPicture = nullptr;
        if (applied_.atlasOverlay)
            updateAtlasPicture();
    }

    void updateAtlasPicture()
    {
        const rhi::Image picture =
            render::atlasPicture(rhi::readDepth(*device_, renderer_.atlas().texture()), device_->conventions());
        if (!atlasPicture_ || atlasPicture_->desc().width != picture.width)
            atlasPicture_ = device_->createTexture(
                {.width = picture.width, .height = picture.height, .debugName = "atlas overlay"});
        device_->writeTexture(*atlasPicture_, 0, 0, picture.bytes);
        status_.atlasPicture = atlasPicture_.get();
    }

    ViewerOptions options_;
    GlfwSession glfw_;
    ViewerWindow window_;
    std::unique_ptr<rhi::Device> device_;
    std::unique_ptr<rhi::Swapchain> swapchain_;
    WindowInput input_;
    AnimationPlayer animation_;
    std::vector<std::string> loaderNotes_;
    std::shared_ptr<const render::EnvironmentImage> environment_; // ViewerOptions::environment.image
    scene::Scene scene_;
    glm::vec3 sceneCenter_{0.0f}; // the scene's bounding sphere, which F frames and the fly speed follows
    float sceneRadius_ = 1.0f;
    bool panelShown_ = true;
    CameraController camera_;
    render::SceneRenderer renderer_;
    Compositor compositor_;
    std::optional<ImGuiSession> imgui_;
    std::optional<ImGuiRenderer> imguiRenderer_;
    std::unique_ptr<rhi::Texture> atlasPicture_;
    ViewState applied_;
    ViewState edited_;
    PanelStatus status_;
};

} // namespace

void runViewer(const ViewerOptions& options)
{
    if (options.width == 0 || options.height == 0)
        throw rhi::Error(
            fmt::format("--size {}x{}: width and height must be at least 1", options.width, options.height));
    ViewerApp app(options);
    app.run();
}

} // namespace penumbra::viewer
