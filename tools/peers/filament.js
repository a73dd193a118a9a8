// Filament's web build (its View's ambient occlusion) on one glTF scene (run_engine.mjs drives this
// page through Chromium), with the same window API as peers.js: setupPeers, setEngineView, runEngine.
// The AO alone: Filament has no output of it and applies it to indirect diffuse light only, so the
// scene is drawn lit by a uniform environment alone (spherical harmonics of band 0; the glTF's
// punctual lights removed), every material made diffuse (albedo 0.02, metallic 0, roughness 1, and
// an index of refraction of 1, so no specular: F0 = 0; at that albedo multi-bounce AO changes
// nothing), with post-processing off (no tone mapping, dithering or anti-aliasing: the canvas holds
// linear radiance). The AO is the frame with it over the same frame without it, pixel by pixel.
// glTF is right-handed like Filament: ssaolab's camera, in the file's coordinates, is used as it is.
// Time: the median frame with the AO minus the median frame without, each ended by a 1-pixel
// readPixels, as peers.js times its passes.
/* global Filament */
import { aoBase64, framesDone, median, pageCanvas, readParams, timedFrames, timedJob } from './harness.js';

const ALBEDO = 0.02, LIGHT = 45; // the frame without AO near 0.9 of the canvas's range, never clipped

let engine, scene, view, camera, renderer, swapChain, gl, cfg, defaults, qualityLevels;

window.setupPeers = async (config) => {
    cfg = config;
    const canvas = pageCanvas(cfg.width, cfg.height);
    await new Promise((resolve) => Filament.init([], resolve));
    engine = Filament.Engine.create(canvas, { preserveDrawingBuffer: true, antialias: false });
    gl = canvas.getContext('webgl2'); // the context Filament created
    scene = engine.createScene();
    swapChain = engine.createSwapChain();
    renderer = engine.createRenderer();
    camera = engine.createCamera(Filament.EntityManager.get().create());
    view = engine.createView();
    view.setCamera(camera);
    view.setScene(scene);
    view.setViewport([0, 0, cfg.width, cfg.height]);
    view.setPostProcessingEnabled(false);
    renderer.setClearOptions({ clearColor: [1, 1, 1, 1], clear: true });
    const fetched = new Uint8Array(await (await fetch(cfg.scene)).arrayBuffer());
    const { bytes, meshes, hidden } = aoOnlyScene(fetched);
    const asset = engine.createAssetLoader().createAsset(bytes);
    if (!asset) throw new Error('Filament could not parse the scene');
    const url = new URL(cfg.scene, location.href).href;
    await new Promise((resolve) => asset.loadResources(resolve, null, url.slice(0, url.lastIndexOf('/') + 1), null));
    scene.addEntities(asset.getEntities());
    scene.setIndirectLight(Filament.IndirectLight.Builder().irradianceSh(1, [1, 1, 1]).intensity(LIGHT).build(engine));
    camera.setExposureDirect(1.0);
    defaults = plain(view.setAmbientOcclusionOptionsDefaults({}));
    qualityLevels = Object.values(Filament.View$QualityLevel).filter((v) => typeof v?.value === 'number');
    makeCamera();
    return { renderer: gl.getParameter(gl.RENDERER), three: 'filament (web)', meshes, hidden, flipped: 0 };
};

// Enum members as their numbers: the options as the table reads them.
const plain = (o) => Object.fromEntries(Object.entries(o).map(([k, v]) => [k, typeof v?.value === 'number' ? v.value : v]));

