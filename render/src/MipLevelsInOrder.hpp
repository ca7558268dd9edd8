#pragma once

#include "penumbra/rhi/MipChain.hpp"

#include <cstddef>
#include <functional>

namespace penumbra::render {

// Runs generate(0) to generate(count - 1) on one thread per hardware thread, and hands each result to consume(k, ...)
// on the calling thread in order of k as soon as it and those before it are ready, so the uploads of a scene's
// textures overlap the generation of the later ones' mip levels (with a dozen 2048 x 2048 textures, the chains
// filtered in batches and uploaded after each batch left a core idle; docs/notes/2026-12-06-large-texture-loading.md).
// At most two results per thread wait to be consumed, which bounds the memory held. Each result depends on k alone, so
// the textures do not depend on the thread count. The first failure, of either, is rethrown after the threads stop.
void generateMipLevelsInOrder(std::size_t count, const std::function<rhi::MipLevels(std::size_t)>& generate,
                              const std::function<void(std::size_t, const rhi::MipLevels&)>& consume);

} // namespace penumbra::render
