// The per-instance vertex data of every pass that draws scene meshes (penumbra::shadows::InstanceTransform): one
// instanced draw places every copy of a mesh.

#include "instance_constants.glsl"

// The model matrix's first three rows, as the columns of a mat3x4; its last row is (0, 0, 0, 1).
layout(location = PENUMBRA_LOCATION_INSTANCE_ROWS) in mat3x4 instanceRows;

// mat4(mat3x4) sets the fourth column to (0, 0, 0, 1): the last row, once transposed.
mat4 instanceModel() { return transpose(mat4(instanceRows)); }

// cross(a, b) rounded alike by both backends' compilers (transform.glsl says why): a product, then one fused
// multiply-add.
vec3 instanceCross(vec3 a, vec3 b)
{
    precise vec3 result = fma(a.yzx, b.zxy, -(a.zxy * b.yzx));
    return result;
}

// The upper 3 x 3's cofactors, as columns: cross(m1, m2), cross(m2, m0), cross(m0, m1), which is det(m) times the
// inverse transpose and transforms normals with no division (Akenine-Moller et al., "Real-Time Rendering", 4th ed.,
// section 4.1.7, "Normal Transform").
mat3 instanceCofactors()
{
    const mat3 m = mat3(instanceModel());
    return mat3(instanceCross(m[1], m[2]), instanceCross(m[2], m[0]), instanceCross(m[0], m[1]));
}

// The sign of det(model): -1 where the transform mirrors (and reverses the bitangent), else 1.
float instanceHandedness()
{
    const mat3 m = mat3(instanceModel());
    precise float det = dot(m[0], instanceCross(m[1], m[2]));
    return det < 0.0 ? -1.0 : 1.0;
}

// The normal matrix up to a positive scale, |det(model)| times the inverse transpose: normals are normalized where
// they are used.
mat3 instanceNormalMatrix() { return instanceCofactors() * instanceHandedness(); }
