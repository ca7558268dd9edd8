#include "penumbra/parity/Harness.hpp"

#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/backends/Registry.hpp"
#include "penumbra/rhi/Error.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <set>

namespace penumbra::parity {
namespace {

std::vector<rhi::NamedConfiguration> chosenConfigurations(const std::vector<std::string>& names)
{
    const std::span<const rhi::NamedConfiguration> all = namedConfigurations();
    if (names.empty())
        return {all.begin(), all.end()};
    std::vector<rhi::NamedConfiguration> chosen;
    std::set<std::string> seen;
    for (const std::string& name : names) {
        if (!seen.insert(name).second)
            throw rhi::Error(fmt::format("parity: configuration '{}' is named twice", name));
        chosen.push_back({name, parseConfiguration(name)}); // throws for an unknown name, listing the known
    }
    return chosen;
}

// What a configuration's device said during the run, as one message; empty when it said nothing.
std::string debugMessages(const rhi::Device& device)
{
    const std::vector<std::string> messages = device.debugMessages();
    std::string text;
    for (const std::string& m : messages)
        text += "\n  " + m;
    return messages.empty() ? std::string()
                            : fmt::format("{} validation or debug message(s):{}", messages.size(), text);
}

void checkPictures(const std::vector<Picture>& pictures)
{
    if (pictures.empty())
        throw rhi::Error("the render function returned no pictures");
    std::set<std::string> names;
    for (const Picture& p : pictures) {
        validate(p);
        if (!names.insert(p.name).second)
            throw rhi::Error(fmt::format("the render function returned two pictures named '{}'", p.name));
    }
}

ConfigurationRun renderOne(const RenderFunction& render, const rhi::NamedConfiguration& configuration, bool validate)
{
    ConfigurationRun run{configuration, ConfigurationRun::Status::Rendered, {}, {}};
    run.configuration.desc.validation = validate;
    run.configuration.desc.throwOnDebugMessage = false; // every message is collected and reported after the run
    std::unique_ptr<rhi::Device> device;
    try {
        device = createDevice(run.configuration.desc);
    } catch (const rhi::UnsupportedError& e) {
        return {configuration, ConfigurationRun::Status::Unsupported, e.what(), {}};
    } catch (const std::exception& e) {
        return {configuration,
                ConfigurationRun::Status::Failed,
                fmt::format("cannot create the device: {}", e.what()),
                {}};
    }
    try {
        run.pictures = render(*device, run.configuration);
        checkPictures(run.pictures);
    } catch (const std::exception& e) {
        run.status = ConfigurationRun::Status::Failed;
        run.message = fmt::format("the render function threw: {}", e.what());
        run.pictures.clear();
    }
    if (const std::string messages = debugMessages(*device); !messages.empty()) {
        run.status = ConfigurationRun::Status::Failed;
        run.message += (run.message.empty() ? "" : "; ") + messages;
    }
    return run;
}

bool rendered(const ConfigurationRun& run) { return run.status == ConfigurationRun::Status::Rendered; }

PairResult comparePair(const std::vector<ConfigurationRun>& runs, std::size_t i, std::size_t j, const Options& options)
{
    const ConfigurationRun& a = runs[i];
    const ConfigurationRun& b = runs[j];
    PairResult pair{i, j, {}};
    const auto thresholdsFor = [&](const std::string& name) {
        const auto found = options.thresholds.find(name);
        const Thresholds perPicture = found == options.thresholds.end() ? Thresholds{} : found->second;
        return options.pairThresholds ? options.pairThresholds(name, a, b, perPicture) : perPicture;
    };
    const auto findIn = [](const ConfigurationRun& run, const std::string& name) -> const Picture* {
        for (const Picture& p : run.pictures)
            if (p.name == name)
                return &p;
        return nullptr;
    };
    for (const Picture& pa : a.pictures) {
        if (const Picture* pb = findIn(b, pa.name)) {
            pair.pictures.push_back(comparePictures(pa, a.conventions(), *pb, b.conventions(), thresholdsFor(pa.name)));
        } else {
            PictureComparison missing{pa.name, pa.kind, thresholdsFor(pa.name), {}, {}};
            missing.failures.push_back(fmt::format("{} rendered it, {} did not", a.name(), b.name()));
            pair.pictures.push_back(std::move(missing));
        }
    }
    for (const Picture& pb : b.pictures)
        if (!findIn(a, pb.name)) {
            PictureComparison missing{pb.name, pb.kind, thresholdsFor(pb.name), {}, {}};
            missing.failures.push_back(fmt::format("{} rendered it, {} did not", b.name(), a.name()));
            pair.pictures.push_back(std::move(missing));
        }
    return pair;
}

} // namespace

const Picture& ConfigurationRun::picture(std::string_view name) const
{
    std::string names;
    for (const Picture& p : pictures) {
        if (p.name == name)
            return p;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    throw rhi::Error(
        fmt::format("{}: no picture named '{}'; it has: {}", configuration.name, name, names.empty() ? "none" : names));
}

std::vector<ConfigurationRun> renderConfigurations(const RenderFunction& render,
                                                   const std::vector<std::string>& configurations, bool validate)
{
    std::vector<ConfigurationRun> runs;
    for (const rhi::NamedConfiguration& c : chosenConfigurations(configurations))
        runs.push_back(renderOne(render, c, validate));
    return runs;
}

Result compare(std::vector<ConfigurationRun> runs, const Options& options)
{
    Result result{std::move(runs), {}};
    const std::vector<ConfigurationRun>& all = result.configurations;
    if (options.pairing == Pairing::AgainstReference) {
        std::size_t reference = 0;
        if (!options.reference.empty()) {
            reference = all.size();
            for (std::size_t i = 0; i < all.size(); ++i)
                if (all[i].name() == options.reference)
                    reference = i;
            if (reference == all.size())
                throw rhi::Error(
                    fmt::format("parity: the reference configuration '{}' is not among those run", options.reference));
        }
        if (reference < all.size() && rendered(all[reference]))
            for (std::size_t i = 0; i < all.size(); ++i)
                if (i != reference && rendered(all[i]))
                    result.pairs.push_back(comparePair(all, reference, i, options));
        return result;
    }
    for (std::size_t i = 0; i < all.size(); ++i)
        for (std::size_t j = i + 1; j < all.size(); ++j)
            if (rendered(all[i]) && rendered(all[j]))
                result.pairs.push_back(comparePair(all, i, j, options));
    return result;
}

Result run(const RenderFunction& render, const Options& options)
{
    // A reference that will not be run is refused before anything renders.
    if (options.pairing == Pairing::AgainstReference && !options.reference.empty()) {
        parseConfiguration(options.reference);
        if (!options.configurations.empty() && std::find(options.configurations.begin(), options.configurations.end(),
                                                         options.reference) == options.configurations.end())
            throw rhi::Error(
                fmt::format("parity: the reference configuration '{}' is not among those to run", options.reference));
    }
    return compare(renderConfigurations(render, options.configurations, options.validate), options);
}

} // namespace penumbra::parity
