#include "GltfFile.hpp"

#include "GltfHugePages.hpp"
#include "GltfImages.hpp"
#include "GltfLayout.hpp"
#include "GltfLimits.hpp"
#include "GltfSchema.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <string_view>

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

// The last kExcerptBytes of text before `end`, each string literal longer than kLongString cut to its first
// kLongString characters and its length, so that an error in or after a data URI does not echo its payload.
constexpr std::size_t kExcerptBytes = 160, kLongString = 40;

std::string excerptBefore(std::string_view text, std::size_t end)
{
    std::string condensed;
    std::size_t stringStart = 0;
    bool inString = false, escaped = false;
    const auto closeString = [&](std::size_t at) {
        const std::size_t length = at - stringStart;
        if (length > kLongString)
            condensed += fmt::format("... ({} bytes)", length);
    };
    for (std::size_t i = 0; i < end && i < text.size(); ++i) {
        const char c = text[i];
        bool shown = true;
        if (!inString) {
            inString = c == '"';
            stringStart = i + 1;
        } else if (escaped) {
            escaped = false;
        } else if (c == '\\') {
            escaped = true;
        } else if (c == '"') {
            closeString(i);
            inString = false;
        }
        if (inString && i >= stringStart)
            shown = i - stringStart < kLongString;
        if (shown)
            condensed += std::isprint(static_cast<unsigned char>(c)) ? c : ' ';
        if (condensed.size() > 2 * kExcerptBytes)
            condensed.erase(0, condensed.size() - kExcerptBytes);
    }
    if (inString)
        closeString(std::min(end, text.size()));
    return condensed.size() > kExcerptBytes ? "..." + condensed.substr(condensed.size() - kExcerptBytes) : condensed;
}

// nlohmann::json's parse error "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error while
// parsing value - invalid literal; last read: '<the token>'" without its id, position and token, which may be a
// whole data URI: the caller names the position and an excerpt.
std::string parseErrorReason(const std::string& what)
{
    const std::size_t colon = what.find(": ");
    std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
    if (const std::size_t lastRead = reason.find("; last read:"); lastRead != std::string::npos)
        reason.resize(lastRead);
    return reason;
}

Json parseJson(const std::string& name, std::string_view text)
{
    checkJsonDepth(name, text);
    try {
        return Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error& error) {
        // error.byte counts from 1, at the character that could not be read (past the end for a truncated file).
        const std::size_t at = std::min<std::size_t>(error.byte > 0 ? error.byte - 1 : 0, text.size());
        const std::string_view before = text.substr(0, at);
        const std::size_t line = 1 + std::size_t(std::count(before.begin(), before.end(), '\n'));
        const std::size_t lineStart = before.rfind('\n');
        const std::size_t column = at - (lineStart == std::string_view::npos ? 0 : lineStart + 1) + 1;
        throw GltfError(fmt::format("{}: cannot read: JSON {} at byte {} of {} (line {}, column {}), after: {}", name,
                                    parseErrorReason(error.what()), at, text.size(), line, column,
                                    excerptBefore(text, at)));
    } catch (const Json::exception& error) {
        throw GltfError(fmt::format("{}: cannot read: {}", name, parseErrorReason(error.what())));
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

// A URI's %XX escapes decoded (RFC 3986, section 2.1), as tinygltf decodes an image's uri before opening it.
std::string percentDecoded(const std::string& uri)
{
    std::string decoded;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            decoded += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    return decoded;
}

// The images whose external file tinygltf could not read (it leaves them empty, warning), by index, with the path
// it tried.
std::map<int, std::filesystem::path> missingImages(const tinygltf::Model& model, const std::filesystem::path& folder)
{
    std::map<int, std::filesystem::path> missing;
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        const tinygltf::Image& image = model.images[i];
        if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0 && image.image.empty())
            missing.emplace(int(i), folder / percentDecoded(image.uri));
    }
    return missing;
}

// tinygltf's warnings about an image it could not read: the loader names the image and the path tried instead.
bool isMissingImageWarning(std::string_view line)
{
    return line.rfind("File not found : ", 0) == 0 || line.rfind("Failed to load external 'uri' for image[", 0) == 0;
}

std::string trimmed(std::string text)
{
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.pop_back();
    return text;
}

} // namespace

Document readDocument(const std::string& name, std::span<const std::uint8_t> bytes, const std::filesystem::path& folder,
                      std::vector<std::string>& notes, MissingTextures missingTextures,
                      const std::function<void(std::size_t, std::size_t)>& progress)
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
    loader.SetImageLoader(stashImageData, &imageFailure);
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readWholeFileHugePages,
                           &tinygltf::WriteWholeFile, nullptr});
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
    if (const std::string failure = decodeStashedImages(model, progress); !failure.empty())
        throw GltfError(fmt::format("{}: {}", name, failure));
    std::map<int, std::filesystem::path> missing = missingImages(model, folder);
    std::size_t start = 0;
    while (start < warning.size()) {
        const std::size_t end = std::min(warning.find('\n', start), warning.size());
        const std::string line = warning.substr(start, end - start);
        if (!line.empty() && !(isMissingImageWarning(line) && !missing.empty()))
            notes.push_back(line);
        start = end + 1;
    }
    return Document(name, std::move(model), std::move(deviations), std::move(missing), missingTextures);
}

Document readDocument(const std::filesystem::path& path, std::vector<std::string>& notes,
                      MissingTextures missingTextures, const std::function<void(std::size_t, std::size_t)>& progress)
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
    std::vector<std::uint8_t> bytes = hugePageBytes(std::size_t(size)); // a .glb holds its buffers and pictures
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw GltfError(fmt::format("{}: cannot read the file", name));
    return readDocument(name, bytes, path.parent_path(), notes, missingTextures, progress);
}

} // namespace penumbra::gltf
