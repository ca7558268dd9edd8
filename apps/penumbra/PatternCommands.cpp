#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "TestPattern.hpp"
#include "ToolDevices.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/rhi/Error.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>

namespace penumbra::apps {
namespace {

struct PatternOptions {
    std::string configuration = "vulkan";
    std::string out = "pattern.png";
    std::uint32_t size = 256;
    bool validate = false;
};

} // namespace

rhi::Image renderPattern(const std::string& configuration, std::uint32_t size, bool validate)
{
    auto device = createDevice(toolDeviceDesc(configuration, validate));
    pattern::PatternRenderer renderer(*device, {.width = size, .height = size});
    renderer.render(pattern::testPattern());
    rhi::Image image = renderer.color();
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(
            fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return image;
}

void addPatternCommand(CLI::App& app)
{
    auto options = std::make_shared<PatternOptions>();
    CLI::App* render =
        app.add_subcommand("pattern", "Render the RHI test pattern through one configuration into a PNG");
    render->add_option("-c,--configuration", options->configuration, "vulkan, vulkan-reversed, opengl, ...")
        ->check(configurationValidator());
    render->add_option("-o,--out", options->out, "PNG file to write");
    render->add_option("-s,--size", options->size, "Width and height in pixels")->check(CLI::Range(1u, 8192u));
    addValidateFlag(*render, options->validate);
    render->callback([options] {
        parity::writePng(options->out, renderPattern(options->configuration, options->size, options->validate));
        fmt::print("{}: {}\n", options->configuration, options->out);
    });
}

void addConfigurationsCommand(CLI::App& app)
{
    auto devices = std::make_shared<bool>(false);
    CLI::App* command = app.add_subcommand("configurations", "List the configuration names");
    command->add_flag("--devices", *devices,
                      "Also start each configuration's device and print its API and device, tab-separated (or why the "
                      "driver refused it), as scripts/device-check.sh reports them");
    command->callback([devices] {
        for (const rhi::NamedConfiguration& c : penumbra::namedConfigurations()) {
            if (!*devices) {
                fmt::print("{}\n", c.name);
                continue;
            }
            try {
                const std::unique_ptr<rhi::Device> device = createDevice(toolDeviceDesc(c.name, false));
                fmt::print("{}\t{}\t{}\n", c.name, device->capabilities().api, device->capabilities().device);
            } catch (const rhi::Error& e) {
                fmt::print("{}\tunsupported\t{}\n", c.name, e.what());
            }
        }
    });
}

} // namespace penumbra::apps
