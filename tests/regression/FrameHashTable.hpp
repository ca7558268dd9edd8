#pragma once

#include "penumbra/rhi/Image.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

// The render regression table: per configuration, the hashes of every output a set of frames wrote (lit image,
// atlases, debug views), as the driver that made them drew them. A frame is named "<scene>/<variant>", an output by
// what it is ("lit", "atlas", "localAtlas", ...).
namespace penumbra::testing {

// 64-bit FNV-1a (Fowler, Noll, Vo; the IETF draft "The FNV Non-Cryptographic Hash Algorithm", section 2) of the
// bytes: one changed byte changes it.
std::uint64_t fnv1a(const void* bytes, std::size_t size);
std::uint64_t hashOf(const rhi::Image& image);
std::uint64_t hashOf(const rhi::DepthImage& depth);

using FrameHashes = std::map<std::string, std::uint64_t>; // output -> hash
using FrameTable = std::map<std::string, FrameHashes>; // "<scene>/<variant>" -> its outputs

struct FrameHashFile {
    std::string configuration;
    std::string driver; // Capabilities::api and ::device, as the table was made with
    FrameTable frames;
};

// Throws rhi::Error naming the file and the field that is missing or of the wrong type.
FrameHashFile readFrameHashes(const std::filesystem::path& path);
// Written atomically, the frames and outputs in name order with 16 hex digits per hash, so that a regenerated
// table differs from the committed one by the lines whose pictures changed.
void writeFrameHashes(const std::filesystem::path& path, const FrameHashFile& file);

// One line per difference: a frame or output the table lacks or has beyond `rendered`, or whose hash differs
// ("town/static-dynamic: staticLocalAtlas is 0123... but the table has 4567...").
std::vector<std::string> frameDifferences(const FrameTable& table, const FrameTable& rendered);

} // namespace penumbra::testing