// The glTF with only what the AO alone needs (see the top): every material diffuse at ALBEDO, both
// sides (ssaolab draws every face); a MASK material keeps its base colour texture for its cut-outs;
// BLEND and transmissive surfaces dropped as ssaolab skips them (README, "Transparent surfaces").
function aoOnlyScene(bytes) {
    const glb = new DataView(bytes.buffer, bytes.byteOffset).getUint32(0, true) === 0x46546c67;
    const json = JSON.parse(new TextDecoder().decode(glb ? glbChunks(bytes).json : bytes));
    const dropped = new Set();
    const materials = (json.materials ?? []).map((m, i) => {
        const pbr = m.pbrMetallicRoughness ?? {};
        if (m.alphaMode === 'BLEND' || (m.extensions ?? {}).KHR_materials_transmission) dropped.add(i);
        const out = { pbrMetallicRoughness: { baseColorFactor: [ALBEDO, ALBEDO, ALBEDO, (pbr.baseColorFactor ?? [1, 1, 1, 1])[3]],
                                              metallicFactor: 0, roughnessFactor: 1 },
                      extensions: { KHR_materials_ior: { ior: 1 } }, doubleSided: true };
        if (m.alphaMode === 'MASK') {
            Object.assign(out, { alphaMode: 'MASK', alphaCutoff: m.alphaCutoff ?? 0.5 });
            if (pbr.baseColorTexture) out.pbrMetallicRoughness.baseColorTexture = pbr.baseColorTexture;
        }
        return out;
    });
    const plainMaterial = materials.length;
    materials.push({ pbrMetallicRoughness: { baseColorFactor: [ALBEDO, ALBEDO, ALBEDO, 1], metallicFactor: 0, roughnessFactor: 1 },
                     extensions: { KHR_materials_ior: { ior: 1 } }, doubleSided: true });
    json.materials = materials;
    // Only the cut-outs' textures stay (a file may list a texture whose image it lacks).
    const textures = [];
    for (const m of materials) {
        const t = m.pbrMetallicRoughness.baseColorTexture;
        if (!t) continue;
        const texture = (json.textures ?? [])[t.index];
        if (!texture) throw new Error(`a MASK material names texture ${t.index}, which the file lacks`);
        m.pbrMetallicRoughness.baseColorTexture = { ...t, index: textures.push(texture) - 1 };
    }
    json.textures = textures;
    let meshes = 0, hidden = 0;
    const emptied = new Set();
    (json.meshes ?? []).forEach((mesh, i) => {
        const kept = [];
        for (const p of mesh.primitives ?? []) {
            ++meshes;
            if (dropped.has(p.material)) { ++hidden; continue; }
            kept.push({ ...p, material: p.material ?? plainMaterial });
        }
        if (kept.length) mesh.primitives = kept; else emptied.add(i);
    });
    for (const node of json.nodes ?? []) {
        if (emptied.has(node.mesh)) delete node.mesh;
        if (node.extensions) delete node.extensions.KHR_lights_punctual;
    }
    if (json.extensions) delete json.extensions.KHR_lights_punctual;
    const noLights = (list) => (list ?? []).filter((e) => e !== 'KHR_lights_punctual');
    json.extensionsUsed = [...new Set([...noLights(json.extensionsUsed), 'KHR_materials_ior'])];
    if (json.extensionsRequired) json.extensionsRequired = noLights(json.extensionsRequired);
    const text = new TextEncoder().encode(JSON.stringify(json));
    return { bytes: glb ? glbWith(text, glbChunks(bytes).bin) : text, meshes, hidden };
}

// A GLB's JSON chunk and its binary chunk (or null), as views of `bytes`.
function glbChunks(bytes) {
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const jsonLength = dv.getUint32(12, true);
    const json = bytes.subarray(20, 20 + jsonLength);
    const binAt = 20 + jsonLength;
    const bin = binAt + 8 <= bytes.byteLength ? bytes.subarray(binAt + 8, binAt + 8 + dv.getUint32(binAt, true)) : null;
    return { json, bin };
}

// A GLB of this JSON and binary chunk (each padded to 4 bytes: spaces after JSON, zeros after BIN).
function glbWith(jsonBytes, bin) {
    const pad = (n) => (n + 3) & ~3;
    const jl = pad(jsonBytes.length), bl = bin ? pad(bin.length) : 0;
    const out = new Uint8Array(12 + 8 + jl + (bin ? 8 + bl : 0));
    const dv = new DataView(out.buffer);
    dv.setUint32(0, 0x46546c67, true); dv.setUint32(4, 2, true); dv.setUint32(8, out.length, true);
    dv.setUint32(12, jl, true); dv.setUint32(16, 0x4e4f534a, true);
    out.fill(0x20, 20, 20 + jl);
    out.set(jsonBytes, 20);
    if (bin) {
        dv.setUint32(20 + jl, bl, true); dv.setUint32(24 + jl, 0x004e4942, true);
        out.set(bin, 28 + jl);
    }
    return out;
}

// Filament's camera from cfg.camera (ssaolab's metrics.json camera, in the file's coordinates).
function makeCamera() {
    const c = cfg.camera;
    camera.setProjectionFov(c.fov_y_deg, cfg.width / cfg.height, c.near, c.far === 'inf' ? 1e7 : c.far, Filament.Camera$Fov.VERTICAL);
    camera.lookAt(c.eye, c.target, c.up);
}

