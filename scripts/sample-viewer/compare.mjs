// Renders glTF files with the Khronos glTF Sample Viewer (render-viewer.mjs) and with `penumbra render` on Vulkan
// and OpenGL at the same size, camera (the file's camera 0) and lights (the file's KHR_lights_punctual ones, and
// with --ibl on the same environment on both sides, else no image-based or ambient light), and writes for each file
// OUT/<name>/{viewer,penumbra-vulkan,penumbra-opengl,side-by-side}.png, then OUT/results.json and OUT/results.md with
// the differences in 8-bit units.
//   node compare.mjs [--size WxH] [--out DIR] [--penumbra PATH] [--shadows on|off] [--ibl on|off] [--anisotropy N]
//                    [--scenes] FILE.glb...
// --scenes adds scenes.mjs's feature scenes. --shadows off (the default) marks every node castShadows "off"
// (Penumbra's node extras, ignored by the viewer), as the viewer draws no shadows. --anisotropy goes to penumbra
// render (its default when not given). --ibl on writes environment.mjs's sky as OUT/environment.hdr and lights
// both sides with it: the viewer's image-based lighting (its own prefiltering) and `penumbra render --environment`.
// Besides the viewer's own picture, "viewer-srgb" is the viewer's picture re-encoded from its pow(1/2.2) curve to
// the exact sRGB curve (IEC 61966-2-1) that penumbra writes, background pixels left as they are: its numbers
// separate shading differences from the two encodings.
import fs from "node:fs";
import path from "node:path";
import { execFileSync } from "node:child_process";
import { PNG } from "pngjs";
import { encodeGlb, readGltf } from "./glb.mjs";
import { renderWithSampleViewer } from "./render-viewer.mjs";
import { writeEnvironment } from "./environment.mjs";
import { writeScenes } from "./scenes.mjs";

// penumbra render's background, sRGB-encoded (kBackground in render/src/SceneRenderer.cpp).
const background = [0.2, 0.22, 0.26];
const thresholds = [8, 16];

function parseArguments(argv) {
    const options = { size: "640x360", out: "out/sample-viewer", penumbra: "build/bin/penumbra", shadows: "off", ibl: "off",
                      anisotropy: null, scenes: false, files: [] };
    for (let i = 0; i < argv.length; ++i) {
        const flag = argv[i];
        if (flag === "--scenes")
            options.scenes = true;
        else if (["--size", "--out", "--penumbra", "--shadows", "--ibl", "--anisotropy"].includes(flag) && i + 1 < argv.length)
            options[flag.slice(2)] = argv[++i];
        else if (flag.startsWith("--"))
            throw new Error(`unknown option ${flag}`);
        else
            options.files.push(flag);
    }
    const size = options.size.match(/^(\d+)x(\d+)$/);
    if (!size)
        throw new Error(`--size: expected WIDTHxHEIGHT, got ${options.size}`);
    [options.width, options.height] = [Number(size[1]), Number(size[2])];
    if (!["on", "off"].includes(options.shadows))
        throw new Error(`--shadows: expected on or off, got ${options.shadows}`);
    if (!["on", "off"].includes(options.ibl))
        throw new Error(`--ibl: expected on or off, got ${options.ibl}`);
    return options;
}

// The file both renderers draw: the original, with castShadows "off" on every scene root when shadows are off
// (the setting is inherited by children). External buffers and images are copied beside it.
function prepare(file, dir, shadows) {
    const { json, bin } = readGltf(file);
    if (shadows === "off")
        for (const root of json.scenes?.[json.scene ?? 0]?.nodes ?? []) {
            const node = json.nodes[root];
            node.extras = { ...node.extras, penumbra: { ...node.extras?.penumbra, castShadows: "off" } };
        }
    for (const resource of [...(json.buffers ?? []), ...(json.images ?? [])])
        if (resource.uri && !resource.uri.startsWith("data:"))
            fs.copyFileSync(path.resolve(path.dirname(file), decodeURIComponent(resource.uri)),
                            path.join(dir, decodeURIComponent(resource.uri)));
    const out = path.join(dir, "scene.glb");
    fs.writeFileSync(out, encodeGlb(json, bin));
    return { file: out, json, bin };
}

// The name `penumbra render --camera` takes for the file's camera 0: the camera's, else its node's.
function cameraName(json) {
    if (!json.cameras?.length)
        throw new Error("the file has no camera: the comparison needs camera 0 on both sides");
    if (json.cameras[0].name)
        return json.cameras[0].name;
    const node = json.nodes.find((n) => n.camera === 0);
    if (!node?.name)
        throw new Error("camera 0 and its node have no name for penumbra render --camera");
    return node.name;
}

