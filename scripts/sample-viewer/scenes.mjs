// Writes the small glTF 2.0 scenes of single material features that compare.mjs renders beside
// tests/support/GltfBuilder.cpp's materials scene: each has one camera (index 0) and one directional
// KHR_lights_punctual light, so that the Sample Viewer and penumbra render see the same camera and light.
//   node scenes.mjs OUT_DIR   writes OUT_DIR/<name>.glb for every scene and prints the paths
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { PNG } from "pngjs";
import { encodeGlb } from "./glb.mjs";

// glTF 2.0 section 5.1.3 (accessor.componentType) and section 5.26 (sampler filters and wraps).
const FLOAT = 5126, UNSIGNED_BYTE = 5121, UNSIGNED_SHORT = 5123;
const NEAREST = 9728, LINEAR = 9729, REPEAT = 10497, CLAMP = 33071, MIRROR = 33648;

class Builder {
    constructor() {
        this.json = { asset: { version: "2.0", generator: "penumbra scripts/sample-viewer/scenes.mjs" }, scene: 0,
                      scenes: [{ nodes: [] }], extensionsUsed: ["KHR_lights_punctual"] };
        this.chunks = [];
        this.length = 0;
    }

    add(array, element) {
        (this.json[array] ??= []).push(element);
        return this.json[array].length - 1;
    }

    // Vertex attributes and buffer views start on 4-byte boundaries (glTF 2.0 section 3.6.2.4).
    view(bytes) {
        const pad = (4 - (this.length % 4)) % 4;
        if (pad) {
            this.chunks.push(Buffer.alloc(pad));
            this.length += pad;
        }
        const offset = this.length;
        this.chunks.push(Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength));
        this.length += bytes.byteLength;
        return this.add("bufferViews", { buffer: 0, byteOffset: offset, byteLength: bytes.byteLength });
    }

    accessor(values, type, componentType, extra = {}) {
        const size = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 }[type];
        const Typed = { [FLOAT]: Float32Array, [UNSIGNED_BYTE]: Uint8Array, [UNSIGNED_SHORT]: Uint16Array }[componentType];
        return this.add("accessors", { bufferView: this.view(Typed.from(values)), count: values.length / size, type,
                                       componentType, ...extra });
    }

    positions(values) {
        const min = [0, 1, 2].map((c) => Math.min(...values.filter((_, i) => i % 3 === c)));
        const max = [0, 1, 2].map((c) => Math.max(...values.filter((_, i) => i % 3 === c)));
        return this.accessor(values, "VEC3", FLOAT, { min, max });
    }

    // An RGBA8 picture (rows top-down) as a PNG image in the buffer and a texture over it.
    texture(width, height, texel, sampler) {
        const png = new PNG({ width, height });
        for (let y = 0; y < height; ++y)
            for (let x = 0; x < width; ++x)
                png.data.set(texel(x, y), 4 * (y * width + x));
        const image = this.add("images", { bufferView: this.view(PNG.sync.write(png)), mimeType: "image/png" });
        const texture = { source: image };
        if (sampler)
            texture.sampler = this.add("samplers", sampler);
        return this.add("textures", texture);
    }

    material(material) { return this.add("materials", material); }

    root(node) { this.json.scenes[0].nodes.push(this.add("nodes", node)); }

    // A directional light along `direction` (it shines that way) and a camera at `eye` looking down -z.
    lightAndCamera(direction, eye, intensity = 3.0) {
        this.json.extensions = { KHR_lights_punctual: { lights: [{ name: "sun", type: "directional", intensity }] } };
        this.root({ name: "sun", rotation: rotationFromMinusZ(direction),
                    extensions: { KHR_lights_punctual: { light: 0 } } });
        this.add("cameras", { name: "view", type: "perspective", perspective: { yfov: 0.6, znear: 0.1, zfar: 100 } });
        this.root({ name: "view camera", camera: 0, translation: eye });
    }

    use(extension) {
        if (!this.json.extensionsUsed.includes(extension))
            this.json.extensionsUsed.push(extension);
    }

    glb() {
        this.json.buffers = [{ byteLength: this.length }];
        return encodeGlb(this.json, Buffer.concat(this.chunks));
    }
}

