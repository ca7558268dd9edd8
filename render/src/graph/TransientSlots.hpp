#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::render {

// A texture the frame makes for a span of its passes: the first and the last pass (in running order) that use it,
// and which textures it could share memory with (equal `kind`: the same size, format, samples and usage).
struct TransientLifetime {
    std::size_t kind = 0;
    std::size_t firstPass = 0;
    std::size_t lastPass = 0;
};

// The slot each transient texture takes: textures of one kind whose lifetimes do not overlap share a slot, so the
// frame makes one texture where its passes use several one after another (the aliasing of Filament's FrameGraph and
// of O'Donnell's "FrameGraph: Extensible Rendering Architecture in Frostbite", GDC 2017, at whole-texture grain).
// Slots are numbered within their kind from 0, first come first served in order of first use, so a frame that
// declares the same textures again gets the same slots (and the graph's pool the same textures).
std::vector<std::uint32_t> assignTransientSlots(const std::vector<TransientLifetime>& lifetimes);

} // namespace penumbra::render
