#pragma once

#include "penumbra/rhi/Conventions.hpp"
#include "penumbra/rhi/Image.hpp"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

namespace penumbra::parity {

// What a render function hands the harness: named pictures, compared picture by picture between
// configurations. Names are file stems of the report ("colour", "depth", "atlas"): letters, digits,
// '-', '_' and '.'.
enum class PictureKind {
    Color, // an rhi::Image as read back, compared per byte of every channel (8-bit steps for RGBA8)
    Depth, // window depth as read back, compared in a DepthSpace that every depth convention shares
    Float, // raw float values (a light-depth map, a G-buffer channel), compared as they are
};

// How a depth picture is made comparable across depth ranges and reversed-Z. In each, texels at the
// far plane (the depth clear value) are background: a texel drawn in one picture and background in
// the other is a coverage mismatch, counted apart from the differences of texels drawn in both.
enum class DepthSpace {
    // (d - far) / (near - far) of the configuration's rhi::Conventions: 0 at the far plane, 1 at the
    // near plane. Orthographic window depth is linear in view depth in every convention, so this is
    // its linear depth; for a perspective projection it is the same function of view depth in
    // [0, 1] and [-1, 1] alike, reversed or not.
    FromFarPlane,
    // Positive view depth (rhi::Conventions::viewDepth through the projection the picture was drawn
    // with), in view-space units.
    LinearView,
    // Values the render function computed itself, one per texel, 0 for background: an atlas of tiles
    // with projections of their own (render::lightDepthFraction).
    Given,
};

// One named picture a render function returns: colour, depth (in one of the depth spaces) or floats.
struct Picture {
    std::string name;
    PictureKind kind = PictureKind::Color;
    rhi::Image color; // Color
    rhi::DepthImage depth; // Depth: raw window depth; Float: the width, height and values
    DepthSpace space = DepthSpace::FromFarPlane;
    glm::mat4 projection{1.0f}; // Depth in LinearView
    std::vector<float> given; // Depth in Given

    // Width in texels.
    std::uint32_t width() const { return kind == PictureKind::Color ? color.width : depth.width; }
    // Height in texels.
    std::uint32_t height() const { return kind == PictureKind::Color ? color.height : depth.height; }
};

// A colour picture, compared per byte of every channel.
Picture colorPicture(std::string name, rhi::Image image);
// Depth compared from the far plane (DepthSpace::FromFarPlane).
Picture depthPicture(std::string name, rhi::DepthImage depth);
// Depth compared in linear view depth through `projection` (DepthSpace::LinearView).
Picture viewDepthPicture(std::string name, rhi::DepthImage depth, const glm::mat4& projection);
// Depth compared in values of the caller's own, `comparable[i]` for texel i (DepthSpace::Given).
Picture depthPicture(std::string name, rhi::DepthImage depth, std::vector<float> comparable);
// Values compared as they are (PSNR with peak 1), width x height of them, row 0 at the top.
Picture floatPicture(std::string name, std::uint32_t width, std::uint32_t height, std::vector<float> values);

// "colour", "depth" or "float".
const char* kindName(PictureKind kind);
// "RGBA8 64x64", "depth 64x64 (linear view depth)": what error messages and reports call a picture.
std::string describe(const Picture& picture);

// Throws rhi::Error naming the picture when its name is not a file stem, it is empty, or its data
// does not fill width x height.
void validate(const Picture& picture);

// A depth or float picture's values as they are compared under `conventions`, and which texels are
// drawn (not background). Float pictures are drawn everywhere.
struct ComparableValues {
    std::vector<float> values;
    std::vector<bool> drawn;
};
// The values a picture is compared by, in a space shared by every configuration, and which texels were drawn.
ComparableValues comparableValues(const Picture& picture, const rhi::Conventions& conventions);

} // namespace penumbra::parity