// The unit quaternion [x, y, z, w] turning -z (a light's and a camera's forward, KHR_lights_punctual) onto `d`.
function rotationFromMinusZ(d) {
    const length = Math.hypot(...d);
    const to = d.map((c) => c / length);
    const from = [0, 0, -1];
    const axis = [from[1] * to[2] - from[2] * to[1], from[2] * to[0] - from[0] * to[2], from[0] * to[1] - from[1] * to[0]];
    const w = 1 + from[0] * to[0] + from[1] * to[1] + from[2] * to[2];
    const norm = Math.hypot(...axis, w);
    return [...axis, w].map((c) => c / norm);
}

// A 2 x 2 quad in the xy plane facing +z, uv (0, 0) at the top left corner, as GltfBuilder's addQuadMesh:
// `extra(attributes, corners)` adds attributes; `uv` maps each corner's (u, v).
function quad(b, name, material, { uv = (u, v) => [u, v], extra = () => {} } = {}) {
    const corners = [[-1, 1], [1, 1], [1, -1], [-1, -1]];
    const base = [[0, 0], [1, 0], [1, 1], [0, 1]];
    const attributes = {
        POSITION: b.positions(corners.flatMap(([x, y]) => [x, y, 0])),
        NORMAL: b.accessor(corners.flatMap(() => [0, 0, 1]), "VEC3", FLOAT),
        TEXCOORD_0: b.accessor(base.flatMap(([u, v]) => uv(u, v)), "VEC2", FLOAT),
    };
    extra(attributes, base);
    const indices = b.accessor([0, 3, 2, 0, 2, 1], "SCALAR", UNSIGNED_SHORT);
    return b.add("meshes", { name, primitives: [{ attributes, indices, material }] });
}

// A UV sphere of radius 1: `rings` bands of latitude, `segments` of longitude.
function sphere(b, name, material, rings = 32, segments = 64) {
    const positions = [], normals = [], uvs = [], indices = [];
    for (let r = 0; r <= rings; ++r)
        for (let s = 0; s <= segments; ++s) {
            const theta = (Math.PI * r) / rings, phi = (2 * Math.PI * s) / segments;
            const n = [Math.sin(theta) * Math.sin(phi), Math.cos(theta), Math.sin(theta) * Math.cos(phi)];
            positions.push(...n);
            normals.push(...n);
            uvs.push(s / segments, r / rings);
        }
    for (let r = 0; r < rings; ++r)
        for (let s = 0; s < segments; ++s) {
            const a = r * (segments + 1) + s, c = a + segments + 1;
            indices.push(a, c, a + 1, a + 1, c, c + 1);
        }
    return b.add("meshes", { name, primitives: [{ attributes: {
        POSITION: b.positions(positions), NORMAL: b.accessor(normals, "VEC3", FLOAT), TEXCOORD_0: b.accessor(uvs, "VEC2", FLOAT),
    }, indices: b.accessor(indices, "SCALAR", UNSIGNED_SHORT), material }] });
}

const pbr = (r, g, bl, metallic, roughness, a = 1) =>
    ({ baseColorFactor: [r, g, bl, a], metallicFactor: metallic, roughnessFactor: roughness });

// Two rows of five spheres, roughness 0.05 to 1: dielectric red above, metal (gold) below. Specular highlight
// size and shape, GGX and Fresnel, metallic's removal of the diffuse term.
function spheres() {
    const b = new Builder();
    const roughness = [0.05, 0.25, 0.5, 0.75, 1.0];
    roughness.forEach((rough, i) => {
        for (const [row, metallic, colour] of [[0, 0, [0.8, 0.1, 0.1]], [1, 1, [1.0, 0.77, 0.34]]]) {
            const material = b.material({ name: `${metallic ? "metal" : "dielectric"} roughness ${rough}`,
                                          pbrMetallicRoughness: pbr(...colour, metallic, rough) });
            b.root({ name: `sphere ${row} ${i}`, mesh: sphere(b, `sphere ${row} ${i}`, material),
                     translation: [(i - 2) * 2.3, row === 0 ? 1.2 : -1.2, 0] });
        }
    });
    b.lightAndCamera([-0.4, -0.5, -1.0], [0, 0, 14]);
    return b;
}

