// The per-instance vertex data of every pass that draws scene meshes (penumbra::shadows::InstanceTransform): one
// instanced draw places every copy of a mesh.

#include "instance_constants.glsl"

layout(location = PENUMBRA_LOCATION_INSTANCE_MODEL) in mat4 instanceModel;
// The inverse transpose of the model matrix's upper 3 x 3, as columns; column 0's w: the sign of det(model).
layout(location = PENUMBRA_LOCATION_INSTANCE_NORMAL) in mat3x4 instanceNormal;

mat3 instanceNormalMatrix() { return mat3(instanceNormal); }

float instanceHandedness() { return instanceNormal[0].w; }
