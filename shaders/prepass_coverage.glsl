// The depth prepasses' alpha test of clip materials: the lit pass's alpha (lit.frag), cut at the material's cutoff,
// so the lit pass after them needs no discard. Needs lit.glsl and material.glsl first.

layout(location = 2) in vec2 vUv;
layout(location = 3) in vec2 vUv1;
layout(location = 5) in vec4 vColor;

void discardClipHoles()
{
    const bool textured = hasMap(PENUMBRA_TEXTURE_BASE_COLOR);
    const vec2 baseUv = transformedUv(uvRows(PENUMBRA_TEXTURE_BASE_COLOR), vUv, vUv1);
    const float textureAlpha = textured ? texture(coverageMap, baseUv).a : 1.0;
    const float alpha =
        materialAlpha(object.baseColor.a, PENUMBRA_CASTER_CLIP, baseUv, textured, textureAlpha) * vColor.a;
    if (alpha < object.alphaCutoff)
        discard;
}
