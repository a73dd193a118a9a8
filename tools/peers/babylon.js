// Babylon.js's SSAO2RenderingPipeline and its older SSAORenderingPipeline on one glTF scene
// (run_engine.mjs drives this page through Chromium), with the same window API as peers.js:
// setupPeers, setEngineView, runEngine.
// The AO alone: the pipeline's last stage multiplies the scene's colour by the AO, so every surface
// is drawn in one unlit white material (emissive 1, lighting off, both sides) on a white clear
// colour, with image processing (tone mapping, gamma) off: the canvas holds 1 x AO, linear.
// The scene keeps the glTF's right-handed coordinates (scene.useRightHandedSystem), so ssaolab's
// camera, in the file's coordinates, is used as it is. Time: the median frame with the pipeline
// minus the median frame without, each ended by a 1-pixel readPixels, as peers.js times its passes.
/* global BABYLON */
import { frameTimes as harnessFrameTimes, median, pageCanvas, timedJob, readAo as harnessReadAo, readParams as readRows, seededRandom, writePath } from './harness.js';

let engine, scene, camera, cfg, canvas;

window.setupPeers = async (config) => {
    cfg = config;
    canvas = pageCanvas(cfg.width, cfg.height);
    engine = new BABYLON.Engine(canvas, false, { preserveDrawingBuffer: true, stencil: true, antialias: false }, false);
    engine.setHardwareScalingLevel(1);
    // Shaders compile as they are asked for: with parallel compilation Babylon skips a mesh or a
    // post-process whose effect is not ready yet, and a frame would be timed and read without it.
    engine.getCaps().parallelShaderCompile = undefined;
    scene = new BABYLON.Scene(engine);
    scene.useRightHandedSystem = true;
    scene.clearColor = new BABYLON.Color4(1, 1, 1, 1);
    scene.imageProcessingConfiguration.isEnabled = false;
    await BABYLON.AppendSceneAsync(cfg.scene, scene);
    // ssaolab skips BLEND and transmissive surfaces (README, "Transparent surfaces"); every other
    // surface is drawn white, unlit, both sides.
    const white = new BABYLON.StandardMaterial('ssaolab-white', scene);
    white.disableLighting = true;
    white.emissiveColor = new BABYLON.Color3(1, 1, 1);
    white.diffuseColor = new BABYLON.Color3(0, 0, 0);
    white.specularColor = new BABYLON.Color3(0, 0, 0);
    white.backFaceCulling = false;
    let meshes = 0, hidden = 0;
    for (const m of scene.meshes) {
        if (!m.getTotalVertices || m.getTotalVertices() === 0) continue;
        ++meshes;
        const mat = m.material;
        const transmissive = mat && mat.subSurface && mat.subSurface.isRefractionEnabled;
        if (mat && ((mat.needAlphaBlending && mat.needAlphaBlending()) || transmissive)) {
            m.isVisible = false;
            ++hidden;
            continue;
        }
        m.material = white;
        m.alwaysSelectAsActiveMesh = true; // no culling against the camera's frustum: ssaolab draws all
    }
    for (const l of scene.lights.slice()) l.dispose();
    makeCamera();
    await scene.whenReadyAsync();
    const gl = engine._gl;
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    return { renderer: info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
             three: `babylon.js ${BABYLON.Engine.Version}`, meshes, hidden, flipped: 0 };
};

// Babylon's camera from cfg.camera (ssaolab's metrics.json camera, in the file's coordinates), made
// once and moved for each view: the pipelines attached to it stay, with their compiled shaders.
function makeCamera() {
    const c = cfg.camera, v = (a) => new BABYLON.Vector3(a[0], a[1], a[2]);
    if (!camera) camera = new BABYLON.TargetCamera('ssaolab-camera', v(c.eye), scene);
    camera.position = v(c.eye);
    camera.upVector = v(c.up);
    camera.setTarget(v(c.target));
    camera.fovMode = BABYLON.Camera.FOVMODE_VERTICAL_FIXED;
    camera.fov = c.fov_y_deg * Math.PI / 180;
    camera.minZ = c.near;
    camera.maxZ = c.far === 'inf' ? 1e7 : c.far;
    scene.activeCamera = camera;
}

const far = () => (cfg.camera.far === 'inf' ? 1e7 : cfg.camera.far);

// SSAO2RenderingPipeline's lengths from R ("make peers"): the radius R, the self-occlusion epsilon
// at the defaults' ratio to it (0.02 : 2), and the depth fade (from 0.75 maxZ to maxZ; the default
// fades from 75 to 100 units) starting at the camera's far plane, so nothing inside the scene fades.
const ssao2Lengths = () => ({ radius: cfg.radius, epsilon: 0.01 * cfg.radius, maxZ: far() / 0.75 });

function makeSsao2(ratio) {
    const p = new BABYLON.SSAO2RenderingPipeline(`ssao${++pipelines}`, scene, ratio, [camera]);
    Object.assign(p, ssao2Lengths());
    // The radius is clamped to minZAspect x depth / near "to save performance on close geometry":
    // ssaolab's near plane is fitted to the scene, far larger than an application's, so the clamp
    // would bite where it would not in the application: off.
    p.minZAspect = 1e6;
    return p;
}

// SSAORenderingPipeline reads the depth renderer's d = (z - near) / (far - near) and reaches radius
// / d of the screen (UV) at view depth z. Its radius from R: R projected at the camera's target
// (depth zt), R / (2 tan(fov_y / 2) zt) of the screen, so radius = that x (zt - near) / (far -
// near). Its occluding depth difference ends at area = R / (far - near), and starts at fallOff, at
// the defaults' ratio to area (1e-6 : 0.0075).
function ssaoLengths() {
    const c = cfg.camera, span = far() - c.near;
    const zt = Math.max(Math.hypot(...c.target.map((t, i) => t - c.eye[i])), c.near * (1 + 1e-6));
    const area = cfg.radius / span;
    return { radius: cfg.radius / (2 * Math.tan(c.fov_y_deg * Math.PI / 360) * zt) * (zt - c.near) / span,
             area, fallOff: area * (1e-6 / 0.0075) };
}

