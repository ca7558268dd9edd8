#include "penumbra/shadows/StaticShadowBake.hpp"

#include "penumbra/imageio/ImageFiles.hpp"
#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace penumbra::shadows {
namespace {

using Json = nlohmann::json;

constexpr std::string_view kFormat = "penumbra static shadow bake";
constexpr int kVersion = 1;

void writeDepthFile(const std::filesystem::path& path, const BakedShadowMap& map)
{
    imageio::writeExrFile(path, {map.size, map.size * std::uint32_t(map.frusta.size()), {"Z"}, map.depth});
}

std::vector<float> readDepthFile(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height)
{
    imageio::FloatImage depth = imageio::readExr(path);
    if (depth.width != width || depth.height != height || depth.channels.size() != 1)
        throw rhi::Error(fmt::format("{}: {}x{} with {} channels, the manifest gives {}x{} with 1", path.string(),
                                     depth.width, depth.height, depth.channels.size(), width, height));
    return std::move(depth.values);
}

Json frustumJson(const ShadowFrustum& f)
{
    Json view = Json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            view.push_back(f.view[c][r]);
    return {{"view", view},
            {"projection", f.perspective ? "perspective" : "orthographic"},
            {"extent", f.extent},
            {"near", f.nearPlane},
            {"far", f.farPlane}};
}

// Reads the manifest's fields, naming the file and the JSON pointer of what is wrong.
class ManifestReader {
public:
    explicit ManifestReader(std::filesystem::path path) : path_(std::move(path)) {}

    [[noreturn]] void fail(const std::string& pointer, std::string_view what) const
    {
        throw rhi::Error(fmt::format("{}: {}: {}", path_.string(), pointer, what));
    }

    const Json& field(const Json& object, const std::string& pointer, const char* key) const
    {
        if (!object.is_object() || !object.contains(key))
            fail(pointer + "/" + key, "missing");
        return object.at(key);
    }

    std::string string(const Json& object, const std::string& pointer, const char* key) const
    {
        const Json& value = field(object, pointer, key);
        if (!value.is_string())
            fail(pointer + "/" + key, fmt::format("expected a string, got {}", value.dump()));
        return value.get<std::string>();
    }

    std::uint32_t count(const Json& object, const std::string& pointer, const char* key, std::uint32_t low,
                        std::uint32_t high) const
    {
        const Json& value = field(object, pointer, key);
        if (!value.is_number_unsigned() || value.get<std::uint64_t>() < low || value.get<std::uint64_t>() > high)
            fail(pointer + "/" + key, fmt::format("expected an integer in {}..{}, got {}", low, high, value.dump()));
        return value.get<std::uint32_t>();
    }

    float number(const Json& object, const std::string& pointer, const char* key) const
    {
        const Json& value = field(object, pointer, key);
        if (!value.is_number())
            fail(pointer + "/" + key, fmt::format("expected a number, got {}", value.dump()));
        return value.get<float>();
    }

    ShadowFrustum frustum(const Json& object, const std::string& pointer) const
    {
        ShadowFrustum f;
        const Json& view = field(object, pointer, "view");
        if (!view.is_array() || view.size() != 16)
            fail(pointer + "/view", "expected an array of 16 numbers (column-major)");
        for (std::size_t i = 0; i < 16; ++i) {
            if (!view[i].is_number())
                fail(fmt::format("{}/view/{}", pointer, i), "expected a number");
            f.view[int(i / 4)][int(i % 4)] = view[i].get<float>();
        }
        const std::string projection = string(object, pointer, "projection");
        if (projection != "perspective" && projection != "orthographic")
            fail(pointer + "/projection", "expected \"perspective\" or \"orthographic\"");
        f.perspective = projection == "perspective";
        f.extent = number(object, pointer, "extent");
        f.nearPlane = number(object, pointer, "near");
        f.farPlane = number(object, pointer, "far");
        return f;
    }

private:
    std::filesystem::path path_;
};

LightKind kindNamed(const ManifestReader& r, const std::string& pointer, const std::string& name)
{
    for (const LightKind kind : {LightKind::Directional, LightKind::Spot, LightKind::Point})
        if (bakedKindName(kind) == name)
            return kind;
    r.fail(pointer, fmt::format("expected \"directional\", \"spot\" or \"point\", got \"{}\"", name));
}

std::string depthFileName(const BakedShadowMap& map)
{
    return fmt::format("{}-{}.exr", bakedKindName(map.kind), map.lightIndex);
}

} // namespace

std::string_view bakedKindName(LightKind kind)
{
    switch (kind) {
    case LightKind::Spot:
        return "spot";
    case LightKind::Point:
        return "point";
    case LightKind::Directional:
        break;
    }
    return "directional";
}

BakedShadowMap bakeShadowMap(const StaticShadowMap& map, const ShadowAtlasLayout& atlas, const rhi::DepthImage& depth,
                             const rhi::Conventions& conventions)
{
    const std::uint32_t size = atlas.tileSize();
    BakedShadowMap baked{map.kind, map.lightIndex, {}, size, {}, 0, {}};
    baked.depth.reserve(std::size_t(size) * size * map.tiles.size());
    for (const StaticShadowTile& tile : map.tiles) {
        baked.frusta.push_back(tile.frustum);
        const glm::uvec2 offset = atlas.tileOffset(tile.tile);
        for (std::uint32_t y = 0; y < size; ++y)
            for (std::uint32_t x = 0; x < size; ++x)
                baked.depth.push_back(
                    linearShadowDepth(depth.at(offset.x + x, offset.y + y), tile.projection, conventions));
    }
    return baked;
}

