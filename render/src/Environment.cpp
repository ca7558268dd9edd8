#include "penumbra/render/Environment.hpp"

#include "penumbra/rhi/Error.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace penumbra::render {
namespace {

constexpr float kPi = 3.14159265358979f;

// Each basis function's constant (Ramamoorthi and Hanrahan 2001, equation 3), in Sh9's order; the polynomials are
// 1, y, z, x, xy, yz, 3z^2 - 1, xz, x^2 - y^2.
constexpr std::array<float, 9> kBasisConstants{0.282095f, 0.488603f, 0.488603f, 0.488603f, 1.092548f,
                                               1.092548f, 0.315392f, 1.092548f, 0.546274f};
// The clamped cosine's convolution per band (Ramamoorthi and Hanrahan 2001, equation 8), by coefficient.
constexpr std::array<float, 9> kCosineBands{kPi,     2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4,
                                            kPi / 4, kPi / 4,     kPi / 4,     kPi / 4};

std::array<float, 9> polynomials(const glm::vec3& d)
{
    return {1.0f, d.y, d.z, d.x, d.x * d.y, d.y * d.z, 3.0f * d.z * d.z - 1.0f, d.x * d.z, d.x * d.x - d.y * d.y};
}

// The studio's soft regions: a lobe around `axis` falling to 1/e at an angle of about acos(1 - width).
float lobe(const glm::vec3& d, const glm::vec3& axis, float width)
{
    return std::exp((glm::dot(d, glm::normalize(axis)) - 1.0f) / width);
}

} // namespace

