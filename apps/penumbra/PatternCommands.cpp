#include "Commands.hpp"
#include "ImageFiles.hpp"
#include "TestPattern.hpp"

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
};

rhi::Image renderPattern(const std::string& configuration, std::uint32_t size)
{
    auto device = createDevice(configuration);
    pattern::PatternRenderer renderer(*device, {.width = size, .height = size});
    renderer.render(pattern::testPattern());
    rhi::Image image = renderer.color();
    if (const auto messages = device->debugMessages(); !messages.empty())
        throw rhi::Error(fmt::format("{}: {} debug message(s), first: {}", configuration, messages.size(), messages[0]));
    return image;
}

} // namespace

CLI::Validator configurationValidator()
{
    return CLI::Validator(
        [](std::string& name) {
            try {
                rhi::parseConfiguration(name);
            } catch (const rhi::Error& e) {
                return std::string(e.what());
            }
            return std::string();
        },
        "CONFIGURATION");
}

void addRenderCommand(CLI::App& app)
{
    auto options = std::make_shared<PatternOptions>();
    CLI::App* render = app.add_subcommand("render", "Render the test pattern through one configuration into a PNG");
    render->add_option("-c,--configuration", options->configuration, "vulkan, vulkan-reversed, opengl, ...")
        ->check(configurationValidator());
    render->add_option("-o,--out", options->out, "PNG file to write");
    render->add_option("-s,--size", options->size, "Width and height in pixels")->check(CLI::Range(1u, 8192u));
    render->callback([options] {
        writePng(options->out, renderPattern(options->configuration, options->size));
        fmt::print("{}: {}\n", options->configuration, options->out);
    });
}

void addDemoCommand(CLI::App& app)
{
    auto out = std::make_shared<std::string>("out/demo");
    CLI::App* demo = app.add_subcommand("demo", "Render the test pattern through every configuration and compare");
    demo->add_option("-o,--out", *out, "Folder that receives <configuration>/pattern.png");
    demo->callback([out] {
        std::vector<std::pair<std::string, rhi::Image>> images;
        for (const rhi::NamedConfiguration& c : rhi::namedConfigurations()) {
            const std::string name(c.name);
            images.emplace_back(name, renderPattern(name, 256));
            const std::filesystem::path path = std::filesystem::path(*out) / name / "pattern.png";
            writePng(path, images.back().second);
            fmt::print("{:<24} {}\n", name, path.string());
        }
        bool identical = true;
        for (const auto& [name, image] : images)
            if (image.bytes != images.front().second.bytes) {
                identical = false;
                fmt::print("parity: {} differs from {}\n", name, images.front().first);
            }
        fmt::print("parity: {} configurations, {}\n", images.size(),
                   identical ? "all byte-identical" : "NOT identical");
        if (!identical)
            throw rhi::Error("the configurations did not render identical pictures");
    });
}

void addConfigurationsCommand(CLI::App& app)
{
    app.add_subcommand("configurations", "List the configuration names")->callback([] {
        for (const rhi::NamedConfiguration& c : rhi::namedConfigurations())
            fmt::print("{}\n", c.name);
    });
}

} // namespace penumbra::apps
