// Renders glTF files with the Khronos glTF Sample Viewer's engine (viewer.html) in headless Chromium and writes
// each picture as a PNG. Used by compare.mjs; on its own:
//   node render-viewer.mjs WIDTHxHEIGHT CLEAR_R,G,B MODEL.glb OUT.png [MODEL2 OUT2 ...]
// WebGL2 runs on SwiftShader (Chromium's CPU Vulkan device under ANGLE), so no GPU is needed.
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { PNG } from "pngjs";

const here = path.dirname(fileURLToPath(import.meta.url));
const types = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm",
                ".glb": "model/gltf-binary", ".gltf": "model/gltf+json", ".bin": "application/octet-stream",
                ".png": "image/png", ".jpg": "image/jpeg", ".hdr": "application/octet-stream" };

// Serves this folder under / and the models' folders under /model/<n>/, nothing else.
function serve(modelDirs) {
    const server = http.createServer((request, response) => {
        const url = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
        const match = url.match(/^\/model\/(\d+)\/(.*)$/);
        const root = match ? modelDirs[Number(match[1])] : here;
        const file = path.resolve(root, "." + (match ? "/" + match[2] : url));
        if (!root || !file.startsWith(root + path.sep) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
            response.writeHead(404);
            response.end();
            return;
        }
        response.writeHead(200, { "Content-Type": types[path.extname(file)] ?? "application/octet-stream" });
        fs.createReadStream(file).pipe(response);
    });
    return new Promise((resolve) => server.listen(0, "127.0.0.1", () => resolve(server)));
}

export const chromiumPath = process.env.CHROMIUM ?? "/usr/bin/chromium";

// jobs: [{ model, out, width, height, camera (glTF camera index), clear ([r, g, b] in 0-1), environment (a .hdr
// file for image-based lighting, or none) }]; returns the WebGL renderer string.
export async function renderWithSampleViewer(jobs) {
    const files = jobs.flatMap((job) => (job.environment ? [job.model, job.environment] : [job.model]));
    const modelDirs = [...new Set(files.map((file) => path.dirname(path.resolve(file))))];
    const url = (file) => `/model/${modelDirs.indexOf(path.dirname(path.resolve(file)))}/${path.basename(file)}`;
    const server = await serve(modelDirs);
    const browser = await chromium.launch({
        executablePath: chromiumPath,
        args: ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
               "--no-sandbox"],
    });
    let renderer = "";
    try {
        const page = await browser.newPage();
        const log = [];
        page.on("console", (message) => log.push(`${message.type()}: ${message.text()}`));
        page.on("pageerror", (error) => log.push(`pageerror: ${error}`));
        await page.goto(`http://127.0.0.1:${server.address().port}/viewer.html`);
        await page.waitForFunction(() => window.renderJob !== undefined);
        for (const job of jobs) {
            const query = new URLSearchParams({
                model: url(job.model), width: String(job.width), height: String(job.height),
                camera: String(job.camera ?? 0), clear: (job.clear ?? [0, 0, 0]).join(","),
                ...(job.environment ? { environment: url(job.environment) } : {}),
            });
            // Prefiltering an environment (the first job that names it) runs the viewer's GGX and Lambertian sampling
            // on SwiftShader: minutes.
            const result = await page.evaluate((q) => window.renderJob(q), query.toString());
            if (result.error)
                throw new Error(`Sample Viewer failed on ${job.model}: ${result.error}\n${log.join("\n")}`);
            // The errors expected: no KTX or Draco decoder is loaded (viewer.html); no compared file needs one.
            const expected = /Failed to initalize (KTXDecoder|DracoDecoder)/;
            const errors = log.filter((line) => (line.startsWith("error") || line.startsWith("pageerror")) &&
                                                !expected.test(line));
            if (errors.length > 0)
                throw new Error(`Sample Viewer reported errors on ${job.model}:\n${errors.join("\n")}`);
            log.length = 0;
            renderer = result.renderer;
            writeBottomUp(job.out, result.width, result.height, Buffer.from(result.rgba, "base64"));
        }
    } finally {
        await browser.close();
        server.close();
    }
    return renderer;
}

// gl.readPixels rows run bottom-up; PNG rows top-down.
function writeBottomUp(file, width, height, rgba) {
    const png = new PNG({ width, height });
    const row = width * 4;
    for (let y = 0; y < height; ++y)
        rgba.copy(png.data, y * row, (height - 1 - y) * row, (height - y) * row);
    fs.mkdirSync(path.dirname(path.resolve(file)), { recursive: true });
    fs.writeFileSync(file, PNG.sync.write(png));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
    const [size, clear, ...pairs] = process.argv.slice(2);
    if (!size || !clear || pairs.length === 0 || pairs.length % 2 !== 0) {
        console.error("usage: node render-viewer.mjs WIDTHxHEIGHT R,G,B MODEL OUT.png [MODEL OUT.png ...]");
        process.exit(2);
    }
    const [width, height] = size.split("x").map(Number);
    const jobs = [];
    for (let i = 0; i < pairs.length; i += 2)
        jobs.push({ model: pairs[i], out: pairs[i + 1], width, height, camera: 0, clear: clear.split(",").map(Number) });
    console.log(`WebGL: ${await renderWithSampleViewer(jobs)}`);
}