glm::vec3 equirectDirection(float u, float v)
{
    const float phi = (u - 0.5f) * 2.0f * kPi;
    const float theta = v * kPi;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

glm::vec2 equirectUv(const glm::vec3& d)
{
    return {std::atan2(d.z, d.x) / (2.0f * kPi) + 0.5f, std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

EnvironmentImage studioEnvironment(std::uint32_t width)
{
    EnvironmentImage image{width, width / 2, {}};
    image.texels.resize(std::size_t(image.width) * image.height);
    // A neutral grey sky brighter overhead, a dark floor, and two soft panels; colours stay near white so that the
    // environment does not tint materials. Dim enough beside a sun of intensity 3 that its shadows keep their
    // contrast: an upward white surface receives about a quarter of white from the studio.
    const glm::vec3 zenith{0.18f, 0.19f, 0.2f};
    const glm::vec3 horizon{0.14f, 0.14f, 0.14f};
    const glm::vec3 floor{0.04f, 0.038f, 0.036f};
    const glm::vec3 key{1.7f, 1.6f, 1.5f};
    const glm::vec3 fill{0.47f, 0.5f, 0.57f};
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const glm::vec3 d =
                equirectDirection((float(x) + 0.5f) / float(image.width), (float(y) + 0.5f) / float(image.height));
            const float up = std::max(d.y, 0.0f);
            // Smoothly from floor to horizon across the horizon, so no hard line shows in reflections.
            const float aboveFloor = std::clamp(d.y * 8.0f + 0.5f, 0.0f, 1.0f);
            glm::vec3 c = glm::mix(floor, glm::mix(horizon, zenith, std::sqrt(up)), aboveFloor);
            c += key * lobe(d, {-0.6f, 0.6f, 0.55f}, 0.04f) + fill * lobe(d, {0.75f, 0.3f, -0.55f}, 0.08f);
            image.texels[std::size_t(y) * image.width + x] = c;
        }
    return image;
}

EnvironmentImage resampleEnvironment(const EnvironmentImage& image, std::uint32_t width, std::uint32_t height)
{
    EnvironmentImage out{width, height, {}};
    out.texels.resize(std::size_t(width) * height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const float sx = (float(x) + 0.5f) * float(image.width) / float(width) - 0.5f;
            const float sy = std::clamp((float(y) + 0.5f) * float(image.height) / float(height) - 0.5f, 0.0f,
                                        float(image.height - 1));
            const float fx = std::floor(sx);
            const float fy = std::floor(sy);
            const auto column = [&](float c) {
                const auto w = static_cast<long long>(image.width);
                return static_cast<std::uint32_t>(((static_cast<long long>(c) % w) + w) % w);
            };
            const std::uint32_t x0 = column(fx);
            const std::uint32_t x1 = column(fx + 1.0f);
            const auto y0 = static_cast<std::uint32_t>(fy);
            const std::uint32_t y1 = std::min(y0 + 1, image.height - 1);
            const float tx = sx - fx;
            const float ty = sy - fy;
            out.texels[std::size_t(y) * width + x] = glm::mix(glm::mix(image.at(x0, y0), image.at(x1, y0), tx),
                                                              glm::mix(image.at(x0, y1), image.at(x1, y1), tx), ty);
        }
    return out;
}

void validate(const EnvironmentImage& image, std::string_view source)
{
    if (image.width == 0 || image.height == 0 || image.texels.size() != std::size_t(image.width) * image.height)
        throw rhi::Error(fmt::format("environment {}: {}x{} with {} texels is not a picture", source, image.width,
                                     image.height, image.texels.size()));
    for (std::size_t i = 0; i < image.texels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(image.texels[i][c]) || image.texels[i][c] < 0.0f)
                throw rhi::Error(fmt::format("environment {}: texel ({}, {}) channel {} is {}: radiance must be finite "
                                             "and at least 0",
                                             source, i % image.width, i / image.width, c, image.texels[i][c]));
}

void validate(const EnvironmentLight& environment)
{
    if (!(environment.intensity >= 0.0f && environment.intensity <= kMaxEnvironmentIntensity))
        throw rhi::Error(fmt::format("environment.intensity: {} is outside [0, {}]", environment.intensity,
                                     kMaxEnvironmentIntensity));
    if (!std::isfinite(environment.rotationDegrees) || std::abs(environment.rotationDegrees) > 360.0f)
        throw rhi::Error(
            fmt::format("environment.rotation: {} is outside [-360, 360] degrees", environment.rotationDegrees));
}

std::array<float, 9> sh9Basis(const glm::vec3& direction)
{
    std::array<float, 9> basis = polynomials(direction);
    for (std::size_t i = 0; i < basis.size(); ++i)
        basis[i] *= kBasisConstants[i];
    return basis;
}

Sh9 projectSh9(const EnvironmentImage& image)
{
    std::array<glm::dvec3, 9> sum{};
    for (std::uint32_t y = 0; y < image.height; ++y) {
        const float v = (float(y) + 0.5f) / float(image.height);
        // An equirectangular texel's solid angle: (2 pi / width) (pi / height) sin(theta).
        const double solidAngle = (2.0 * kPi / image.width) * (kPi / image.height) * std::sin(double(v) * kPi);
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::array<float, 9> basis = sh9Basis(equirectDirection((float(x) + 0.5f) / float(image.width), v));
            const glm::dvec3 radiance = glm::dvec3(image.at(x, y)) * solidAngle;
            for (std::size_t i = 0; i < 9; ++i)
                sum[i] += radiance * double(basis[i]);
        }
    }
    Sh9 result;
    for (std::size_t i = 0; i < 9; ++i)
        result[i] = glm::vec3(sum[i]);
    return result;
}

glm::vec3 irradianceSh9(const Sh9& radiance, const glm::vec3& n)
{
    const std::array<float, 9> basis = sh9Basis(n);
    glm::vec3 e{0.0f};
    for (std::size_t i = 0; i < 9; ++i)
        e += kCosineBands[i] * radiance[i] * basis[i];
    return e;
}

Sh9 diffuseShaderCoefficients(const Sh9& radiance)
{
    Sh9 c;
    for (std::size_t i = 0; i < 9; ++i)
        c[i] = radiance[i] * (kCosineBands[i] / kPi * kBasisConstants[i]);
    return c;
}

glm::vec2 hammersley(std::uint32_t k, std::uint32_t n)
{
    std::uint32_t bits = k;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {float(k) / float(n), float(bits) * 2.3283064365386963e-10f};
}

std::vector<glm::vec2> brdfTable(std::uint32_t size)
{
    std::vector<glm::vec2> table(std::size_t(size) * size);
    for (std::uint32_t j = 0; j < size; ++j)
        for (std::uint32_t i = 0; i < size; ++i) {
            const float nv = (float(i) + 0.5f) / float(size);
            const float roughness = (float(j) + 0.5f) / float(size);
            const float a = roughness * roughness;
            const float a2 = a * a;
            const glm::vec3 v{std::sqrt(1.0f - nv * nv), 0.0f, nv};
            glm::vec2 sum{0.0f};
            for (std::uint32_t k = 0; k < kEnvironmentSamples; ++k) {
                // GGX half vectors about n = +z (Karis 2013, ImportanceSampleGGX).
                const glm::vec2 xi = hammersley(k, kEnvironmentSamples);
                const float phi = 2.0f * kPi * xi.x;
                const float cosTheta = std::sqrt((1.0f - xi.y) / (1.0f + (a2 - 1.0f) * xi.y));
                const float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
                const glm::vec3 h{sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
                const float vh = glm::dot(v, h);
                const glm::vec3 l = 2.0f * vh * h - v;
                const float nl = l.z;
                if (nl <= 0.0f || vh <= 0.0f)
                    continue;
                const float nh = h.z;
                // f nl / pdf with pdf = D nh / (4 vh) and the lit shader's visibility V = G / (4 nl nv).
                const float visibility =
                    0.5f / (nl * std::sqrt(nv * nv * (1.0f - a2) + a2) + nv * std::sqrt(nl * nl * (1.0f - a2) + a2));
                const float weight = 4.0f * visibility * nl * vh / nh;
                const float schlick = std::pow(1.0f - vh, 5.0f);
                sum += glm::vec2((1.0f - schlick) * weight, schlick * weight);
            }
            table[std::size_t(j) * size + i] = sum / float(kEnvironmentSamples);
        }
    return table;
}

} // namespace penumbra::render
