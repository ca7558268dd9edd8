// Spot and point shadow attenuation over the other atlas: the light plane's normal bias, the cube face
// of a point light, tile-clamped PCF (shadow_filter.glsl); or, in cube-map mode, point lights through
// hardware cube lookups. The block is penumbra::shadows::OtherShadowUniforms.

layout(std140, binding = 4) uniform OtherShadows {
    mat4 worldToAtlas[16];
    vec4 tileBounds[16];
    vec4 tileData[16];
    vec4 cubeData[4];
    vec4 atlasSize;
    ivec4 config;
} otherShadows;

// Read with texelFetch (shadow_filter.glsl).
layout(binding = 5) uniform sampler2D otherShadowAtlas;
// Nearest comparisons, the compare op the convention's (lit where the receiver is nearer or as near).
layout(binding = 6) uniform samplerCubeArrayShadow pointShadowCubes;

const int PENUMBRA_POINT_CUBE_MAP = 1;

// The face of the largest component of d (light to point), ties to x, then y, then z:
// penumbra::shadows::cubeFace. Faces in the order +X, -X, +Y, -Y, +Z, -Z.
int cubeFace(vec3 d)
{
    const vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

vec3 cubeFaceAxis(int face)
{
    vec3 axis = vec3(0.0);
    axis[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
    return axis;
}

// Shadow of a spot light (its cone `axis`) or a point light (six tiles from `firstTile`, the face picked
// by the direction from the light) at a receiver; `normal` is its geometric normal, either side.
float otherAtlasShadow(int firstTile, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal)
{
    const vec3 fromLight = position - lightPosition;
    int tile = firstTile;
    vec3 plane = axis;
    if (isPoint) {
        const int face = cubeFace(fromLight);
        tile += face;
        plane = cubeFaceAxis(face);
    }
    // A perspective texel grows linearly with the distance from the light plane, and the normal offset with it.
    const float distanceToPlane = dot(fromLight, plane);
    precise vec3 biased =
        position + receiverNormalOffset(normal, normalize(-fromLight), distanceToPlane * otherShadows.tileData[tile].x);
    const vec4 p = transformPoint(otherShadows.worldToAtlas[tile], biased);
    const vec4 bounds = otherShadows.tileBounds[tile];
    return filterShadowTile(otherShadowAtlas, p.xyz / p.w, otherShadows.atlasSize.x, otherShadows.config.x,
                            ivec2(bounds.xy), ivec2(bounds.zw));
}

// Cube-map mode: a k x k box of nearest comparisons (k = 2, 3, 5, 7 by the filter) spread over the face's
// texels around the receiver's direction; hardware face selection carries taps across face edges.
float cubeMapShadow(int cube, vec3 lightPosition, vec3 position, vec3 normal)
{
    const vec4 data = otherShadows.cubeData[cube];
    const vec3 fromLight = position - lightPosition;
    const int face = cubeFace(fromLight);
    const vec3 axis = cubeFaceAxis(face);
    precise vec3 biased =
        position + receiverNormalOffset(normal, normalize(-fromLight), dot(fromLight, axis) * data.z);
    const vec3 d = biased - lightPosition;
    const float major = max(max(abs(d.x), abs(d.y)), abs(d.z));
    const float reference = (data.x * -major + data.y) / major;
    const vec3 u = cubeFaceAxis((face + 2) % 6) * (2.0 * major * data.w);
    const vec3 v = cubeFaceAxis((face + 4) % 6) * (2.0 * major * data.w);
    const int k = int[](2, 3, 5, 7)[otherShadows.config.x];
    float lit = 0.0;
    for (int y = 0; y < k; ++y)
        for (int x = 0; x < k; ++x) {
            const vec3 tap = d + (float(x) - 0.5 * float(k - 1)) * u + (float(y) - 0.5 * float(k - 1)) * v;
            lit += texture(pointShadowCubes, vec4(tap, float(cube)), reference);
        }
    return lit / float(k * k);
}

// The filtered shadow map alone, before any strength (1 = lit): what ground truth compares. `tile`: the
// light's first tile (or cube).
float otherShadowVisibility(int tile, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal)
{
    return isPoint && otherShadows.config.y == PENUMBRA_POINT_CUBE_MAP
               ? cubeMapShadow(tile, lightPosition, position, normal)
               : otherAtlasShadow(tile, isPoint, lightPosition, axis, position, normal);
}

// 1 = fully lit. `shadow`: first tile (or cube), -1 without shadows; the light's shadow strength. `strength` is the
// global one (distance fade), which applies to every light.
float otherShadowAttenuation(vec2 shadow, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal,
                             float strength)
{
    const float s = shadow.y * strength;
    if (shadow.x < 0.0 || s <= 0.0)
        return 1.0;
    return mix(1.0, otherShadowVisibility(int(shadow.x), isPoint, lightPosition, axis, position, normal), s);
}
