// The Poisson-disk filters over one tile of a depth atlas: a fixed-radius Poisson disk, and percentage-closer soft
// shadows (Fernando 2005, "Percentage-Closer Soft Shadows"; NVIDIA 2008, "Integrating Realistic Soft Shadows into
// Your Game Engine"): a blocker search, the average blocker depth, the penumbra from the receiver and blocker depths,
// then the Poisson disk over that penumbra. The same math as penumbra::shadows::SoftShadowMath; the disks are
// penumbra::shadows::poissonDisk's golden-angle spirals, walked tap by tap (DiskWalk).
//
// Every tap compares against the receiver's plane at the texel it reads, not the receiver's own depth (Isidoro 2006,
// "Receiver Plane Depth Bias", GDC): a wide kernel over a sloped receiver then does not shadow the receiver itself.
// The disk turns by a hash of the receiver's texel in the light's own grid, so a static scene's shadows stay put
// while the camera moves, and both backends give the same pixels.

// The disk of `count` points turned by `rotation`, scaled by `radius` and centred on `centre`, walked point by
// point: point k at radius sqrt((k + 0.5) / count) along a direction the golden angle past point k - 1's, less the
// spiral's mean (penumbra::shadows::poissonDisk). A tap costs no uniform read and no sine (PoissonDisk.hpp).
struct DiskWalk {
    vec2 origin; // centre less the turned, scaled spiral mean
    vec2 direction; // of the next point, turned
    float radius;
    float count;
};

DiskWalk diskWalk(vec2 centre, mat2 rotation, float radius, int count)
{
    return DiskWalk(centre - radius * (rotation * penumbraSpiralMean(count)), rotation[0], radius, float(count));
}

// Point k of the walk; turns the walk on to point k + 1.
vec2 nextDiskPoint(inout DiskWalk w, int k)
{
    const vec2 point = w.origin + w.radius * sqrt((float(k) + 0.5) / w.count) * w.direction;
    w.direction = mat2(PENUMBRA_GOLDEN_TURN, vec2(-PENUMBRA_GOLDEN_TURN.y, PENUMBRA_GOLDEN_TURN.x)) * w.direction;
    return point;
}

// The receiver's screen-space position derivatives, set once by main() in uniform control flow
// (setReceiverDerivatives): the shadow functions run in per-light branches, where derivatives are undefined.
vec3 receiverDx = vec3(0.0);
vec3 receiverDy = vec3(0.0);

void setReceiverDerivatives(vec3 dx, vec3 dy)
{
    receiverDx = dx;
    receiverDy = dy;
}

// PCG2D (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering", section 3): penumbra::shadows::pcg2d.
uvec2 pcg2d(uvec2 v)
{
    v = v * 1664525u + 1013904223u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    return v;
}

// The disk's turn at `lightTexel`; unturned where SoftControls.diskRotation is 0 (penumbra::shadows::diskRotationAngle).
mat2 diskRotation(ivec2 lightTexel, SoftControls controls)
{
    if (controls.diskRotation == 0)
        return mat2(1.0);
    const float angle = 6.28318531 * (float(pcg2d(uvec2(lightTexel)).x >> 8u) * (1.0 / 16777216.0));
    const float c = cos(angle);
    const float s = sin(angle);
    return mat2(c, s, -s, c);
}

// d(depth) per texel along x and y of the receiver's plane, from the screen derivatives of its shadow-map position
// (texel x, texel y, depth): penumbra::shadows::receiverPlaneDepthGradient.
vec2 receiverPlaneDepthGradient(vec3 dx, vec3 dy)
{
    const float determinant = dx.x * dy.y - dx.y * dy.x;
    if (!(abs(determinant) > 1e-12))
        return vec2(0.0);
    return vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / determinant;
}

// One receiver over one tile: texel-space position, depth, receiver-plane gradient, tile and disk rotation.
struct SoftTile {
    vec2 centre;
    float depth;
    vec2 gradient;
    ivec2 tileMin;
    ivec2 tileMax;
    mat2 rotation;
};

