// penumbra: the command-line tool. Every subcommand runs on any configuration by name.
#include "Commands.hpp"
#include "ViewCommand.hpp"

#include "penumbra/rhi/Error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

int main(int argc, char** argv)
{
    CLI::App app{"Penumbra: one renderer, Vulkan and OpenGL, identical pixels"};
    app.require_subcommand(1);
    penumbra::apps::addRenderCommand(app);
    penumbra::apps::addPatternCommand(app);
    penumbra::apps::addDemoCommand(app);
    penumbra::apps::addConfigurationsCommand(app);
    penumbra::apps::addBenchCommand(app);
    penumbra::apps::addViewCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const penumbra::rhi::Error& e) {
        fmt::print(stderr, "penumbra: error: {}\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "penumbra: unexpected error: {}\n", e.what());
        return 2;
    }
    return 0;
}