const tick = () => new Promise((r) => setTimeout(r, 0));

// One frame drawn, in ms (beginFrame to a 1-pixel read). Filament skips a frame while an earlier
// frame's GPU fence is unsignalled, and WebGL updates a fence only between tasks: each frame waits a
// task, and a skipped one is tried again (not timed). In Chromium a fence now and then never
// signals and every later frame would be skipped: past 20 skips the renderer (and with it its
// frame skipper's fences) is made anew.
let renewed = 0;
async function frame() {
    const px = new Uint8Array(4);
    for (let tries = 0; tries < 100; ++tries) {
        if (tries > 0 && tries % 20 === 0) {
            engine.destroyRenderer(renderer);
            renderer = engine.createRenderer();
            renderer.setClearOptions({ clearColor: [1, 1, 1, 1], clear: true });
            ++renewed;
        }
        const t0 = performance.now();
        if (renderer.beginFrame(swapChain)) {
            renderer.renderView(view);
            renderer.endFrame();
            engine.execute();
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
            const ms = performance.now() - t0;
            await tick();
            return ms;
        }
        await tick();
    }
    throw new Error(`Filament skipped 100 frames in a row (its renderer made anew ${renewed} times)`);
}

async function frameTimes(frames) { // harness.js framesDone: when they stop
    const all = [];
    while (!framesDone(all, frames))
        all.push(await frame());
    return timedFrames(all);
}

async function readFrame() {
    await frame();
    await frame();
    const rgba = new Uint8Array(cfg.width * cfg.height * 4);
    gl.readPixels(0, 0, cfg.width, cfg.height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    return rgba;
}

// The options at the defaults with every length from R ("make peers"): the radius R, the bias and
// the blur's edge threshold at the defaults' ratios to the radius (0.0005 : 0.3, 0.05 : 0.3).
function makePeersOptions() {
    return { ...defaults, radius: cfg.radius, bias: cfg.radius * (0.0005 / 0.3),
             bilateralThreshold: cfg.radius * (0.05 / 0.3) };
}

// What setAmbientOcclusionOptions takes: the enum rows as Filament's enum members.
function filamentOptions(o, enabled) {
    const out = { ...o, enabled };
    for (const k of ['quality', 'lowPassFilter', 'upsampling']) {
        const level = qualityLevels.find((q) => q.value === Math.round(o[k]));
        if (!level) throw new Error(`${k} ${o[k]} is not a View$QualityLevel (0 LOW .. 3 ULTRA)`);
        out[k] = level;
    }
    return out;
}

let engineView = -1, offFrame, plainMs;

window.setEngineView = (index, cam, radius) => {
    if (index === engineView) return;
    cfg.camera = cam;
    cfg.radius = radius;
    makeCamera();
    engineView = index;
    offFrame = undefined;
    plainMs = undefined;
};

// job: { peer, params, values, scale, frames }, as peers.js's runEngine takes it.
window.runEngine = async (job) => {
    if (job.peer !== 'filament-ssao') throw new Error(`filament.html runs filament-ssao, not '${job.peer}'`);
    const base = makePeersOptions(), o = { ...base };
    for (const p of job.params) {
        const scale = job.scale?.[p.name];
        o[p.name] = job.values[p.name] ?? (scale !== undefined ? base[p.name] * scale : base[p.name]);
    }
    if (offFrame === undefined) { // the frame without the AO, once a view
        view.setAmbientOcclusionOptions(filamentOptions(o, false));
        offFrame = await readFrame();
        if (job.frames > 0) plainMs = median(await frameTimes(job.frames));
    } else if (job.frames > 0 && plainMs === undefined) {
        view.setAmbientOcclusionOptions(filamentOptions(o, false));
        plainMs = median(await frameTimes(job.frames));
    }
    view.setAmbientOcclusionOptions(filamentOptions(o, true));
    const out = { values: readParams(o, job.params) };
    if (job.frames > 0) Object.assign(out, timedJob(await frameTimes(job.frames), plainMs));
    const on = await readFrame(), n = cfg.width * cfg.height, ao = new Uint8Array(n);
    for (let i = 0; i < n; ++i) {
        const lit = offFrame[4 * i];
        ao[i] = lit >= 8 ? Math.min(255, Math.round((255 * on[4 * i]) / lit)) : 255;
    }
    out.ao = aoBase64(ao);
    return out;
};

window.peersReady = true;