// A 32 x 32 normal texture of one dome (glTF 2.0 section 3.9.3: red X to the right, green Y up the picture, +Z
// out): lit from the upper left, its upper left rim is bright. A flipped green channel lights the lower rim.
function domeNormals(b) {
    return b.texture(32, 32, (x, y) => {
        const s = ((x + 0.5) / 32) * 2 - 1, t = 1 - ((y + 0.5) / 32) * 2;
        const r = Math.hypot(s, t) / 0.8;
        const n = r < 1 ? [s / 0.8 * 0.9, t / 0.8 * 0.9, Math.sqrt(Math.max(0, 1 - 0.81 * r * r))] : [0, 0, 1];
        const l = Math.hypot(...n);
        return [...n.map((c) => Math.round(((c / l) * 0.5 + 0.5) * 255)), 255];
    }, { magFilter: LINEAR, minFilter: LINEAR, wrapS: CLAMP, wrapT: CLAMP });
}

// Four quads with the dome: stored tangents (w = 1), generated tangents, and u mirrored (TEXCOORD_0 u -> 1 - u)
// with stored tangents (-1, 0, 0, w = -1) and generated ones. All four should light alike: the bitangent is
// w * cross(normal, tangent) (section 3.7.2.1), up the picture.
function normalMap() {
    const b = new Builder();
    const texture = domeNormals(b);
    const material = b.material({ name: "dome", pbrMetallicRoughness: pbr(0.8, 0.8, 0.8, 0, 0.5),
                                  normalTexture: { index: texture, scale: 1 } });
    const tangent = (t) => (attributes) => {
        attributes.TANGENT = b.accessor([0, 1, 2, 3].flatMap(() => t), "VEC4", FLOAT);
    };
    const mirrored = (u, v) => [1 - u, v];
    const quads = [["stored tangents", {}, tangent([1, 0, 0, 1])], ["generated tangents", {}, () => {}],
                   ["mirrored, stored tangents", { uv: mirrored }, tangent([-1, 0, 0, -1])],
                   ["mirrored, generated tangents", { uv: mirrored }, () => {}]];
    quads.forEach(([name, options, extra], i) =>
        b.root({ name, mesh: quad(b, name, material, { ...options, extra }), translation: [(i - 1.5) * 2.4, 0, 0] }));
    b.lightAndCamera([0.5, -0.5, -0.7], [0, 0, 11]);
    return b;
}

// Emissive factor alone on black, scaled by KHR_materials_emissive_strength, an emissive texture (sRGB, section
// 3.9.3) times its factor, and emissive added to a lit surface.
function emissive() {
    const b = new Builder();
    b.use("KHR_materials_emissive_strength");
    const gradient = b.texture(8, 1, (x) => [Math.round((x / 7) * 255), 128, 255 - Math.round((x / 7) * 255), 255],
                               { magFilter: NEAREST, minFilter: NEAREST });
    const black = pbr(0, 0, 0, 0, 1);
    const materials = [
        ["factor", { pbrMetallicRoughness: black, emissiveFactor: [1.0, 0.5, 0.1] }],
        ["strength 2.5", { pbrMetallicRoughness: black, emissiveFactor: [0.3, 0.2, 0.1],
                           extensions: { KHR_materials_emissive_strength: { emissiveStrength: 2.5 } } }],
        ["texture", { pbrMetallicRoughness: black, emissiveFactor: [1, 1, 1], emissiveTexture: { index: gradient } }],
        ["lit plus emissive", { pbrMetallicRoughness: pbr(0.5, 0.5, 0.5, 0, 0.6), emissiveFactor: [0.0, 0.15, 0.3] }],
    ];
    materials.forEach(([name, material], i) => {
        const index = b.material({ name, ...material });
        b.root({ name, mesh: quad(b, name, index), translation: [(i - 1.5) * 2.4, 0, 0] });
    });
    b.lightAndCamera([0.3, -0.4, -1], [0, 0, 11]);
    return b;
}

