// Spot and point shadow attenuation over the local atlas: the light plane's normal bias, the cube face
// of a point light, tile-clamped PCF (shadow_filter.glsl); or, in cube-map mode, point lights through
// hardware cube lookups. The block is penumbra::shadows::LocalShadowUniforms, the atlas tiles' storage block
// LocalShadowTiles one penumbra::shadows::LocalAtlasTileData per tile.

#include "local_shadows_block.glsl"

// Read with texelFetch (shadow_filter.glsl).
layout(binding = PENUMBRA_BINDING_LOCAL_ATLAS) uniform sampler2D localShadowAtlas;
// Nearest comparisons, the compare op the convention's (lit where the receiver is nearer or as near).
layout(binding = PENUMBRA_BINDING_SHADOW_CUBES) uniform samplerCubeArrayShadow pointShadowCubes;
// The same cubes read raw, no comparison: the soft filters compare against the receiver plane themselves.
layout(binding = PENUMBRA_BINDING_SHADOW_CUBE_DEPTHS) uniform samplerCubeArray pointShadowCubeDepths;

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

// The tile of a spot light's shadow (its first) or a point light's (first + the face the direction from the light
// picks), and the plane its depth grows from: the cone's axis or the face's.
struct LocalTile {
    int tile;
    vec3 plane;
};

LocalTile localTile(int firstTile, bool isPoint, vec3 axis, vec3 fromLight)
{
    if (!isPoint)
        return LocalTile(firstTile, axis);
    const int face = cubeFace(fromLight);
    return LocalTile(firstTile + face, cubeFaceAxis(face));
}

// The receiver moved by its normal offset and projected into a perspective tile (divide by w): a perspective texel
// grows linearly with the distance from the light plane, and the normal offset (`biasScale` per unit distance) with it.
vec4 localShadowPosition(mat4 worldToAtlas, float biasScale, vec3 plane, vec3 fromLight, vec3 position, vec3 normal)
{
    precise vec3 biased =
        position + receiverNormalOffset(normal, normalize(-fromLight), dot(fromLight, plane) * biasScale);
    return transformPoint(worldToAtlas, biased);
}

// A perspective tile (its texels `bounds`) of a depth atlas at the receiver's projected position `p`
// (worldToAtlas x its position, before the divide by w), filtered by `filterIndex`: the tent filters, or the Poisson
// and PCSS filters with the tile's soft data. The realtime tiles and the static maps (static_shadows.glsl) both filter through it.
float filterLocalTile(sampler2D atlas, float atlasSize, mat4 worldToAtlas, vec4 p, TileTexelBounds bounds, int filterIndex,
                      PerspectiveTileSoft tileSoft)
{
#if PENUMBRA_SOFT_FILTERS
    if (filterIndex < PENUMBRA_FILTER_FIRST_POISSON_DISK)
#endif
        return filterShadowTile(atlas, p.xyz / p.w, atlasSize, filterIndex, bounds.first, bounds.last);
#if PENUMBRA_SOFT_FILTERS
    const SoftTile t = softTile(p.xyz / p.w, projectedDerivative(worldToAtlas, p, receiverDx),
                                projectedDerivative(worldToAtlas, p, receiverDy), atlasSize, bounds.first,
                                bounds.last, vec2(0.0), localShadows.soft);
    return perspectiveSoftShadow(atlas, t, filterIndex, localShadows.soft,
                                 tileSoft);
#endif
}

// Shadow of a spot light (its cone `axis`) or a point light (six tiles from `firstTile`, the face picked
// by the direction from the light) at a receiver; `normal` is its geometric normal, either side.
float localAtlasShadow(int firstTile, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal)
{
    const vec3 fromLight = position - lightPosition;
    const LocalTile local = localTile(firstTile, isPoint, axis, fromLight);
    const LocalAtlasTileData t = localShadowTiles.tiles[local.tile];
    const vec4 p = localShadowPosition(t.worldToAtlas, t.normalBias, local.plane, fromLight, position, normal);
    return filterLocalTile(localShadowAtlas, localShadows.atlasSize, t.worldToAtlas, p, t.bounds, t.shadowFilter, t.soft);
}

