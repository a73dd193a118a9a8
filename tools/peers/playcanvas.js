// PlayCanvas's CameraFrame SSAO (its pass follows Filament's scalable ambient obscurance) on one glTF scene
// (run_engine.mjs drives this page through Chromium), with the same window API as peers.js:
// setupPeers, setEngineView, runEngine. The AO alone: the frame's own debug output 'ssao' (the
// compose pass shows the SSAO texture), tone mapping linear; the compose pass gamma-encodes it for
// the canvas, and readAo decodes it back to linear AO. PlayCanvas is right-handed like glTF: ssaolab's camera, in the file's coordinates, is
// used as it is. Time: the median frame with the CameraFrame minus the median frame without it,
// each ended by a 1-pixel readPixels, as peers.js times its passes.
import * as pc from '/playcanvas/build/playcanvas.mjs';
import { frameTimes as harnessFrameTimes, gammaDecodeTable, median, pageCanvas, timedJob, readAo as harnessReadAo, readParams, seededRandom, writePath } from './harness.js';

let app, device, cameraEntity, cfg;

window.setupPeers = async (config) => {
    cfg = config;
    const canvas = pageCanvas(cfg.width, cfg.height);
    device = await pc.createGraphicsDevice(canvas, { deviceTypes: ['webgl2'], antialias: false, alpha: false,
                                                      preserveDrawingBuffer: true });
    device.maxPixelRatio = 1;
    const opts = new pc.AppOptions();
    opts.graphicsDevice = device;
    opts.componentSystems = [pc.RenderComponentSystem, pc.CameraComponentSystem];
    opts.resourceHandlers = [pc.TextureHandler, pc.ContainerHandler];
    app = new pc.AppBase(canvas);
    app.init(opts);
    app.setCanvasFillMode(pc.FILLMODE_NONE, cfg.width, cfg.height);
    app.setCanvasResolution(pc.RESOLUTION_FIXED, cfg.width, cfg.height);
    const asset = await new Promise((resolve, reject) =>
        app.assets.loadFromUrl(cfg.scene, 'container', (err, a) => (err ? reject(new Error(String(err))) : resolve(a))));
    const root = asset.resource.instantiateRenderEntity();
    app.root.addChild(root);
    // ssaolab skips BLEND and transmissive surfaces (README, "Transparent surfaces") and draws
    // every face: the same here.
    let meshes = 0, hidden = 0;
    for (const r of root.findComponents('render')) {
        for (const mi of r.meshInstances) {
            ++meshes;
            const m = mi.material;
            if (m.blendType !== pc.BLEND_NONE || (m.refraction ?? 0) > 0) { mi.visible = false; ++hidden; continue; }
            m.cull = pc.CULLFACE_NONE;
            m.update();
        }
    }
    makeCamera();
    return { renderer: device.gl.getParameter(device.gl.RENDERER), three: `playcanvas ${pc.version}`, meshes, hidden, flipped: 0 };
};

// PlayCanvas's camera from cfg.camera (ssaolab's metrics.json camera, in the file's coordinates).
function makeCamera() {
    const c = cfg.camera;
    if (!cameraEntity) {
        cameraEntity = new pc.Entity('ssaolab-camera');
        cameraEntity.addComponent('camera', { clearColor: new pc.Color(1, 1, 1, 1) });
        app.root.addChild(cameraEntity);
    }
    const cam = cameraEntity.camera;
    cam.fov = c.fov_y_deg; // vertical (horizontalFov false)
    cam.horizontalFov = false;
    cam.nearClip = c.near;
    cam.farClip = c.far === 'inf' ? 1e7 : c.far;
    cam.toneMapping = pc.TONEMAP_LINEAR;
    cameraEntity.setPosition(c.eye[0], c.eye[1], c.eye[2]);
    cameraEntity.lookAt(new pc.Vec3(c.target[0], c.target[1], c.target[2]), new pc.Vec3(c.up[0], c.up[1], c.up[2]));
}

// The CameraFrame with SSAO on (its default type is none: a user turns it on, every other setting
// the package's) and every length set from R ("make peers"): the radius R.
function makeFrame(ctor) {
    Math.random = seededRandom(0x55a0);
    const f = new pc.CameraFrame(app, cameraEntity.camera);
    f.rendering.toneMapping = pc.TONEMAP_LINEAR;
    f.ssao.type = pc.SSAOTYPE_COMBINE;
    f.ssao.radius = cfg.radius;
    if (ctor.scale !== undefined) f.ssao.scale = ctor.scale;
    f.debug = 'ssao';
    f.update();
    return f;
}

const frameTimes = (frames) => harnessFrameTimes(device.gl, () => app.render(), frames);
// The compose pass gamma-encodes whatever it writes to a non-sRGB target, the canvas included, its
// 'ssao' debug output too: pow(ao, 1 / 2.2) (gamma.js's gammaCorrectOutput). Decoded back to linear.
const linear = gammaDecodeTable(2.2);
const readAo = () => harnessReadAo(device.gl, cfg.width, cfg.height, linear);

let engineView = -1, plainMs, frame = null, frameKey = null;

function dropFrame() {
    if (frame) frame.destroy();
    frame = null;
    frameKey = null;
}

window.setEngineView = (index, cam, radius) => {
    if (index === engineView) return;
    dropFrame();
    plainMs = undefined;
    cfg.camera = cam;
    cfg.radius = radius;
    makeCamera();
    engineView = index;
};

// job: { peer, params, values, scale, frames }, as peers.js's runEngine takes it.
window.runEngine = (job) => {
    if (job.peer !== 'playcanvas-ssao') throw new Error(`playcanvas.html runs playcanvas-ssao, not '${job.peer}'`);
    const ctor = {};
    for (const p of job.params)
        if (p.write.constructor_arg !== undefined && job.values[p.name] !== undefined) ctor[p.name] = job.values[p.name];
    if (job.frames > 0 && plainMs === undefined) { // the frame without the CameraFrame, once a view
        dropFrame();
        plainMs = median(frameTimes(job.frames));
    }
    const key = JSON.stringify(ctor);
    if (frameKey !== key) {
        dropFrame();
        frame = makeFrame(ctor);
        frame.ssaolabBase = readParams(frame, job.params);
        frameKey = key;
    }
    for (const p of job.params) {
        if (p.write.constructor_arg !== undefined) continue;
        const scale = job.scale?.[p.name];
        const v = job.values[p.name] ?? (scale !== undefined ? frame.ssaolabBase[p.name] * scale : frame.ssaolabBase[p.name]);
        writePath(frame, p.write.path, p.type === 'boolean' ? Boolean(v) : v);
    }
    frame.update();
    const out = { values: readParams(frame, job.params) };
    if (job.frames > 0) {
        Object.assign(out, timedJob(frameTimes(job.frames), plainMs));
    } else {
        app.render();
        app.render();
    }
    out.ao = readAo();
    return out;
};

window.peersReady = true;