// Vertex colours (section 3.7.2.1, COLOR_0 multiplies the base colour): float RGBA, normalized unsigned byte
// RGBA and normalized unsigned short RGB, a different colour at each corner; the last also times a texture.
function vertexColours() {
    const b = new Builder();
    const corners = [[1, 0.1, 0.1, 1], [0.1, 1, 0.1, 1], [0.1, 0.1, 1, 1], [1, 1, 0.1, 1]];
    const stripes = b.texture(2, 1, (x) => (x ? [255, 255, 255, 255] : [128, 128, 128, 255]),
                              { magFilter: NEAREST, minFilter: NEAREST });
    const white = b.material({ name: "white", pbrMetallicRoughness: pbr(1, 1, 1, 0, 0.6) });
    const textured = b.material({ name: "textured", pbrMetallicRoughness: { ...pbr(1, 1, 1, 0, 0.6),
                                                                             baseColorTexture: { index: stripes } } });
    const colour = (component) => (attributes) => {
        if (component === FLOAT)
            attributes.COLOR_0 = b.accessor(corners.flat(), "VEC4", FLOAT);
        else if (component === UNSIGNED_BYTE)
            attributes.COLOR_0 = b.accessor(corners.flat().map((c) => Math.round(c * 255)), "VEC4", UNSIGNED_BYTE,
                                            { normalized: true });
        else {
            // 6 bytes of RGB and 2 of padding per vertex: attributes start on 4-byte boundaries.
            const padded = corners.flatMap((c) => [...c.slice(0, 3).map((x) => Math.round(x * 65535)), 0]);
            attributes.COLOR_0 = b.accessor(padded, "VEC3", UNSIGNED_SHORT, { normalized: true });
            const accessor = b.json.accessors[attributes.COLOR_0];
            accessor.count = 4;
            b.json.bufferViews[accessor.bufferView].byteStride = 8;
        }
    };
    const quads = [["float rgba", white, FLOAT], ["ubyte rgba", white, UNSIGNED_BYTE],
                   ["ushort rgb", white, UNSIGNED_SHORT], ["ushort rgb textured", textured, UNSIGNED_SHORT]];
    quads.forEach(([name, material, component], i) =>
        b.root({ name, mesh: quad(b, name, material, { extra: colour(component) }),
                 translation: [(i - 1.5) * 2.4, 0, 0] }));
    b.lightAndCamera([0.3, -0.4, -1], [0, 0, 11]);
    return b;
}

// An 8 x 8 picture that shows its orientation: a red top-left quarter, green top-right, blue bottom-left, a grey
// checker bottom-right, nearest filtered.
function orientedPicture(b, sampler) {
    return b.texture(8, 8, (x, y) => {
        if (x < 4 && y < 4) return [230, 30, 30, 255];
        if (y < 4) return [30, 200, 30, 255];
        if (x < 4) return [30, 60, 230, 255];
        return (x + y) % 2 ? [240, 240, 240, 255] : [60, 60, 60, 255];
    }, { magFilter: NEAREST, minFilter: NEAREST, ...sampler });
}

// KHR_texture_transform (offset, rotation, scale; its texCoord override) and TEXCOORD_1, top row; sampler wrap
// modes (section 5.26) and filters over uvs from -1 to 2, bottom row.
function textureTransforms() {
    const b = new Builder();
    b.use("KHR_texture_transform");
    const picture = orientedPicture(b, { wrapS: REPEAT, wrapT: REPEAT });
    const textured = (name, textureInfo) => b.material({ name, pbrMetallicRoughness: {
        ...pbr(1, 1, 1, 0, 0.8), baseColorTexture: { index: picture, ...textureInfo } } });
    const transform = (t) => ({ extensions: { KHR_texture_transform: t } });
    const uv1 = (attributes, base) => {
        attributes.TEXCOORD_1 = b.accessor(base.flatMap(([u, v]) => [v, u]), "VEC2", FLOAT);
    };
    const top = [
        ["plain", textured("plain", {})],
        ["offset 0.25, 0", textured("offset", transform({ offset: [0.25, 0] }))],
        ["rotation 0.5", textured("rotation", transform({ rotation: 0.5 }))],
        ["scale 2, 1", textured("scale", transform({ scale: [2, 1] }))],
        ["texCoord 1 (u, v swapped)", textured("texCoord 1", { texCoord: 1 })],
        ["transform texCoord 1", textured("transform texCoord 1", transform({ texCoord: 1, offset: [0, 0.25] }))],
    ];
    top.forEach(([name, material], i) =>
        b.root({ name, mesh: quad(b, name, material, { extra: uv1 }), translation: [(i - 2.5) * 2.3, 1.2, 0] }));
    const wide = (u, v) => [u * 3 - 1, v * 3 - 1];
    const samplers = [
        ["repeat", { wrapS: REPEAT, wrapT: REPEAT }], ["clamp", { wrapS: CLAMP, wrapT: CLAMP }],
        ["mirrored repeat", { wrapS: MIRROR, wrapT: MIRROR }], ["repeat s, mirror t", { wrapS: REPEAT, wrapT: MIRROR }],
        ["linear, clamp", { wrapS: CLAMP, wrapT: CLAMP, magFilter: LINEAR, minFilter: LINEAR }],
        ["no sampler (repeat, auto filter)", null],
    ];
    samplers.forEach(([name, sampler], i) => {
        const texture = sampler ? orientedPicture(b, sampler) : b.add("textures", { source: b.json.textures[picture].source });
        const material = b.material({ name, pbrMetallicRoughness: { ...pbr(1, 1, 1, 0, 0.8), baseColorTexture: { index: texture } } });
        b.root({ name, mesh: quad(b, name, material, { uv: wide }), translation: [(i - 2.5) * 2.3, -1.2, 0] });
    });
    b.lightAndCamera([0.2, -0.3, -1], [0, 0, 13.5], 3.14159);
    return b;
}

