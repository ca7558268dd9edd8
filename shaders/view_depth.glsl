// The view depth that contact shadows march through and upsample by (penumbra::render::ContactShadowPass): the
// fragment's clip w, the distance along the camera's forward, as the rasterizer interpolated it (gl_FragCoord.w holds
// 1 / w_c, GLSL 4.50 section 7.1.2). No depth convention touches it: the depth range, reversed-Z and the depth
// buffer's rounding change z alone, while x, y and w of every clip position are the same in every configuration, so
// the same triangles give the same view depth bit for bit where a depth read back from the depth buffer would not
// (docs/notes/2026-12-07-contact-parity-cost.md).
float fragmentViewDepth() { return 1.0 / gl_FragCoord.w; }

// What the prepass writes for contact shadows: the view depth, negated on alpha-tested surfaces. Those are mostly
// cards without thickness (leaves, grilles), and a depth buffer cannot tell what lies behind a card: a march passing
// behind one in view, within the thickness band, would count it without meeting it. So the march counts a card only
// where its ray crosses one between two samples (contact_shadows.frag). 0 stays "no surface".
float prepassViewDepth(bool alphaTested) { return alphaTested ? -fragmentViewDepth() : fragmentViewDepth(); }
