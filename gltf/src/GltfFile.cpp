#include "GltfFile.hpp"

#include "GltfImages.hpp"
#include "GltfLayout.hpp"
#include "GltfLimits.hpp"
#include "GltfSchema.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>

namespace penumbra::gltf {
namespace {

// glTF 2.0, section 4.4.3 and 4.4.3.2: the GLB header's magic "glTF" and the chunk types.
constexpr std::uint32_t kGlbMagic = 0x46546C67;
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;
constexpr std::uint32_t kGlbHeaderBytes = 12, kChunkHeaderBytes = 8;

std::uint32_t readU32(std::span<const std::uint8_t> bytes, std::size_t at)
{
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
}

bool isGlb(std::span<const std::uint8_t> bytes) { return bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic; }

// The JSON chunk of a GLB file, after checking the header and the chunk layout.
std::string_view glbJson(const std::string& name, std::span<const std::uint8_t> bytes)
{
    const auto fail = [&](const std::string& what) { throw GltfError(fmt::format("{}: GLB: {}", name, what)); };
    if (bytes.size() < kGlbHeaderBytes + kChunkHeaderBytes)
        fail(fmt::format("{} bytes, too few for the header and a chunk", bytes.size()));
    if (readU32(bytes, 4) != 2)
        fail(fmt::format("version {} is not 2", readU32(bytes, 4)));
    if (readU32(bytes, 8) != bytes.size())
        fail(fmt::format("the header says {} bytes, the file has {}", readU32(bytes, 8), bytes.size()));
    std::size_t at = kGlbHeaderBytes;
    std::string_view json;
    for (int chunk = 0; at < bytes.size(); ++chunk) {
        if (bytes.size() - at < kChunkHeaderBytes)
            fail(fmt::format("chunk {} at byte {} is cut short", chunk, at));
        const std::uint32_t length = readU32(bytes, at), type = readU32(bytes, at + 4);
        if (length % 4 != 0)
            fail(fmt::format("chunk {} has {} bytes, not a multiple of 4", chunk, length));
        if (length > bytes.size() - at - kChunkHeaderBytes)
            fail(fmt::format("chunk {} of {} bytes runs past the end of the file", chunk, length));
        if (chunk == 0) {
            if (type != kJsonChunk)
                fail("the first chunk is not JSON");
            json = {reinterpret_cast<const char*>(bytes.data() + at + kChunkHeaderBytes), length};
        }
        at += kChunkHeaderBytes + length;
    }
    return json;
}

// Containers nested deeper than kMaxJsonDepth (the whole text's object or array is level 1), found before parsing
// so that the parser's recursion stays bounded. A scan of its own: nlohmann::json 3.11.2's parse with a callback
// searches the enclosing container at the end of every object in it (json_sax_dom_callback_parser::end_object;
// nlohmann/json pull request 5457 removes that), which made 100 000 nodes take seconds.
void checkJsonDepth(const std::string& name, std::string_view text)
{
    int depth = 0;
    bool inString = false, escaped = false;
    for (const char c : text) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxJsonDepth)
                throw GltfError(fmt::format("{}: cannot read: JSON nested deeper than {} levels", name, kMaxJsonDepth));
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

Json parseJson(const std::string& name, std::string_view text)
{
    checkJsonDepth(name, text);
    try {
        return Json::parse(text.begin(), text.end());
    } catch (const Json::exception& error) {
        throw GltfError(fmt::format("{}: cannot read: {}", name, error.what()));
    }
}

void checkObjectCounts(const JsonFile& file)
{
    if (!file.root.is_object())
        file.fail("", fmt::format("expected an object, got {}", shortDump(file.root)));
    for (const auto& [key, value] : file.root.items())
        if (value.is_array() && value.size() > kMaxObjects)
            file.fail("/" + key, fmt::format("{} elements, over the limit of {}", value.size(), kMaxObjects));
}

std::string trimmed(std::string text)
{
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.pop_back();
    return text;
}

} // namespace

Document readDocument(const std::string& name, std::span<const std::uint8_t> bytes, const std::filesystem::path& folder,
                      std::vector<std::string>& notes)
{
    const bool glb = isGlb(bytes);
    const Json root =
        parseJson(name, glb ? glbJson(name, bytes)
                            : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    Deviations deviations;
    const JsonFile file{name, root, deviations};
    checkObjectCounts(file);
    checkSchema(file);

    tinygltf::TinyGLTF loader;
    std::string imageFailure;
    loader.SetImageLoader(loadImageData, &imageFailure);
    tinygltf::Model model;
    std::string error, warning;
    const std::string base = folder.string();
    const bool ok =
        glb ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), base)
            : loader.LoadASCIIFromString(&model, &error, &warning, reinterpret_cast<const char*>(bytes.data()),
                                         unsigned(bytes.size()), base);
    if (!imageFailure.empty())
        throw GltfError(fmt::format("{}: {}", name, imageFailure));
    if (!ok)
        throw GltfError(fmt::format("{}: cannot read: {}", name, trimmed(error.empty() ? warning : error)));
    checkLayout(file, model);
    std::size_t start = 0;
    while (start < warning.size()) {
        const std::size_t end = std::min(warning.find('\n', start), warning.size());
        if (end > start)
            notes.push_back(warning.substr(start, end - start));
        start = end + 1;
    }
    return Document(name, std::move(model), std::move(deviations));
}

Document readDocument(const std::filesystem::path& path, std::vector<std::string>& notes)
{
    const std::string name = path.string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw GltfError(fmt::format("{}: no such file", name));
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error)
        throw GltfError(fmt::format("{}: cannot read: {}", name, error.message()));
    if (size > kMaxFileBytes)
        throw GltfError(fmt::format("{}: {} bytes, over the limit of {}", name, size, kMaxFileBytes));
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes(size);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw GltfError(fmt::format("{}: cannot read the file", name));
    return readDocument(name, bytes, path.parent_path(), notes);
}

} // namespace penumbra::gltf
