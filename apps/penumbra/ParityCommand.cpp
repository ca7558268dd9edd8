#include "BackendOptions.hpp"
#include "Commands.hpp"
#include "Interrupt.hpp"
#include "SceneOptions.hpp"
#include "TestPattern.hpp"

#include "penumbra/parity/Harness.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "penumbra/parity/Report.hpp"
#include "penumbra/rhi/Error.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <memory>

namespace penumbra::apps {
namespace {

constexpr std::uint32_t kPatternSize = 256;

struct ParityOptions {
    SceneOptions scene;
    std::string out = "out/parity";
    bool validate = false;
};

// What is left between the backends (a few triangle-edge texels and shadow-edge pixels, see README
// "Parity across backends" and tests/shadows_gpu/ShadowParityTest.cpp) stays far inside these coarse
// limits, at any size and scene; the test pattern must be byte-identical. The atlases' raw depth is
// reported, not judged: at some frame sizes a few triangle-edge texels still differ.
parity::Options parityOptions()
{
    parity::Options options;
    options.thresholds["pattern"] = parity::identical();
    options.thresholds["lit"] = {.maxDifference = parity::kAnyDifference, .minPsnr = 50.0};
    // render::lightDepthFraction units: fractions of a tile's depth range. Perspective tiles clip casters at
    // near and far planes whose clip-space equations differ per convention, so a few texels there may be
    // drawn in one atlas only; the orthographic directional cascades pancake instead and keep coverage exact
    // (at their far plane, depths within its rounding read as the far plane in every convention).
    options.thresholds["atlas"] = {.maxDifference = 2e-4, .bitExactWhereConventionsAgree = false};
    for (const char* perspective : {"other-atlas", "cube-atlas"})
        options.thresholds[perspective] = {.maxDifference = 2e-4,
                                           .maxCoverageMismatches = 16,
                                           .bitExactWhereConventionsAgree = false};
    return options;
}

void runParity(const ParityOptions& options)
{
    const LoadedScene loaded = loadScene(options.scene);
    render::FrameDesc frame = frameDesc(options.scene, loaded.scene);
    frame.cascadeView = true;
    for (const std::string& note : loaded.notes)
        fmt::print("{}: {}\n", options.scene.scene, note);

    std::map<std::string, rhi::Image> cascades; // written beside the report's pictures, not compared
    const parity::Result result = parity::run(
        [&](rhi::Device& device, const rhi::NamedConfiguration& configuration) {
            stopIfInterrupted();
            pattern::PatternRenderer pattern(device, {.width = kPatternSize, .height = kPatternSize});
            pattern.render(pattern::testPattern());
            const ShadowPictures pictures = renderShadowScene(device, configuration.name, loaded.scene, frame);
            printStats(pictures, loaded.scene);
            cascades[configuration.name] = pictures.cascades;
            std::vector<parity::Picture> compared = parityPictures(pictures);
            compared.insert(compared.begin(), parity::colorPicture("pattern", pattern.color()));
            return compared;
        },
        [&] {
            parity::Options o = parityOptions();
            o.validate = options.validate;
            return o;
        }());
    // The harness reports a render function's exception as that configuration's failure: an interruption is
    // read again here, so that no report is written.
    stopIfInterrupted();
    const std::filesystem::path folder = options.out;
    parity::writeReport(folder, result, options.scene.scene);
    for (const auto& [configuration, picture] : cascades)
        parity::writePng(folder / configuration / "cascades.png", picture);

    fmt::print("{}\n", result.summary());
    fmt::print("report: {}, {}; pictures in {}/<configuration>/\n", (folder / "index.html").string(),
               (folder / "parity.json").string(), folder.string());
    if (!result.pass()) {
        std::string failures;
        for (const std::string& line : result.failures())
            failures += line + "\n";
        throw rhi::Error(fmt::format("the configurations differ beyond the parity thresholds:\n{}", failures));
    }
}

} // namespace

void addParityCommand(CLI::App& app)
{
    auto options = std::make_shared<ParityOptions>();
    CLI::App* command = app.add_subcommand(
        "parity", "Render the test pattern and a scene through every configuration, compare every pair and write a "
                  "report: parity.json, index.html with difference heat maps, <configuration>/{pattern,lit,atlas,"
                  "cascades}.png and atlas.exr; exits non-zero when a pair misses the thresholds");
    addSceneOptions(*command, options->scene);
    command->add_option("-o,--out", options->out, "Report folder")->capture_default_str();
    addValidateFlag(*command, options->validate);
    command->callback([options] {
        installInterruptHandler();
        runParity(*options);
    });
}

} // namespace penumbra::apps