// The receiver in tile `tileMin..tileMax` at atlas position `p` (u, v, depth) whose screen derivatives are
// dpdx, dpdy (atlas units); `lightTexel` adds to a tile texel for the light's own texel grid; `c` says whether the
// disk turns.
SoftTile softTile(vec3 p, vec3 dpdx, vec3 dpdy, float atlasSize, ivec2 tileMin, ivec2 tileMax, vec2 lightTexel,
                  SoftControls c)
{
    SoftTile t;
    t.centre = p.xy * atlasSize;
    t.depth = p.z;
    const vec3 scale = vec3(atlasSize, atlasSize, 1.0);
    t.gradient = receiverPlaneDepthGradient(dpdx * scale, dpdy * scale);
    t.tileMin = tileMin;
    t.tileMax = tileMax;
    t.rotation = diskRotation(ivec2(floor(t.centre - vec2(tileMin) + lightTexel)), c);
    return t;
}

// The receiver plane's depth at the centre of `texel`.
float planeDepth(SoftTile t, ivec2 texel) { return t.depth + dot(t.gradient, vec2(texel) + 0.5 - t.centre); }

// (stored depth, receiver plane's depth) at the texel under texel-space `position`, clamped into the tile: a blocker
// where the stored depth is the nearer to the light.
vec2 depthAndPlaneAt(sampler2D atlas, SoftTile t, vec2 position)
{
    const ivec2 texel = clamp(ivec2(floor(position)), t.tileMin, t.tileMax);
    return vec2(texelFetch(atlas, texel, 0).r, planeDepth(t, texel));
}

// (average depth of the blockers, their count, the nearest blocker's depth) among `count` taps within `radius`
// texels: a tap's texel, clamped into the tile, is a blocker when its depth is nearer to the light than the receiver
// plane there. Taps spread over a wide search can all step over a caster thinner than their spacing that covers the
// receiver's own texel; where they find none, that texel is read too, and found a blocker it is the one blocker
// (a search that calls such a receiver lit leaves lit holes in the shadows of wires and slats).
// penumbra::shadows::searchBlockers.
vec3 searchBlockers(sampler2D atlas, SoftTile t, float radius, int count)
{
    float sum = 0.0;
    float blockers = 0.0;
    float nearest = t.depth;
    DiskWalk disk = diskWalk(t.centre, t.rotation, radius, count);
    for (int i = 0; i < count; ++i) {
        const vec2 tap = depthAndPlaneAt(atlas, t, nextDiskPoint(disk, i));
        if (penumbraIsNearer(tap.x, tap.y)) {
            sum += tap.x;
            blockers += 1.0;
            nearest = penumbraIsNearer(tap.x, nearest) ? tap.x : nearest;
        }
    }
    if (blockers == 0.0) {
        const vec2 own = depthAndPlaneAt(atlas, t, t.centre);
        if (penumbraIsNearer(own.x, own.y))
            return vec3(own.x, 1.0, own.x);
    }
    return vec3(blockers > 0.0 ? sum / blockers : 0.0, blockers, nearest);
}

// The blocker search in two steps. The first searches as far as the nearest caster of the whole light could reach
// (the search radius, clamped to maxPenumbraTexels), which is mostly far wider than any blocker near the receiver
// needs, and by that clamp a different region of the world in each cascade; it finds the nearest blocker. The second
// searches only the disk that blocker can shadow the receiver from (its light cone, `refined` texels) and averages
// the blockers there, so the average, and the penumbra, depend on the blockers near the receiver, not on the clamp.
// A blocker farther from the light has a narrower cone, inside the nearest one's, so a second search that finds no
// blocker finds none that can shadow the receiver: fully lit, without filtering, as a first search that finds none.
// The two steps are one loop run twice, not two calls: the compilers inline every call, and on Mesa's llvmpipe a
// second copy of the search loop made the lit pass about 0.1 of PCF 5x5 slower, for the Poisson disk too, which
// never runs it.
const int PCSS_SEARCH_STEPS = 2;

