#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace penumbra::render {

// Image-based lighting's CPU half: an equirectangular environment, its diffuse irradiance as nine spherical harmonics
// and the split-sum BRDF table. EnvironmentMaps (render/src) prefilters the specular chain on the GPU.

// Linear radiance over the sphere in the equirectangular projection: texel (x, y) of a width x height image looks
// along equirectDirection((x + 0.5) / width, (y + 0.5) / height); row 0 is straight up (+y).
struct EnvironmentImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<glm::vec3> texels; // width * height, row by row

    const glm::vec3& at(std::uint32_t x, std::uint32_t y) const { return texels[std::size_t(y) * width + x]; }
};

// The size every environment is resampled to before it is prefiltered (EnvironmentMaps): sharp enough for a mirror at
// the frame sizes the tools render, small enough that prefiltering stays a few milliseconds on a software driver.
inline constexpr std::uint32_t kEnvironmentWidth = 256;
inline constexpr std::uint32_t kEnvironmentHeight = kEnvironmentWidth / 2;
// The split-sum BRDF table's size (brdfTable): NdotV across, roughness down.
inline constexpr std::uint32_t kBrdfTableSize = 32;
// GGX importance samples per texel of the BRDF table and of each prefiltered level.
inline constexpr std::uint32_t kEnvironmentSamples = 64;
// Upper bound of the environment's intensity, as kMaxAmbientIntensity: a typo is caught.
inline constexpr float kMaxEnvironmentIntensity = 100.0f;

// The unit direction at equirectangular coordinates (u, v) in [0, 1]^2: u turns about +y from -x through +z (u = 0.5
// looks along +x), v goes from +y (0) to -y (1). equirectUv is its inverse; shaders/environment.glsl the same in GLSL.
glm::vec3 equirectDirection(float u, float v);
glm::vec2 equirectUv(const glm::vec3& direction);

// The built-in neutral studio environment, generated in code: a grey sky gradient over a darker floor, with a soft warm
// key region high on one side and a dimmer cool fill opposite, so metals show shape from every side.
EnvironmentImage studioEnvironment(std::uint32_t width = kEnvironmentWidth);
// `image` bilinearly resampled (wrapping around, clamped at the poles) to width x height.
EnvironmentImage resampleEnvironment(const EnvironmentImage& image, std::uint32_t width, std::uint32_t height);
// Throws rhi::Error naming `source` for an empty image, a size that does not match its texels, or a texel component
// that is negative or not finite (naming the texel).
void validate(const EnvironmentImage& image, std::string_view source);

// Nine real spherical harmonics coefficients (bands 0 to 2) per colour channel, ordered Y00, Y1-1, Y10, Y11, Y2-2,
// Y2-1, Y20, Y21, Y22 over (x, y, z) = direction.
using Sh9 = std::array<glm::vec3, 9>;
// The nine basis functions at a unit direction (Ramamoorthi and Hanrahan 2001, "An Efficient Representation for
// Irradiance Environment Maps", equation 3).
std::array<float, 9> sh9Basis(const glm::vec3& direction);
// The radiance's projection onto the basis: the integral of L(w) Y_i(w) over the sphere, summed per texel with its
// solid angle.
Sh9 projectSh9(const EnvironmentImage& image);
// The irradiance at normal n from projected radiance (Ramamoorthi and Hanrahan 2001, equations 7 and 8: band l scaled
// by A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4).
glm::vec3 irradianceSh9(const Sh9& radiance, const glm::vec3& n);
// The coefficients the lit shader evaluates: radiance projected, times each band's A_l / pi and each basis function's
// constant, so that the Lambertian radiance per unit albedo at n is c0 + c1 y + c2 z + c3 x + c4 xy + c5 yz
// + c6 (3 z^2 - 1) + c7 xz + c8 (x^2 - y^2) (shaders/environment.glsl).
Sh9 diffuseShaderCoefficients(const Sh9& radiance);

// The split-sum BRDF table (Karis 2013, "Real Shading in Unreal Engine 4", section "Image Based Lighting"): texel
// (i, j) holds the scale A and bias B of f0 in the specular reflectance f0 A + B at NdotV = (i + 0.5) / size and
// perceptual roughness (j + 0.5) / size, integrated with kEnvironmentSamples GGX importance samples and the lit
// shader's height-correlated Smith visibility. size * size pairs, row by row.
std::vector<glm::vec2> brdfTable(std::uint32_t size = kBrdfTableSize);

// Levels of the prefiltered specular chain: kEnvironmentWidth x kEnvironmentHeight down to 8 x 4 texels, level m for
// perceptual roughness m / (kEnvironmentLevels - 1).
inline constexpr std::uint32_t kEnvironmentLevels = 6;

// The light a frame takes from its surroundings (FrameDesc::environment): with an image, diffuse and specular
// image-based lighting replace the ambient light; without one, the ambient light lights alone.
struct EnvironmentLight {
    std::shared_ptr<const EnvironmentImage> image; // nullptr: no environment
    float intensity = 1.0f; // 0..kMaxEnvironmentIntensity, scales the image's radiance
    float rotationDegrees = 0.0f; // turns the environment about +y (counter-clockwise seen from above)
};

// Throws rhi::Error naming "environment.intensity" or "environment.rotation" and the allowed range.
void validate(const EnvironmentLight& environment);

// The k-th of n points of the Hammersley set in [0, 1)^2 (Karis 2013; the radical inverse of k in base 2).
glm::vec2 hammersley(std::uint32_t k, std::uint32_t n);

} // namespace penumbra::render
