#include "penumbra/scene/Keyframes.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace penumbra::scene {
namespace {

// Below this angle between two rotations sin(angle) is too small to divide by: a normalized lerp is exact to float
// precision there.
constexpr float kSlerpMinAngle = 1e-4f;

// Where `time` falls: between key `k` and k + 1 at fraction `u`, with `interval` = t(k+1) - t(k). Clamped: before
// the first key k = 0, u = 0; at or after the last k = last, u = 0.
struct Segment {
    std::size_t k = 0;
    float u = 0.0f;
    float interval = 0.0f;
};

Segment segmentAt(const std::vector<float>& times, float time)
{
    if (times.size() < 2 || time <= times.front())
        return {};
    if (time >= times.back())
        return {times.size() - 1, 0.0f, 0.0f};
    const auto next = std::upper_bound(times.begin(), times.end(), time);
    const auto k = std::size_t(next - times.begin()) - 1;
    const float interval = times[k + 1] - times[k];
    return {k, (time - times[k]) / interval, interval};
}

// Component c of value `role` of key k: CUBICSPLINE stores in-tangent (role 0), value (1), out-tangent (2) per key.
float at(const Keyframes& keys, std::size_t k, std::size_t role, std::size_t c)
{
    const std::size_t perKey = keys.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t slot = keys.interpolation == Interpolation::CubicSpline ? role : 0;
    return keys.values[(k * perKey + slot) * keys.width + c];
}

constexpr std::size_t kInTangent = 0, kValue = 1, kOutTangent = 2;

glm::quat quatAt(const Keyframes& keys, std::size_t k)
{
    // glTF stores x, y, z, w; glm::quat takes w first.
    return {at(keys, k, kValue, 3), at(keys, k, kValue, 0), at(keys, k, kValue, 1), at(keys, k, kValue, 2)};
}

} // namespace

std::vector<float> sampleKeyframes(const Keyframes& keys, float time)
{
    const Segment s = segmentAt(keys.times, time);
    std::vector<float> out(keys.width);
    for (std::size_t c = 0; c < keys.width; ++c) {
        const float v0 = at(keys, s.k, kValue, c);
        if (s.u == 0.0f || keys.interpolation == Interpolation::Step) {
            out[c] = v0;
            continue;
        }
        const float v1 = at(keys, s.k + 1, kValue, c);
        if (keys.interpolation == Interpolation::Linear) {
            out[c] = (1.0f - s.u) * v0 + s.u * v1;
            continue;
        }
        // Appendix C, "Cubic Spline Interpolation": p(t) = (2t^3 - 3t^2 + 1) v_k + t_d (t^3 - 2t^2 + t) b_k
        // + (-2t^3 + 3t^2) v_k+1 + t_d (t^3 - t^2) a_k+1, b_k the out-tangent of key k, a_k+1 the in-tangent of k + 1.
        const float t = s.u, t2 = t * t, t3 = t2 * t;
        const float b0 = at(keys, s.k, kOutTangent, c), a1 = at(keys, s.k + 1, kInTangent, c);
        out[c] = (2.0f * t3 - 3.0f * t2 + 1.0f) * v0 + s.interval * (t3 - 2.0f * t2 + t) * b0 +
                 (-2.0f * t3 + 3.0f * t2) * v1 + s.interval * (t3 - t2) * a1;
    }
    return out;
}

glm::quat slerpShorter(const glm::quat& a, const glm::quat& b, float u)
{
    const float d = glm::dot(a, b);
    const glm::quat target = d < 0.0f ? -b : b;
    const float angle = std::acos(std::min(std::abs(d), 1.0f));
    if (angle < kSlerpMinAngle)
        return glm::normalize((1.0f - u) * a + u * target);
    const float sine = std::sin(angle);
    return glm::normalize(std::sin((1.0f - u) * angle) / sine * a + std::sin(u * angle) / sine * target);
}

glm::quat sampleRotation(const Keyframes& keys, float time)
{
    if (keys.interpolation == Interpolation::Linear) {
        const Segment s = segmentAt(keys.times, time);
        if (s.u == 0.0f)
            return glm::normalize(quatAt(keys, s.k));
        return slerpShorter(glm::normalize(quatAt(keys, s.k)), glm::normalize(quatAt(keys, s.k + 1)), s.u);
    }
    const std::vector<float> v = sampleKeyframes(keys, time);
    return glm::normalize(glm::quat(v[3], v[0], v[1], v[2]));
}

float Animation::duration() const
{
    float last = 0.0f;
    for (const Keyframes& keys : samplers)
        if (!keys.times.empty())
            last = std::max(last, keys.times.back());
    return last;
}

} // namespace penumbra::scene