function makeSsao(ratio) {
    const p = new BABYLON.SSAORenderingPipeline(`ssao${++pipelines}`, scene, ratio, [camera]);
    Object.assign(p, ssaoLengths());
    return p;
}

const PIPELINES = {
    'babylon-ssao2': (ctor) => makeSsao2({ ssaoRatio: ctor.ssaoRatio ?? 0.5, blurRatio: ctor.blurRatio ?? 1 }),
    'babylon-ssao': (ctor) => makeSsao({ ssaoRatio: ctor.ssaoRatio ?? 0.5, combineRatio: ctor.combineRatio ?? 1 }),
};
const LENGTHS = { 'babylon-ssao2': ssao2Lengths, 'babylon-ssao': ssaoLengths };

function makePipeline(peer, ctor) {
    Math.random = seededRandom(0x55a0); // its noise texture and sample sphere: one image per setting in every session
    const p = PIPELINES[peer](ctor);
    p.ssaolabCtor = { ssaoRatio: ctor.ssaoRatio ?? 0.5 };
    return p;
}
let pipelines = 0;

// The rows a pipeline keeps where their table reads them; the constructor's ratio as it was given.
function readParams(p, params) {
    const ctor = params.filter((r) => r.write.constructor_arg !== undefined);
    return { ...readRows(p, params.filter((r) => r.write.constructor_arg === undefined)),
             ...Object.fromEntries(ctor.map((r) => [r.name, Number(p.ssaolabCtor[r.name])])) };
}

const frameTimes = (frames) => harnessFrameTimes(engine._gl, () => scene.render(), frames);
const readAo = () => harnessReadAo(engine._gl, cfg.width, cfg.height);

let engineView = -1, plainMs, lastPeer;
const built = new Map(); // JSON of the peer and its constructor values -> { pipeline, peer, base }

// Every pipeline disposed, and the depth renderer SSAORenderingPipeline turned on with it: a frame
// without any pipeline draws the scene alone.
function disposeAll() {
    for (const e of built.values()) e.pipeline.dispose();
    built.clear();
    scene.disableDepthRenderer();
}

function detachAll() {
    for (const e of built.values()) scene.postProcessRenderPipelineManager.detachCamerasFromRenderPipeline(e.pipeline.name, camera);
}

// A new view moves the camera; every pipeline built stays (a shader Babylon compiled for one view
// serves the next), its baseline's lengths set from the new view's R and camera.
window.setEngineView = (index, cam, radius) => {
    if (index === engineView) return;
    plainMs = undefined;
    cfg.camera = cam;
    cfg.radius = radius;
    makeCamera();
    for (const e of built.values()) Object.assign(e.base, LENGTHS[e.peer]());
    engineView = index;
};

// Babylon loads a post-process's shaders asynchronously (a promise, even from the bundle): until
// every one is ready the pipeline is skipped and the frame shows no AO. Renders until they are (at
// most 30 s, then the job fails rather than read a frame without the AO).
async function ready() {
    const start = performance.now();
    while (!camera._postProcesses.filter(Boolean).every((pp) => pp.isReady())) {
        if (performance.now() - start > 30000) throw new Error('the SSAO2 pipeline\'s shaders were not ready after 30 s');
        scene.render();
        await new Promise((r) => setTimeout(r, 5));
    }
}

// job: { peer, params, values, scale, frames }, as peers.js's runEngine takes it.
window.runEngine = async (job) => {
    if (!Object.hasOwn(PIPELINES, job.peer)) throw new Error(`babylon.html runs ${Object.keys(PIPELINES).join(' and ')}, not '${job.peer}'`);
    if (job.peer !== lastPeer) disposeAll(); // one pipeline's depth renderer never runs beside the other
    lastPeer = job.peer;
    const ctor = {};
    for (const p of job.params)
        if (p.write.constructor_arg !== undefined && job.values[p.name] !== undefined) ctor[p.name] = job.values[p.name];
    if (job.frames > 0 && plainMs === undefined) { // the frame without any pipeline, once a view
        disposeAll();
        plainMs = median(frameTimes(job.frames));
    }
    const key = JSON.stringify([job.peer, ctor]);
    detachAll();
    let e = built.get(key);
    const fresh = !e;
    if (!e) {
        const pipeline = makePipeline(job.peer, ctor);
        e = { pipeline, peer: job.peer, base: readParams(pipeline, job.params) };
        built.set(key, e);
    } else {
        scene.postProcessRenderPipelineManager.attachCamerasToRenderPipeline(e.pipeline.name, camera);
    }
    Math.random = seededRandom(0x55a1); // the samples setter draws a new sample sphere: the same one in every session
    for (const p of job.params) {
        if (p.write.constructor_arg !== undefined) continue;
        const scale = job.scale?.[p.name];
        const v = job.values[p.name] ?? (scale !== undefined ? e.base[p.name] * scale : e.base[p.name]);
        writePath(e.pipeline, p.write.path, p.type === 'boolean' ? Boolean(v) : v);
    }
    await ready();
    const out = { values: readParams(e.pipeline, job.params) };
    if (job.frames > 0) {
        Object.assign(out, timedJob(frameTimes(job.frames), plainMs));
    } else {
        scene.render();
        if (fresh) scene.render(); // a new pipeline's first frame fills its textures; one it already ran draws once
    }
    out.ao = readAo();
    return out;
};

window.peersReady = true;
