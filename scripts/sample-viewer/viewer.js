// window.renderJob(query) renders the glTF file named in the query string (model=URL, width, height, camera=glTF
// camera index, clear=r,g,b in 0-1, environment=URL of a .hdr for image-based lighting, optional) once with the
// Sample Viewer's engine and resolves to
// { width, height, rgba (base64, rows bottom-up as gl.readPixels returns them), renderer } or { error }.
// One page renders every job with one WebGL context, so that an environment is prefiltered once for all of them.
// Set-up, read from the engine's source (dist/gltf-viewer.module.js, GltfState.renderingParameters):
// - without environment=: useIBL false: no image-based light (the USE_IBL define is not set, u_EnvIntensity is 0),
//   an empty stand-in environment (noEnvironment below); with it: useIBL true, the .hdr loaded and prefiltered by
//   the viewer's own loadEnvironment (GGX, Lambertian and Charlie cube maps), iblIntensity 1; renderEnvironmentMap
//   false either way;
// - usePunctual true, useDirectionalLightsWithDisabledIBL false: the file's KHR_lights_punctual lights only,
//   no generated key and fill lights;
// - toneMap NONE, exposure 1: the shader's toneMap() is then linearTosRGB(colour) = pow(colour, 1 / 2.2),
//   clamped by the 8-bit canvas; there is no exact sRGB curve or linear option for the canvas pass;
// - antialias false: one sample per pixel like penumbra render's default --msaa 1.
import { GltfState, GltfView } from "./node_modules/@khronosgroup/gltf-viewer/dist/gltf-viewer.module.js";


// The engine binds an environment's textures for every draw, IBL on or off (gltfRenderer.applyEnvironmentMap reads
// state.environment unguarded). Loading a real one runs its GGX/Lambertian/Charlie filtering on the CPU
// (SwiftShader) for minutes, so this stands in: no textures, so WebGl.setTexture finds none and binds nothing;
// with USE_IBL undefined the shader samples none of them anyway.
const noEnvironment = {
    textures: [], images: [], samplers: [], mipCount: 1, iblIntensityScale: 0,
    diffuseEnvMap: { index: 0 }, specularEnvMap: { index: 0 }, sheenEnvMap: { index: 0 },
    lut: { index: 0 }, sheenLUT: { index: 0 }, sheenELUT: { index: 0 },
};

// A 1 x 1 white PNG (written by pngjs).
const sheenStandIn = "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAAC0lEQVR4AWP4DwQACfsD/c8LaHIAAAAASUVORK5CYII=";

const canvas = document.getElementById("canvas");
const gl = canvas.getContext("webgl2", { antialias: false, alpha: false, preserveDrawingBuffer: true });
const view = gl ? new GltfView(gl) : null;
const loader = view?.createResourceLoader(undefined, undefined, "./node_modules/@khronosgroup/gltf-viewer/dist/libs/");
// Prefiltered environments by URL.
const environments = new Map();

async function render(params) {
    if (!gl)
        throw new Error("no WebGL2 context");
    const width = Number(params.get("width"));
    const height = Number(params.get("height"));
    const camera = Number(params.get("camera") ?? "0");
    const clear = (params.get("clear") ?? "0,0,0").split(",").map(Number);
    canvas.width = width;
    canvas.height = height;
    const state = view.createState();
    // By URL, so that a .gltf file's external buffers and images resolve beside it.
    state.gltf = await loader.loadGltf(params.get("model"));
    const environment = params.get("environment");
    // The sheen albedo table is an image the viewer's web app ships, not its npm package; no compared material has
    // sheen, so a 1 x 1 stand-in fills the slot.
    if (environment && !environments.has(environment))
        environments.set(environment, await loader.loadEnvironment(environment, { lut_sheen_E_file: sheenStandIn }));
    state.environment = environment ? environments.get(environment) : noEnvironment;
    state.sceneIndex = state.gltf.scene ?? 0;
    state.cameraIndex = state.gltf.cameras.length > 0 ? camera : undefined;
    Object.assign(state.renderingParameters, {
        useIBL: environment !== null,
        iblIntensity: 1.0,
        usePunctual: true,
        useDirectionalLightsWithDisabledIBL: false,
        renderEnvironmentMap: false,
        toneMap: GltfState.ToneMaps.NONE,
        exposure: 1.0,
        // Passed to gl.clearColor as it is (GltfRenderer.clearFrame), so in 0-1 despite the doc comment.
        clearColor: [...clear, 1],
    });
    // Textures finish uploading after loadGltf resolves: the frame is drawn until two in a row agree. A picture that
    // never settles is not a reference: it fails rather than handing on whichever frame came last.
    const maxFrames = 20;
    const pixels = new Uint8Array(width * height * 4);
    const previous = new Uint8Array(width * height * 4);
    for (let frame = 0; ; ++frame) {
        view.renderFrame(state, width, height);
        gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        if (frame > 0 && pixels.every((value, i) => value === previous[i]))
            break;
        if (frame + 1 === maxFrames)
            throw new Error(`no two frames in a row agreed in ${maxFrames} frames drawn 100 ms apart`);
        previous.set(pixels);
        await new Promise((resolve) => setTimeout(resolve, 100));
    }
    let binary = "";
    for (let i = 0; i < pixels.length; i += 0x8000)
        binary += String.fromCharCode(...pixels.subarray(i, i + 0x8000));
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    return { width, height, rgba: btoa(binary),
             renderer: info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER) };
}

window.renderJob = (query) =>
    render(new URLSearchParams(query)).catch((error) => ({ error: String((error && error.stack) || error) }));