// Alpha modes (section 3.9.4) over a horizontal alpha ramp: OPAQUE ignores alpha, MASK at cutoffs 0.5 (default) and
// 0.25, BLEND over a bar behind; and the back faces of a single-sided (culled) and a double-sided quad.
function alphaAndSides() {
    const b = new Builder();
    const ramp = b.texture(16, 1, (x) => [200, 120, 40, Math.round((x / 15) * 255)],
                           { magFilter: NEAREST, minFilter: NEAREST, wrapS: CLAMP, wrapT: CLAMP });
    const ramped = (name, extra) => b.material({ name, ...extra, pbrMetallicRoughness: {
        ...pbr(1, 1, 1, 0, 0.6), baseColorTexture: { index: ramp } } });
    const quads = [["opaque", ramped("opaque", {})], ["mask 0.5", ramped("mask", { alphaMode: "MASK" })],
                   ["mask 0.25", ramped("mask 0.25", { alphaMode: "MASK", alphaCutoff: 0.25 })],
                   ["blend", ramped("blend", { alphaMode: "BLEND" })]];
    quads.forEach(([name, material], i) =>
        b.root({ name, mesh: quad(b, name, material), translation: [(i - 2) * 2.3, 1.2, 0] }));
    const bar = b.material({ name: "bar", pbrMetallicRoughness: pbr(0.1, 0.3, 0.8, 0, 0.6) });
    b.root({ name: "bar behind", mesh: quad(b, "bar", bar), translation: [-0.2, 1.2, -1.5], scale: [6, 0.25, 1] });
    // Half a turn about y: the quads' back faces look at the camera.
    const halfTurn = [0, 1, 0, 0];
    const single = b.material({ name: "single-sided", pbrMetallicRoughness: pbr(0.2, 0.8, 0.2, 0, 0.6) });
    const double = b.material({ name: "double-sided", doubleSided: true, pbrMetallicRoughness: pbr(0.8, 0.2, 0.8, 0, 0.6) });
    b.root({ name: "single-sided from behind", mesh: quad(b, "single-sided", single), translation: [-1.2, -1.3, 0],
             rotation: halfTurn });
    b.root({ name: "double-sided from behind", mesh: quad(b, "double-sided", double), translation: [1.2, -1.3, 0],
             rotation: halfTurn });
    // Lit from the camera's side: the double-sided back face is lit through its flipped normal (section 3.9.5).
    b.lightAndCamera([0.3, -0.4, -1], [0, 0, 13]);
    return b;
}

export const scenes = { spheres, "normal-map": normalMap, emissive, "vertex-colours": vertexColours,
                        "texture-transform": textureTransforms, "alpha-sides": alphaAndSides };

export function writeScenes(dir) {
    fs.mkdirSync(dir, { recursive: true });
    return Object.entries(scenes).map(([name, make]) => {
        const file = path.join(dir, `${name}.glb`);
        fs.writeFileSync(file, make().glb());
        return file;
    });
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
    if (process.argv.length !== 3) {
        console.error("usage: node scenes.mjs OUT_DIR");
        process.exit(2);
    }
    for (const file of writeScenes(process.argv[2]))
        console.log(file);
}
