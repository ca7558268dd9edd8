#include "Commands.hpp"
#include "penumbra/parity/ImageFiles.hpp"
#include "ParityReport.hpp"
#include "SceneOptions.hpp"

#include "penumbra/backends/Registry.hpp"
#include "penumbra/rhi/Error.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <memory>

namespace penumbra::apps {
namespace {

constexpr std::uint32_t kPatternSize = 256;

struct ParityOptions {
    SceneOptions scene;
    std::string out = "out/parity";
};

void runParity(const ParityOptions& options)
{
    const LoadedScene loaded = loadScene(options.scene);
    render::FrameDesc frame = frameDesc(options.scene);
    frame.cascadeView = true;
    for (const std::string& note : loaded.notes)
        fmt::print("{}: {}\n", options.scene.scene, note);

    std::vector<rhi::Image> patterns;
    std::vector<ShadowPictures> pictures;
    for (const rhi::NamedConfiguration& c : penumbra::namedConfigurations()) {
        const std::string name(c.name);
        patterns.push_back(renderPattern(name, kPatternSize));
        pictures.push_back(renderShadowScene(name, loaded.scene, frame));
        printStats(pictures.back(), loaded.scene);
    }
    const ParityReport report = compareParity(pictures, patterns);
    const std::filesystem::path folder = options.out;
    for (std::size_t i = 0; i < pictures.size(); ++i) {
        parity::writePng(folder / pictures[i].configuration / "pattern.png", patterns[i]);
        writeShadowPictures(folder / pictures[i].configuration, pictures[i]);
    }
    writeParityReport(folder, report, pictures, options.scene.scene);

    const auto identical = std::count(report.patternIdentical.begin(), report.patternIdentical.end(), true);
    fmt::print("pattern: {}/{} configurations byte-identical\n", identical, patterns.size());
    fmt::print("{}\n", report.summary(pictures));
    fmt::print("report: {}, {}; pictures in {}/<configuration>/\n", (folder / "index.html").string(),
               (folder / "parity.json").string(), folder.string());
    if (!report.pass)
        throw rhi::Error(fmt::format("the configurations differ beyond the parity thresholds:\n{}",
                                     report.failures(pictures)));
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
    command->callback([options] { runParity(*options); });
}

} // namespace penumbra::apps