// Every tap of the refined search found a blocker and the penumbra fits inside it: the receiver is in the umbra,
// fully shadowed without filtering (the blocker search's early out of NVIDIA 2008, "Integrating Realistic Soft
// Shadows into Your Game Engine"), which spares the umbra the filter's taps.
bool inUmbra(vec2 blockers, int count, float radius, float refined)
{
    return blockers.y == float(count) && radius <= refined;
}

// A bilinear comparison tap at texel-space `position` against the receiver plane, over texels tileMin..tileMax only
// (bilinearCompare's corner clamp and textureGather order): each of the four texels against the plane at its centre.
float bilinearComparePlane(sampler2D atlas, SoftTile t, vec2 position)
{
    const vec2 corner = clamp(position, vec2(t.tileMin) + 0.5, vec2(t.tileMax) + 0.5) - 0.5;
    const vec2 base = floor(corner);
    const vec2 f = corner - base;
    const vec4 depths = textureGather(atlas, (base + 1.0) / vec2(textureSize(atlas, 0)), 0);
    const float plane00 = t.depth + dot(t.gradient, base + 0.5 - t.centre);
    const vec4 planes = plane00 + vec4(t.gradient.y, t.gradient.x + t.gradient.y, t.gradient.x, 0.0);
    const vec4 lit = vec4(penumbraIsNearer(depths.x, planes.x) ? 0.0 : 1.0,
                          penumbraIsNearer(depths.y, planes.y) ? 0.0 : 1.0,
                          penumbraIsNearer(depths.z, planes.z) ? 0.0 : 1.0,
                          penumbraIsNearer(depths.w, planes.w) ? 0.0 : 1.0);
    const float top = mix(lit.w, lit.z, f.x);
    const float bottom = mix(lit.x, lit.y, f.x);
    return mix(top, bottom, f.y);
}

// The Poisson disk of `count` bilinear taps over `radius` texels: 1 = lit.
float poissonFilter(sampler2D atlas, SoftTile t, float radius, int count)
{
    float lit = 0.0;
    DiskWalk disk = diskWalk(t.centre, t.rotation, radius, count);
    for (int i = 0; i < count; ++i)
        lit += bilinearComparePlane(atlas, t, nextDiskPoint(disk, i));
    return lit / float(count);
}

// SoftControls, the blocks' soft-filter settings, is generated from penumbra::shadows::SoftShadowUniforms.
// The radius of the disk of taps, each blurring by `tapVariance` itself, that blurs as the uniform disk of radius
// `penumbra` texels, clamped: penumbra::shadows::diskRadius.
float diskRadius(float penumbra, float tapVariance, SoftControls c)
{
    return clamp(sqrt(max(penumbra * penumbra - 4.0 * tapVariance, 0.0)), c.minTexels, c.maxTexels);
}

