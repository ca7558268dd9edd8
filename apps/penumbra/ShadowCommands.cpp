#include "Commands.hpp"
#include "ImageDifference.hpp"
#include "ImageFiles.hpp"
#include "ShadowScene.hpp"

#include "penumbra/rhi/Configuration.hpp"
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>

namespace penumbra::apps {
namespace {

struct RenderOptions {
    std::string configuration = "vulkan";
    std::string out = "out/render";
    std::string settings;
    std::string scene = "test";
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
};

render::FrameDesc frameDesc(const RenderOptions& options)
{
    render::FrameDesc frame;
    frame.width = options.width;
    frame.height = options.height;
    if (!options.settings.empty())
        frame.shadows = shadows::loadShadowSettings(options.settings);
    return frame;
}

void printStats(const ShadowPictures& pictures)
{
    const render::FrameStats& s = pictures.stats;
    fmt::print("{:<24} caster draws {} ({} without culling bias)", pictures.configuration, s.casterDraws,
               s.casterDrawsWithoutCullingBias);
    if (s.atlasPassMs && s.litPassMs)
        fmt::print(", atlas pass {:.2f} ms, lit pass {:.2f} ms", *s.atlasPassMs, *s.litPassMs);
    fmt::print("\n");
    for (const std::string& note : pictures.notes)
        fmt::print("  note: {}\n", note);
}

// What is left between the backends (a few triangle-edge texels and shadow-edge pixels, see README
// "Parity across backends" and tests/shadows_gpu/ShadowParityTest.cpp) stays far inside these coarse
// limits; the demo fails only beyond them.
constexpr float kMaxLightDepthDifference = 2e-4f;
constexpr double kMinLitPsnr = 50.0;

// Atlases compared raw where depth range and reversed-Z agree, in linear light depth everywhere;
// lit images against the first configuration. Returns whether the figures are within the limits.
bool reportParity(const std::vector<ShadowPictures>& all)
{
    const ShadowPictures& reference = all.front();
    int litMax = 0;
    std::size_t litDiffering = 0;
    double litPsnr = std::numeric_limits<double>::infinity();
    float lightDepthMax = 0.0f;
    std::size_t rawPairs = 0, rawIdentical = 0;
    for (const ShadowPictures& p : all) {
        const ImageDifference lit = compareImages(reference.lit, p.lit);
        litMax = std::max(litMax, lit.maxAbs);
        litDiffering = std::max(litDiffering, lit.differingPixels);
        litPsnr = std::min(litPsnr, lit.psnr);
        lightDepthMax =
            std::max(lightDepthMax, compareFloats(reference.atlasLightDepth, p.atlasLightDepth).maxAbs);
        for (const ShadowPictures& q : all) {
            if (&q <= &p || p.depthRange != q.depthRange || p.reversedZ != q.reversedZ)
                continue;
            ++rawPairs;
            rawIdentical += compareFloats(p.atlasDepth.depth, q.atlasDepth.depth).differingPixels == 0;
        }
    }
    fmt::print("parity: {} configurations; lit vs {}: max diff {}, PSNR {:.1f} dB, at most {} of {} pixels differ; "
               "atlas bit-identical in {}/{} pairs of equal conventions; light-depth max diff {:.3g}\n",
               all.size(), reference.configuration, litMax, litPsnr, litDiffering,
               std::size_t(reference.lit.width) * reference.lit.height, rawIdentical, rawPairs, lightDepthMax);
    return litPsnr >= kMinLitPsnr && lightDepthMax <= kMaxLightDepthDifference;
}

} // namespace

void addRenderCommand(CLI::App& app)
{
    auto options = std::make_shared<RenderOptions>();
    CLI::App* render = app.add_subcommand(
        "render", "Render the shadow test scene through one configuration: lit.png, atlas.png, atlas.exr, cascades.png");
    render->add_option("-c,--configuration", options->configuration, "vulkan, vulkan-reversed, opengl, ...")
        ->check(configurationValidator());
    render->add_option("-o,--out", options->out, "Folder that receives the pictures");
    render->add_option("--settings", options->settings, "Shadow settings JSON file")->check(CLI::ExistingFile);
    render->add_option("--scene", options->scene, "test (four lights), key-light (the first light only), mixed (key, spot and point lights), room (point lights in a room)")
        ->check(CLI::IsMember({"test", "key-light", "mixed", "room"}));
    render->add_option("--width", options->width, "Width in pixels")->check(CLI::Range(1u, 8192u));
    render->add_option("--height", options->height, "Height in pixels")->check(CLI::Range(1u, 8192u));
    render->callback([options] {
        const ShadowPictures pictures = renderShadowScene(options->configuration, namedScene(options->scene), frameDesc(*options));
        writeShadowPictures(options->out, pictures);
        printStats(pictures);
        fmt::print("{}: {}/{{lit,atlas,cascades}}.png, atlas.exr\n", options->configuration, options->out);
    });
}

void addDemoCommand(CLI::App& app)
{
    auto options = std::make_shared<RenderOptions>();
    options->out = "out/demo";
    CLI::App* demo = app.add_subcommand(
        "demo", "Render the test pattern and the shadow test scene through every configuration and compare them");
    demo->add_option("-o,--out", options->out, "Folder that receives <configuration>/{pattern,lit,atlas,cascades}.png");
    demo->add_option("--settings", options->settings, "Shadow settings JSON file")->check(CLI::ExistingFile);
    demo->callback([options] {
        const render::FrameDesc frame = frameDesc(*options);
        const scene::Scene scene = namedScene(options->scene);
        std::vector<rhi::Image> patterns;
        std::vector<ShadowPictures> shadows;
        for (const rhi::NamedConfiguration& c : rhi::namedConfigurations()) {
            const std::string name(c.name);
            const std::filesystem::path folder = std::filesystem::path(options->out) / name;
            patterns.push_back(renderPattern(name, 256));
            writePng(folder / "pattern.png", patterns.back());
            shadows.push_back(renderShadowScene(name, scene, frame));
            writeShadowPictures(folder, shadows.back());
            printStats(shadows.back());
        }
        std::size_t patternsIdentical = 0;
        for (const rhi::Image& pattern : patterns)
            patternsIdentical += pattern.bytes == patterns.front().bytes;
        fmt::print("pattern: {}/{} configurations byte-identical\n", patternsIdentical, patterns.size());
        const bool shadowsAgree = reportParity(shadows);
        fmt::print("pictures in {}/<configuration>/\n", options->out);
        if (patternsIdentical != patterns.size())
            throw rhi::Error("the configurations did not render identical test patterns");
        if (!shadowsAgree)
            throw rhi::Error(fmt::format("the shadow pictures differ beyond the parity limits (lit PSNR >= {} dB, "
                                         "light depth within {})",
                                         kMinLitPsnr, kMaxLightDepthDifference));
    });
}

} // namespace penumbra::apps