// Cube-map mode's soft filters: taps are directions d + x u + y v (u, v one texel of the face at the receiver), read
// raw from the cube array with hardware face selection, compared against the receiver's plane along each tap's ray:
// its major-axis distance there, as window depth (LocalShadowCube::depthRow).
struct CubeReceiver {
    vec3 d;        // light to the receiver
    vec3 u;
    vec3 v;
    vec3 normal;   // the receiver plane's
    int cube;
    LocalShadowCube data;
    mat2 rotation;
};

float cubePlaneDepth(CubeReceiver r, vec3 tap)
{
    const float along = dot(r.normal, tap);
    // Rays that miss the plane (edge-on or behind): the receiver's own distance.
    const float s = abs(along) > 1e-6 ? dot(r.normal, r.d) / along : -1.0;
    const vec3 a = abs(s > 0.0 ? tap * s : r.d);
    const float major = max(max(a.x, a.y), a.z);
    return (r.data.depthRow.x * -major + r.data.depthRow.y) / major;
}

// The tap at disk offset `o` (texels of the face at the receiver).
vec3 cubeTap(CubeReceiver r, vec2 o) { return r.d + o.x * r.u + o.y * r.v; }

// (stored depth, receiver plane's depth) along `tap`: a blocker where the stored depth is the nearer to the light.
vec2 cubeDepthAndPlane(CubeReceiver r, vec3 tap)
{
    return vec2(texture(pointShadowCubeDepths, vec4(tap, float(r.cube))).r, cubePlaneDepth(r, tap));
}

// (average major-axis distance of the blockers, their count, the nearest blocker's distance); as searchBlockers,
// the receiver's own direction is read where no tap found a blocker.
vec3 cubeSearchBlockers(CubeReceiver r, float radius, int count, float receiver)
{
    float sum = 0.0;
    float blockers = 0.0;
    float nearest = receiver;
    DiskWalk disk = diskWalk(vec2(0.0), r.rotation, radius, count);
    for (int i = 0; i < count; ++i) {
        const vec2 tap = cubeDepthAndPlane(r, cubeTap(r, nextDiskPoint(disk, i)));
        if (penumbraIsNearer(tap.x, tap.y)) {
            const float distance = perspectiveDistance(tap.x, r.data.depthRow);
            sum += distance;
            blockers += 1.0;
            nearest = min(nearest, distance);
        }
    }
    if (blockers == 0.0) {
        const vec2 own = cubeDepthAndPlane(r, r.d);
        if (penumbraIsNearer(own.x, own.y)) {
            const float distance = perspectiveDistance(own.x, r.data.depthRow);
            return vec3(distance, 1.0, distance);
        }
    }
    return vec3(blockers > 0.0 ? sum / blockers : 0.0, blockers, nearest);
}

float cubePoissonFilter(CubeReceiver r, float radius, int count)
{
    float lit = 0.0;
    DiskWalk disk = diskWalk(vec2(0.0), r.rotation, radius, count);
    for (int i = 0; i < count; ++i) {
        const vec3 tap = cubeTap(r, nextDiskPoint(disk, i));
        lit += penumbraIsNearer(texture(pointShadowCubeDepths, vec4(tap, float(r.cube))).r, cubePlaneDepth(r, tap))
                   ? 0.0
                   : 1.0;
    }
    return lit / float(count);
}

float cubeSoftShadow(CubeReceiver r, int filterIndex)
{
    const SoftControls c = localShadows.soft;
    float radius = c.poissonRadius;
    if (filterIndex == PENUMBRA_FILTER_PCSS) {
        const vec3 a = abs(r.d);
        const float receiver = max(max(a.x, a.y), a.z);
        // The two steps of the blocker search (soft_shadows.glsl, PCSS_SEARCH_STEPS): the nearest blocker's cone
        // searched again for the average; none there, fully lit.
        float within = perspectiveSearchTexels(receiver, r.data.nearPlane, r.data.lightTexels, c);
        vec3 found = vec3(0.0);
        for (int searchStep = 0; searchStep < PCSS_SEARCH_STEPS; ++searchStep) {
            found = cubeSearchBlockers(r, within, c.blockerSamples, receiver);
            if (found.y == 0.0)
                return 1.0;
            if (searchStep == 0)
                within = min(perspectiveSearchTexels(receiver, found.z, r.data.lightTexels, c), within);
        }
        radius = diskRadius(perspectivePenumbraTexels(receiver, found.x, r.data.lightTexels, c), PENUMBRA_NEAREST_TAP_VARIANCE,
                            c);
        if (inUmbra(found.xy, c.blockerSamples, radius, within))
            return 0.0;
    }
    return cubePoissonFilter(r, radius, c.filterSamples);
}