void restoreShadowMap(const BakedShadowMap& baked, const StaticShadowMap& map, const ShadowAtlasLayout& atlas,
                      const rhi::Conventions& conventions, std::vector<float>& atlasDepth)
{
    const std::uint32_t size = atlas.tileSize();
    if (baked.size != size || baked.frusta.size() != map.tiles.size())
        throw rhi::Error(fmt::format("baked {} {}: {} tiles of {} texels, the settings plan {} of {}",
                                     bakedKindName(baked.kind), baked.lightIndex, baked.frusta.size(), baked.size,
                                     map.tiles.size(), size));
    std::size_t i = 0;
    for (const StaticShadowTile& tile : map.tiles) {
        const glm::uvec2 offset = atlas.tileOffset(tile.tile);
        for (std::uint32_t y = 0; y < size; ++y)
            for (std::uint32_t x = 0; x < size; ++x)
                atlasDepth[std::size_t(offset.y + y) * atlas.atlasSize() + offset.x + x] =
                    windowShadowDepth(baked.depth[i++], tile.projection, conventions);
    }
}

void writeStaticShadowBake(const std::filesystem::path& directory, const StaticShadowBake& bake)
{
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
        throw rhi::Error(fmt::format("{}: cannot create the bake's folder: {}", directory.string(), error.message()));
    nlohmann::ordered_json manifest{{"format", kFormat},
                                    {"version", kVersion},
                                    {"configuration", bake.configuration},
                                    {"objects", bake.objects},
                                    {"lights", Json::array()}};
    for (const BakedShadowMap& map : bake.maps) {
        writeDepthFile(directory / depthFileName(map), map);
        Json frusta = Json::array();
        for (const ShadowFrustum& f : map.frusta)
            frusta.push_back(frustumJson(f));
        manifest["lights"].push_back({{"name", map.lightName},
                                      {"kind", bakedKindName(map.kind)},
                                      {"index", map.lightIndex},
                                      {"file", depthFileName(map)},
                                      {"size", map.size},
                                      {"tiles", map.frusta.size()},
                                      {"hash", fmt::format("{:016x}", map.hash)},
                                      {"frusta", std::move(frusta)}});
    }
    rhi::writeFileAtomically(directory / "manifest.json", manifest.dump(2) + "\n");
}

StaticShadowBake readStaticShadowBake(const std::filesystem::path& directory)
{
    const std::filesystem::path path = directory / "manifest.json";
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw rhi::Error(fmt::format("{}: cannot open the bake's manifest: {}", path.string(), std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    Json root;
    try {
        root = Json::parse(text.str());
    } catch (const Json::exception& e) { // parse_error, and out_of_range for a number beyond double (1e382)
        throw rhi::Error(fmt::format("{}: not valid JSON (truncated?): {}", path.string(), e.what()));
    }
    const ManifestReader r(path);
    if (r.string(root, "", "format") != kFormat)
        r.fail("/format", fmt::format("expected \"{}\"", kFormat));
    if (r.count(root, "", "version", 0, 1000) != kVersion)
        r.fail("/version", fmt::format("this Penumbra reads version {}", kVersion));
    StaticShadowBake bake;
    bake.configuration = r.string(root, "", "configuration");
    const Json& objects = r.field(root, "", "objects");
    if (!objects.is_array())
        r.fail("/objects", "expected an array of names");
    for (std::size_t i = 0; i < objects.size(); ++i)
        bake.objects.push_back(r.string(Json{{"name", objects[i]}}, fmt::format("/objects/{}", i), "name"));
    const Json& lights = r.field(root, "", "lights");
    if (!lights.is_array())
        r.fail("/lights", "expected an array");
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::string pointer = fmt::format("/lights/{}", i);
        const Json& light = lights[i];
        BakedShadowMap map;
        map.lightName = r.string(light, pointer, "name");
        map.kind = kindNamed(r, pointer + "/kind", r.string(light, pointer, "kind"));
        map.lightIndex = r.count(light, pointer, "index", 0, 1u << 20);
        map.size = r.count(light, pointer, "size", 1, 8192);
        const std::uint32_t tiles = r.count(light, pointer, "tiles", 1, 6);
        const std::string hash = r.string(light, pointer, "hash");
        try {
            std::size_t used = 0;
            map.hash = std::stoull(hash, &used, 16);
            if (used != hash.size())
                throw std::invalid_argument(hash);
        } catch (const std::exception&) {
            r.fail(pointer + "/hash", fmt::format("expected 16 hexadecimal digits, got \"{}\"", hash));
        }
        const Json& frusta = r.field(light, pointer, "frusta");
        if (!frusta.is_array() || frusta.size() != tiles)
            r.fail(pointer + "/frusta", fmt::format("expected an array of {} frusta (tiles)", tiles));
        for (std::size_t t = 0; t < tiles; ++t)
            map.frusta.push_back(r.frustum(frusta[t], fmt::format("{}/frusta/{}", pointer, t)));
        const std::string file = r.string(light, pointer, "file");
        if (file.find('/') != std::string::npos || file.find("..") != std::string::npos)
            r.fail(pointer + "/file", fmt::format("expected a file name in the bake's folder, got \"{}\"", file));
        map.depth = readDepthFile(directory / file, map.size, map.size * tiles);
        bake.maps.push_back(std::move(map));
    }
    return bake;
}

} // namespace penumbra::shadows
