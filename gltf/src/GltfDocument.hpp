#pragma once

#include "GltfDeviations.hpp"

#include "penumbra/gltf/GltfLoader.hpp"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace penumbra::gltf {

// A parsed glTF model and the path its errors name.
class Document {
public:
    Document(std::string path, tinygltf::Model model, Deviations deviations = {},
             std::map<int, std::filesystem::path> missingImages = {},
             MissingTextures missingTextures = MissingTextures::Fail)
        : path_(std::move(path)), model_(std::move(model)), deviations_(std::move(deviations)),
          missingImages_(std::move(missingImages)), missingTextures_(missingTextures)
    {
        for (tinygltf::Image& image : model_.images)
            pixels_.push_back(std::move(image.image));
    }

    const tinygltf::Model& model() const { return model_; }
    // The file's path as errors name it.
    const std::string& path() const { return path_; }
    // The path tried for image `index` when its file could not be read, or nullptr.
    const std::filesystem::path* missingImage(int index) const
    {
        const auto found = missingImages_.find(index);
        return found == missingImages_.end() ? nullptr : &found->second;
    }
    MissingTextures missingTextures() const { return missingTextures_; }
    // Reading accessors finds deviations too; they are the loader's bookkeeping, not the document's state.
    Deviations& deviations() const { return deviations_; }
    // The decoded pixels of image `index` (RGBA8, decodeImage), moved out: a picture of tens of MiB goes into the
    // scene without a copy (a copy and its page faults were a tenth of loading a dozen 2048 x 2048 textures). Empty
    // once taken, and for an image that did not load; like the deviations, bookkeeping of the one conversion.
    std::vector<unsigned char> takePixels(int index) const { return std::exchange(pixels_.at(std::size_t(index)), {}); }

    // Throws GltfError "<path>: <what>".
    [[noreturn]] void fail(std::string_view what) const { throw GltfError(fmt::format("{}: {}", path_, what)); }

    // model().<items>[index], or fail() naming `owner`, the kind and how many there are.
    template <typename T>
    const T& at(const std::vector<T>& items, int index, std::string_view kind, std::string_view owner) const
    {
        if (index < 0 || static_cast<std::size_t>(index) >= items.size())
            fail(fmt::format("{}: {} {} does not exist (the file has {})", owner, kind, index, items.size()));
        return items[static_cast<std::size_t>(index)];
    }

private:
    std::string path_;
    tinygltf::Model model_;
    mutable Deviations deviations_;
    mutable std::vector<std::vector<unsigned char>> pixels_; // model_.images' pixels, by image
    std::map<int, std::filesystem::path> missingImages_;
    MissingTextures missingTextures_;
};

// "mesh 2 ('Cube')", or "mesh 2" when unnamed.
std::string describe(std::string_view kind, int index, const std::string& name);

} // namespace penumbra::gltf
