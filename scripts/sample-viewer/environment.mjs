// The environment both renderers light with when compare.mjs runs with --ibl on: an equirectangular sky written as
// a Radiance .hdr file, which `penumbra render --environment` and the Sample Viewer's loadEnvironment both read.
// Its radiance depends on the height of the direction alone (a warm horizon, a blue zenith, a dim ground), so it
// looks the same under any turn about +y: the two renderers' azimuth conventions (and the viewer's default
// environmentRotation of 90 degrees) cannot make the sides differ.
import fs from "node:fs";

export const environmentSize = [256, 128];

// Linear radiance looking at height y (-1 to 1).
function sky(y) {
    const horizon = [1.0, 0.9, 0.8], zenith = [0.3, 0.45, 0.9], ground = [0.25, 0.22, 0.2];
    if (y < 0)
        return ground.map((g) => g * (1 + 0.5 * y));
    return horizon.map((h, c) => h + (zenith[c] - h) * Math.sqrt(y));
}

// Radiance RGBE (Ward 1991, "Real Pixels", Graphics Gems II): the largest component's binary exponent + 128 in the
// fourth byte, each component scaled to 256 by it; flat scanlines (no run-length encoding), which both readers take.
function rgbe([r, g, b]) {
    const largest = Math.max(r, g, b);
    if (largest < 1e-32)
        return [0, 0, 0, 0];
    const exponent = Math.floor(Math.log2(largest)) + 1;
    const scale = 256 / Math.pow(2, exponent);
    return [r, g, b].map((c) => Math.min(255, Math.floor(c * scale))).concat(exponent + 128);
}

// Row 0 looks straight up, as both renderers read an equirectangular picture.
export function writeEnvironment(file) {
    const [width, height] = environmentSize;
    const header = Buffer.from(`#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y ${height} +X ${width}\n`, "latin1");
    const texels = Buffer.alloc(width * height * 4);
    for (let row = 0; row < height; ++row) {
        const texel = rgbe(sky(Math.cos((Math.PI * (row + 0.5)) / height)));
        for (let x = 0; x < width; ++x)
            texels.set(texel, 4 * (row * width + x));
    }
    fs.writeFileSync(file, Buffer.concat([header, texels]));
    return file;
}
