// The normal offset of shadow lookups (Castano 2013, "Shadow Mapping Summary - Part 1"), along the geometric normal
// turned towards the light, so that a two-sided surface seen from either side is lifted out of its own shadow. A
// plane at angle theta to the light rises reach * tan(theta) in light depth across a lookup that reaches `reach`
// (world units) around the receiver; moved d along its normal the receiver is d / cos(theta) in front of the plane,
// so d = reach * sin(theta) clears every texel the lookup reads. Receivers add it; casters in the caster-side mode
// subtract it from their vertices instead (shadow_caster.vert). penumbra::shadows::receiverNormalOffset is the same.
vec3 receiverNormalOffset(vec3 geometricNormal, vec3 towardsLight, float reach)
{
    const vec3 n = dot(geometricNormal, towardsLight) < 0.0 ? -geometricNormal : geometricNormal;
    const float cosine = dot(n, towardsLight);
    return n * (reach * sqrt(max(1.0 - cosine * cosine, 0.0)));
}
