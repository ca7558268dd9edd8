// penumbra: the command-line tool. Every subcommand runs on any configuration by name.
#include "Commands.hpp"
#include "Interrupt.hpp"
#include "ToolDevices.hpp"
#include "ViewCommand.hpp"

#include "penumbra/rhi/Error.hpp"
#include "penumbra/scene/Scene.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace {

// Errors with context (a flag, a file, a configuration) are the user's to fix: exit status 1.
int reportError(const std::exception& e)
{
    fmt::print(stderr, "penumbra: error: {}\n", e.what());
    return 1;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"Penumbra: one renderer, Vulkan and OpenGL, identical pixels"};
    app.require_subcommand(1);
    // The RHI's validation layer (DeviceDesc::validateUsage) is on in debug builds; release builds leave it to each
    // command's --validate (toolDeviceDesc), since `penumbra bench -s draws` measures what it costs.
#ifdef NDEBUG
    penumbra::apps::setToolUsageValidation(false);
#endif
    // Compiled shaders and pipelines outlive the process in the user's cache folder (docs/rhi.md, "Pipeline cache").
    penumbra::apps::setToolPipelineCache(penumbra::apps::pipelineCacheFromEnvironment());
    penumbra::apps::addRenderCommand(app);
    penumbra::apps::addPatternCommand(app);
    penumbra::apps::addParityCommand(app);
    penumbra::apps::addConfigurationsCommand(app);
    penumbra::apps::addBenchCommand(app);
    penumbra::apps::addTruthCommand(app);
    penumbra::apps::addBakeCommand(app);
    penumbra::apps::addSoakCommand(app);
    penumbra::apps::addViewCommand(app);
    penumbra::apps::addSettingsCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const penumbra::apps::Interrupted& e) {
        fmt::print(stderr, "\npenumbra: {}\n", e.what());
        return 128 + e.signal();
    } catch (const penumbra::rhi::Error& e) {
        return reportError(e);
    } catch (const penumbra::scene::SceneError& e) {
        return reportError(e);
    } catch (const std::exception& e) {
        fmt::print(stderr, "penumbra: unexpected error: {}\n", e.what());
        return 2;
    }
    return 0;
}