// ---- Where each mesh node lands in the picture, for per-object numbers: the convex hull of its boxes' corners.

function multiply(a, b) {
    const out = new Array(16).fill(0);
    for (let c = 0; c < 4; ++c)
        for (let r = 0; r < 4; ++r)
            for (let k = 0; k < 4; ++k)
                out[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
    return out;
}

// glTF 2.0 section 3.5.3: a node's matrix, or T * R * S (column-major).
function localMatrix(node) {
    if (node.matrix)
        return node.matrix;
    const [x, y, z, w] = node.rotation ?? [0, 0, 0, 1];
    const [sx, sy, sz] = node.scale ?? [1, 1, 1];
    const [tx, ty, tz] = node.translation ?? [0, 0, 0];
    return [(1 - 2 * (y * y + z * z)) * sx, 2 * (x * y + z * w) * sx, 2 * (x * z - y * w) * sx, 0,
            2 * (x * y - z * w) * sy, (1 - 2 * (x * x + z * z)) * sy, 2 * (y * z + x * w) * sy, 0,
            2 * (x * z + y * w) * sz, 2 * (y * z - x * w) * sz, (1 - 2 * (x * x + y * y)) * sz, 0, tx, ty, tz, 1];
}

function worldMatrices(json) {
    const world = new Map();
    const visit = (index, parent) => {
        const matrix = multiply(parent, localMatrix(json.nodes[index]));
        world.set(index, matrix);
        for (const child of json.nodes[index].children ?? [])
            visit(child, matrix);
    };
    const identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
    for (const root of json.scenes[json.scene ?? 0].nodes)
        visit(root, identity);
    return world;
}

function transform(m, [x, y, z]) {
    return [0, 1, 2, 3].map((r) => m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
}

function hull(points) {
    const sorted = [...points].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
    const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    const half = (list) => {
        const out = [];
        for (const p of list) {
            while (out.length >= 2 && cross(out[out.length - 2], out[out.length - 1], p) <= 0)
                out.pop();
            out.push(p);
        }
        return out.slice(0, -1);
    };
    return [...half(sorted), ...half([...sorted].reverse())];
}

function inside(polygon, x, y) {
    let crossings = false;
    for (let i = 0, j = polygon.length - 1; i < polygon.length; j = i++) {
        const [xi, yi] = polygon[i], [xj, yj] = polygon[j];
        if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi)
            crossings = !crossings;
    }
    return crossings;
}

// Pixel masks of each named mesh node over the camera's perspective (glTF 2.0 section 3.10.2: yfov, the
// picture's aspect ratio when the camera gives none).
function regions(json, width, height) {
    const world = worldMatrices(json);
    const cameraNode = json.nodes.findIndex((n) => n.camera === 0);
    const camera = world.get(cameraNode);
    // The camera's view matrix: the inverse of its rigid world transform.
    const axes = [0, 1, 2].map((c) => {
        const v = camera.slice(c * 4, c * 4 + 3);
        const length = Math.hypot(...v);
        return v.map((x) => x / length);
    });
    const eye = camera.slice(12, 15);
    const perspective = json.cameras[0].perspective;
    const f = 1 / Math.tan(perspective.yfov / 2);
    const aspect = perspective.aspectRatio ?? width / height;
    const out = [];
    for (const [index, matrix] of world) {
        const node = json.nodes[index];
        if (node.mesh === undefined)
            continue;
        const pixels = [];
        let visible = true;
        for (const primitive of json.meshes[node.mesh].primitives) {
            const { min, max } = json.accessors[primitive.attributes.POSITION];
            for (let corner = 0; corner < 8; ++corner) {
                const p = transform(matrix, [corner & 1 ? max[0] : min[0], corner & 2 ? max[1] : min[1],
                                             corner & 4 ? max[2] : min[2]]);
                const d = [0, 1, 2].map((i) => p[i] - eye[i]);
                const [vx, vy, vz] = axes.map((axis) => axis[0] * d[0] + axis[1] * d[1] + axis[2] * d[2]);
                if (vz > -perspective.znear) {
                    visible = false;
                    break;
                }
                pixels.push([(0.5 + (0.5 * f * vx) / (aspect * -vz)) * width, (0.5 - (0.5 * f * vy) / -vz) * height]);
            }
        }
        if (!visible)
            continue;
        const polygon = hull(pixels);
        const mask = new Uint8Array(width * height);
        let count = 0;
        for (let y = 0; y < height; ++y)
            for (let x = 0; x < width; ++x)
                if (inside(polygon, x + 0.5, y + 0.5)) {
                    mask[y * width + x] = 1;
                    ++count;
                }
        if (count > 0)
            out.push({ name: node.name ?? `node ${index}`, mask, pixels: count });
    }
    return out;
}

// ---- Numbers and pictures.

// The viewer's toneMap NONE writes pow(linear, 1 / 2.2) (tonemapping.glsl linearTosRGB); this re-encodes each
// channel with the sRGB curve. Pixels still at the clear colour were never shaded and stay.
function reencodeSrgb(picture, clear) {
    const table = Array.from({ length: 256 }, (_, v) => {
        const linear = Math.pow(v / 255, 2.2);
        const srgb = linear <= 0.0031308 ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
        return Math.round(srgb * 255);
    });
    const out = new PNG({ width: picture.width, height: picture.height });
    picture.data.copy(out.data);
    const background = clear.map((c) => Math.round(c * 255));
    for (let i = 0; i < out.data.length; i += 4)
        if (![0, 1, 2].every((c) => out.data[i + c] === background[c]))
            for (let c = 0; c < 3; ++c)
                out.data[i + c] = table[out.data[i + c]];
    return out;
}

function readPng(file) { return PNG.sync.read(fs.readFileSync(file)); }

// Mean absolute difference per channel (8-bit units) and the fraction of pixels whose largest channel
// difference exceeds each threshold, over the mask's pixels (all when none).
function difference(a, b, mask) {
    const sum = [0, 0, 0];
    const over = thresholds.map(() => 0);
    let count = 0;
    for (let i = 0; i < a.width * a.height; ++i) {
        if (mask && !mask[i])
            continue;
        let largest = 0;
        for (let c = 0; c < 3; ++c) {
            const d = Math.abs(a.data[4 * i + c] - b.data[4 * i + c]);
            sum[c] += d;
            largest = Math.max(largest, d);
        }
        thresholds.forEach((t, k) => { if (largest > t) ++over[k]; });
        ++count;
    }
    const round = (x, digits) => Number(x.toFixed(digits));
    return { mad: sum.map((s) => round(s / count, 2)),
             ...Object.fromEntries(thresholds.map((t, k) => [`over${t}`, round(over[k] / count, 4)])) };
}

// Mean colour (8-bit) over the mask, to say which side is brighter.
function meanColour(picture, mask) {
    const sum = [0, 0, 0];
    let count = 0;
    for (let i = 0; i < picture.width * picture.height; ++i)
        if (!mask || mask[i]) {
            for (let c = 0; c < 3; ++c)
                sum[c] += picture.data[4 * i + c];
            ++count;
        }
    return sum.map((s) => Number((s / count).toFixed(1)));
}

// viewer | penumbra vulkan | penumbra opengl | |viewer - vulkan| x 4, 4 black pixels apart.
function sideBySide(file, pictures, amplify = 4) {
    const [viewer, vulkan] = pictures;
    const diff = new PNG({ width: viewer.width, height: viewer.height });
    for (let i = 0; i < viewer.data.length; i += 4) {
        for (let c = 0; c < 3; ++c)
            diff.data[i + c] = Math.min(255, amplify * Math.abs(viewer.data[i + c] - vulkan.data[i + c]));
        diff.data[i + 3] = 255;
    }
    const all = [...pictures, diff];
    const gap = 4;
    const out = new PNG({ width: all.length * viewer.width + (all.length - 1) * gap, height: viewer.height });
    out.data.fill(0);
    for (let i = 3; i < out.data.length; i += 4)
        out.data[i] = 255;
    all.forEach((picture, k) => PNG.bitblt(picture, out, 0, 0, picture.width, picture.height, k * (viewer.width + gap), 0));
    fs.writeFileSync(file, PNG.sync.write(out));
}

function table(results) {
    const rows = ["| file | region | pair | MAD R | MAD G | MAD B | > 8/255 | > 16/255 | mean first | mean second |",
                  "|---|---|---|---|---|---|---|---|---|---|"];
    for (const result of results)
        for (const region of [{ name: "whole picture", ...result.whole }, ...result.regions])
            for (const [pair, numbers] of Object.entries(region.pairs))
                rows.push(`| ${result.name} | ${region.name} | ${pair} | ${numbers.mad.join(" | ")} | ` +
                          `${(100 * numbers.over8).toFixed(1)}% | ${(100 * numbers.over16).toFixed(1)}% | ` +
                          `${pair.split(" vs ").map((side) => region.mean[side].join(", ")).join(" | ")} |`);
    return rows.join("\n") + "\n";
}

async function main() {
    const options = parseArguments(process.argv.slice(2));
    fs.mkdirSync(options.out, { recursive: true });
    const files = [...options.files];
    if (options.scenes)
        files.push(...writeScenes(path.join(options.out, "scenes")));
    if (files.length === 0)
        throw new Error("no glTF files given (and no --scenes)");
    const penumbra = path.resolve(options.penumbra);
    const environment = options.ibl === "on" ? writeEnvironment(path.join(options.out, "environment.hdr")) : null;
    // Without an environment, no ambient light either: the viewer has none with image-based lighting off.
    const lighting = environment ? ["--environment", environment] : ["--ambient", "0,0,0:0"];
    const jobs = files.map((file) => {
        const name = path.basename(file).replace(/\.(glb|gltf)$/, "");
        const dir = path.join(options.out, name);
        fs.mkdirSync(dir, { recursive: true });
        return { name, dir, source: file, ...prepare(file, dir, options.shadows) };
    });
    for (const job of jobs) {
        const anisotropy = options.anisotropy === null ? [] : ["--anisotropy", options.anisotropy];
        execFileSync(penumbra, ["render", "--scene", job.file, "--camera", cameraName(job.json), ...lighting,
                                "--size", options.size, "--backend", "vulkan,opengl", ...anisotropy,
                                "--out", path.join(job.dir, "penumbra.png")], { stdio: ["ignore", "ignore", "inherit"] });
    }
    const webgl = await renderWithSampleViewer(jobs.map((job) => ({
        model: job.file, out: path.join(job.dir, "viewer.png"), width: options.width, height: options.height,
        camera: 0, clear: background, environment })));
    const results = jobs.map((job) => {
        const pictures = ["viewer", "penumbra-vulkan", "penumbra-opengl"].map((p) => readPng(path.join(job.dir, `${p}.png`)));
        const [viewer, vulkan, opengl] = pictures;
        sideBySide(path.join(job.dir, "side-by-side.png"), pictures);
        const srgb = reencodeSrgb(viewer, background);
        fs.writeFileSync(path.join(job.dir, "viewer-srgb.png"), PNG.sync.write(srgb));
        const measure = (mask) => ({
            pairs: { "viewer vs vulkan": difference(viewer, vulkan, mask), "viewer vs opengl": difference(viewer, opengl, mask),
                     "viewer-srgb vs vulkan": difference(srgb, vulkan, mask),
                     "vulkan vs opengl": difference(vulkan, opengl, mask) },
            mean: { viewer: meanColour(viewer, mask), "viewer-srgb": meanColour(srgb, mask), vulkan: meanColour(vulkan, mask),
                    opengl: meanColour(opengl, mask) },
        });
        return { name: job.name, file: job.source, camera: cameraName(job.json), whole: measure(null),
                 regions: regions(job.json, options.width, options.height).map((r) => ({ name: r.name, pixels: r.pixels,
                                                                                          ...measure(r.mask) })) };
    });
    const report = { sampleViewer: "@khronosgroup/gltf-viewer " +
                         JSON.parse(fs.readFileSync(new URL("./node_modules/@khronosgroup/gltf-viewer/package.json",
                                                            import.meta.url))).version,
                     webgl, size: options.size, shadows: options.shadows,
                     lighting: environment ? `image-based, ${path.basename(environment)} (environment.mjs)` : "ambient 0",
                     anisotropy: options.anisotropy ?? "penumbra render's default", results };
    fs.writeFileSync(path.join(options.out, "results.json"), JSON.stringify(report, null, 1) + "\n");
    fs.writeFileSync(path.join(options.out, "results.md"),
                     `Sample Viewer ${report.sampleViewer} (WebGL: ${webgl}) against penumbra render, ${options.size}, ` +
                     `shadows ${options.shadows}, ${report.lighting}, anisotropy ${report.anisotropy}. MAD: mean absolute difference per channel, 8-bit units; ` +
                     `> 8/255, > 16/255: pixels whose largest channel difference is over that.\n\n` + table(results));
    for (const result of results) {
        const whole = result.whole.pairs;
        console.log(`${result.name}: viewer vs vulkan MAD ${whole["viewer vs vulkan"].mad.join("/")}, ` +
                    `>16: ${(100 * whole["viewer vs vulkan"].over16).toFixed(1)}%; viewer vs opengl MAD ` +
                    `${whole["viewer vs opengl"].mad.join("/")}; vulkan vs opengl MAD ${whole["vulkan vs opengl"].mad.join("/")}`);
    }
    console.log(`wrote ${path.join(options.out, "results.json")}, results.md and <file>/side-by-side.png`);
}

main().catch((error) => {
    console.error(`compare.mjs: ${error.message}`);
    process.exit(1);
});