// Directional lights (penumbra::shadows::directionalSearchTexels, directionalPenumbraTexels): distances past the
// nearest caster from the depth row (so the search does not follow the camera-fitted near plane), the penumbra from
// the angular size in world units over the cascade's texel size. Each loop appears once: the shader compilers inline
// every call.
float directionalSoftShadow(sampler2D atlas, SoftTile t, int filterIndex, SoftControls c, vec2 depthRow,
                            float tanHalfAngle, float texelWorld)
{
    float radius = c.poissonRadius;
    if (filterIndex == PENUMBRA_FILTER_PCSS) {
        const float receiver = max((depthRow.y - t.depth) / depthRow.x, 0.0);
        // The search radius of each step: past the light's nearest caster, then past the nearest blocker found.
        float within = clamp(c.searchScale * receiver * tanHalfAngle / texelWorld, 1.0, max(c.maxTexels, 1.0));
        vec3 found = vec3(0.0);
        for (int searchStep = 0; searchStep < PCSS_SEARCH_STEPS; ++searchStep) {
            found = searchBlockers(atlas, t, within, c.blockerSamples);
            if (found.y == 0.0)
                return 1.0;
            if (searchStep == 0) {
                const float nearest = (depthRow.y - found.z) / depthRow.x;
                within = min(clamp(c.searchScale * max(receiver - nearest, 0.0) * tanHalfAngle / texelWorld, 1.0,
                                   max(c.maxTexels, 1.0)),
                             within);
            }
        }
        const float blocker = (depthRow.y - found.x) / depthRow.x;
        radius = diskRadius(c.penumbraScale * max(receiver - blocker, 0.0) * tanHalfAngle / texelWorld,
                            PENUMBRA_BILINEAR_TAP_VARIANCE, c);
        if (inUmbra(found.xy, c.blockerSamples, radius, within))
            return 0.0;
    }
    return poissonFilter(atlas, t, radius, c.filterSamples);
}

// View distance of a perspective depth: penumbra::shadows::perspectiveDistance.
float perspectiveDistance(float depth, vec2 depthRow) { return depthRow.y / (depth + depthRow.x); }

// Spot and point lights of radius R (lightTexels = R x texels per unit size at unit distance):
// penumbra::shadows::perspectiveSearchTexels, perspectivePenumbraTexels.
float perspectiveSearchTexels(float receiver, float nearPlane, float lightTexels, SoftControls c)
{
    return clamp(c.searchScale * lightTexels * max(receiver - nearPlane, 0.0) / (receiver * nearPlane), 1.0,
                 max(c.maxTexels, 1.0));
}

float perspectivePenumbraTexels(float receiver, float blocker, float lightTexels, SoftControls c)
{
    return c.penumbraScale * lightTexels * max(receiver - blocker, 0.0) / (blocker * receiver);
}

// PerspectiveTileSoft, the tile's soft data, is generated from penumbra::shadows::PerspectiveTileSoft.
float perspectiveSoftShadow(sampler2D atlas, SoftTile t, int filterIndex, SoftControls c, PerspectiveTileSoft tileSoft)
{
    float radius = c.poissonRadius;
    if (filterIndex == PENUMBRA_FILTER_PCSS) {
        const float receiver = perspectiveDistance(t.depth, tileSoft.depthRow);
        float within = perspectiveSearchTexels(receiver, tileSoft.nearPlane, tileSoft.lightTexels, c);
        vec3 found = vec3(0.0);
        for (int searchStep = 0; searchStep < PCSS_SEARCH_STEPS; ++searchStep) {
            found = searchBlockers(atlas, t, within, c.blockerSamples);
            if (found.y == 0.0)
                return 1.0;
            // The nearest blocker's cone: the search formula with that blocker in place of the near plane.
            if (searchStep == 0)
                within = min(perspectiveSearchTexels(receiver, perspectiveDistance(found.z, tileSoft.depthRow),
                                                     tileSoft.lightTexels, c),
                             within);
        }
        const float blocker = perspectiveDistance(found.x, tileSoft.depthRow);
        radius = diskRadius(perspectivePenumbraTexels(receiver, blocker, tileSoft.lightTexels, c),
                            PENUMBRA_BILINEAR_TAP_VARIANCE, c);
        if (inUmbra(found.xy, c.blockerSamples, radius, within))
            return 0.0;
    }
    return poissonFilter(atlas, t, radius, c.filterSamples);
}

// Screen derivatives of a perspective shadow-map position m * (p, 1) / w, from those of p (receiverDx, receiverDy).
vec3 projectedDerivative(mat4 m, vec4 projected, vec3 dp)
{
    const vec4 d = m * vec4(dp, 0.0);
    return (d.xyz - projected.xyz / projected.w * d.w) / projected.w;
}
