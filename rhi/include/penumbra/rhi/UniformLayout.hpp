#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace penumbra::rhi {

// One member of a uniform block: its name, std140 byte offset and size (a whole array for an array).
struct UniformMember {
    std::string name;
    std::uint32_t offset = 0;
    std::uint32_t size = 0;
};

// What a C++ struct uploaded into a uniform block looks like, for PipelineDesc::uniformLayouts: `block` is the
// GLSL block name (`uniform Frame { ... }` is "Frame"), the members are the struct's, each named as in GLSL.
// Build it next to the struct with PENUMBRA_UNIFORM_MEMBER, so offsets and sizes come from the compiler:
//   rhi::UniformLayout{"Frame", sizeof(FrameUniforms),
//                      {PENUMBRA_UNIFORM_MEMBER(FrameUniforms, viewProjection), ...}}
struct UniformLayout {
    std::string block;
    std::uint32_t size = 0;
    std::vector<UniformMember> members;
};

} // namespace penumbra::rhi

// A UniformMember for `member` of `Struct`, by offsetof and sizeof (Struct must be standard-layout).
#define PENUMBRA_UNIFORM_MEMBER(Struct, member)                                                                        \
    ::penumbra::rhi::UniformMember                                                                                     \
    {                                                                                                                  \
#member, std::uint32_t(offsetof(Struct, member)), std::uint32_t(sizeof(Struct::member))                        \
    }

// The UniformMember of a runtime array `T member[]` ending a storage block, for ComputePipelineDesc::storageLayouts:
// its offset in `Struct` (the header the array follows; offsetof of the flexible member is not standard C++, so
// the offset is the header's size rounded up to the element's alignment) and the size of one `Element`, which
// std430 must give as the array stride.
#define PENUMBRA_UNIFORM_ARRAY_ELEMENT(Struct, member, Element)                                                        \
    ::penumbra::rhi::UniformMember                                                                                     \
    {                                                                                                                  \
#member, std::uint32_t((sizeof(Struct) + alignof(Element) - 1) / alignof(Element) * alignof(Element)),         \
            std::uint32_t(sizeof(Element))                                                                             \
    }
