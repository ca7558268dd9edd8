// The equirectangular projection of environments: render::equirectUv and render::equirectDirection in GLSL (u turns
// about +y, u = 0.5 along +x; v = 0 straight up), and the Hammersley points of render::hammersley.

const float ENVIRONMENT_PI = 3.14159265;

vec2 equirectUv(vec3 d)
{
    return vec2(atan(d.z, d.x) / (2.0 * ENVIRONMENT_PI) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / ENVIRONMENT_PI);
}

vec3 equirectDirection(vec2 uv)
{
    const float phi = (uv.x - 0.5) * 2.0 * ENVIRONMENT_PI;
    const float theta = uv.y * ENVIRONMENT_PI;
    return vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}

vec2 hammersley(uint k, uint n) { return vec2(float(k) / float(n), float(bitfieldReverse(k)) * 2.3283064365386963e-10); }