// Cube-map mode: a k x k box of nearest comparisons (k = 2, 3, 5, 7 by the filter) spread over the face's
// texels around the receiver's direction; hardware face selection carries taps across face edges.
float cubeMapShadow(int cube, vec3 lightPosition, vec3 position, vec3 normal)
{
    const LocalShadowCube data = localShadows.cubes[cube];
    const vec3 fromLight = position - lightPosition;
    const int face = cubeFace(fromLight);
    const vec3 axis = cubeFaceAxis(face);
    precise vec3 biased =
        position + receiverNormalOffset(normal, normalize(-fromLight), dot(fromLight, axis) * data.normalBias);
    const vec3 d = biased - lightPosition;
    const float major = max(max(abs(d.x), abs(d.y)), abs(d.z));
    const float reference = (data.depthRow.x * -major + data.depthRow.y) / major;
    const vec3 u = cubeFaceAxis((face + 2) % 6) * (2.0 * major * data.invFaceSize);
    const vec3 v = cubeFaceAxis((face + 4) % 6) * (2.0 * major * data.invFaceSize);
    const int filterIndex = data.shadowFilter;
#if PENUMBRA_SOFT_FILTERS
    if (filterIndex >= PENUMBRA_FILTER_FIRST_POISSON_DISK) {
        // The receiver's texel on its face, offset by face: the light's own texel grid for the disk's rotation.
        const vec2 onFace = vec2(dot(d, cubeFaceAxis((face + 2) % 6)), dot(d, cubeFaceAxis((face + 4) % 6))) / major;
        const ivec2 texel = ivec2(floor((onFace * 0.5 + 0.5) / data.invFaceSize)) + ivec2(face * int(1.0 / data.invFaceSize + 0.5), 0);
        const CubeReceiver r = CubeReceiver(d, u, v, dot(normal, d) > 0.0 ? -normal : normal, cube, data,
                                            diskRotation(texel, localShadows.soft));
        return cubeSoftShadow(r, filterIndex);
    }
#endif
    const int k = PENUMBRA_FILTER_SIZES[filterIndex];
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
float localShadowVisibility(int tile, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal)
{
#if PENUMBRA_SHADOW_CUBES
    return isPoint && localShadows.pointMode == PENUMBRA_POINT_CUBE_MAP
               ? cubeMapShadow(tile, lightPosition, position, normal)
               : localAtlasShadow(tile, isPoint, lightPosition, axis, position, normal);
#else
    return localAtlasShadow(tile, isPoint, lightPosition, axis, position, normal);
#endif
}

// 1 = fully lit. `tile`: the first tile (or cube), -1 without shadows; `lightStrength`: the light's shadow strength.
// `strength` is the global one (distance fade), which applies to every light.
float localShadowAttenuation(int tile, float lightStrength, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position,
                             vec3 normal, float strength)
{
    const float s = lightStrength * strength;
    if (tile < 0 || s <= 0.0)
        return 1.0;
    return mix(1.0, localShadowVisibility(tile, isPoint, lightPosition, axis, position, normal), s);
}

// The realtime shadow faded by the global strength, before the light's own (1 = lit; 1 without a tile).
float localRealtimeShadow(int tile, bool isPoint, vec3 lightPosition, vec3 axis, vec3 position, vec3 normal,
                          float strength)
{
    if (tile < 0 || strength <= 0.0)
        return 1.0;
    return mix(1.0, localShadowVisibility(tile, isPoint, lightPosition, axis, position, normal), strength);
}
