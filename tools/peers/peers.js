// The web peers on one glTF scene (run_peers.mjs drives this page through Chromium).
// Each peer is three.js's EffectComposer with a RenderPass and the peer's pass writing its
// denoised AO (linear, 1 = open) to the canvas; its time is the median frame with the peer minus
// the median frame with the RenderPass alone, each frame ended by a 1-pixel readPixels (WebGL
// has no GPU timer on llvmpipe, and the read waits for the GPU process to finish the frame).
// Every length a peer takes is set from ssaolab's R (the radius itself; SSAOPass's depth range
// as a fraction of the clip range; GTAOPass's thickness at the 4:1 ratio of three.js's example,
// radius 0.25, thickness 1); every other setting is the peer's own default, as a user who adds
// the pass would get. postprocessing's SSAOEffect (pp-ssao) runs in that library's own composer
// instead, timed against its RenderPass alone (makePpPipeline).
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { SSAOPass } from 'three/addons/postprocessing/SSAOPass.js';
import { SAOPass } from 'three/addons/postprocessing/SAOPass.js';
import { GTAOPass } from 'three/addons/postprocessing/GTAOPass.js';
import { N8AOPass } from 'n8ao';
import { frameTimes as harnessFrameTimes, timedJob, median, readAo as harnessReadAo, readParams, seededRandom, writePath } from './harness.js';

// SSAOPass draws its kernel and noise, GTAOPass its denoiser's noise, from Math.random when built:
// seededRandom (harness.js) restarts it for every pass.
const readAo = () => harnessReadAo(renderer.getContext(), cfg.width, cfg.height);

let renderer, scene, camera, cfg;
let pp = null; // postprocessing, loaded in setupPeers (its effects run in its own EffectComposer)

// cfg: { scene (URL of the .gltf/.glb), width, height, radius (world units),
//        camera: ssaolab's metrics.json camera (eye, target, up, fov_y_deg, near, far) }
window.setupPeers = async (config) => {
    cfg = config;
    const canvas = document.createElement('canvas');
    document.body.appendChild(canvas);
    renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true,
                                         powerPreference: 'high-performance' });
    renderer.setPixelRatio(1);
    renderer.setSize(cfg.width, cfg.height, false);
    pp = await import('postprocessing').catch(() => null); // only pp-ssao needs it
    const gltf = await new GLTFLoader().loadAsync(cfg.scene);
    // The glTF's root is a Group; three.js applies a pass's override material (SSAOPass's and
    // postprocessing's normal pre-passes) only to a Scene, so the root goes inside one.
    scene = new THREE.Scene();
    scene.add(gltf.scene);
    scene.background = new THREE.Color(1, 1, 1);
    scene.add(new THREE.AmbientLight(0xffffff, 1.0));
    // ssaolab skips BLEND and transmissive surfaces by default (README, "Transparent surfaces"):
    // hide them here too so both sides occlude with the same geometry.
    // ssaolab draws every face without culling and shades the side it sees (gbuffer.frag: the
    // normal turned towards the viewer). three.js culls back faces and MeshNormalMaterial flips
    // a normal only on back faces of double-sided materials, so scenes whose normals disagree
    // with their winding (CornellBox's walls) would read as occluded from inside: turn each
    // vertex normal to the side its triangles' winding faces, and draw both sides.
    let hidden = 0, meshes = 0, flipped = 0;
    scene.traverse((o) => {
        if (!o.isMesh) return;
        ++meshes;
        const mats = Array.isArray(o.material) ? o.material : [o.material];
        if (mats.some((m) => m.transparent || (m.transmission ?? 0) > 0)) { o.visible = false; ++hidden; }
        for (const m of mats) m.side = THREE.DoubleSide;
        flipped += orientNormals(o.geometry);
    });
    makeCamera();
    const gl = renderer.getContext();
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    return { renderer: info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER),
             three: THREE.REVISION, meshes, hidden, flipped };
};

// three.js's camera from cfg.camera (ssaolab's metrics.json camera, in the file's coordinates).
function makeCamera() {
    const c = cfg.camera;
    const far = c.far === 'inf' ? 1e7 : c.far;
    camera = new THREE.PerspectiveCamera(c.fov_y_deg, cfg.width / cfg.height, c.near, far);
    camera.position.fromArray(c.eye);
    camera.up.fromArray(c.up);
    camera.lookAt(new THREE.Vector3().fromArray(c.target));
    camera.updateMatrixWorld(true);
}

// Turns each vertex normal towards the sum of its triangles' winding normals; returns how many
// were turned.
function orientNormals(g) {
    const pos = g.getAttribute('position'), nrm = g.getAttribute('normal');
    if (!pos || !nrm) return 0;
    const idx = g.index, n = idx ? idx.count : pos.count, acc = new Float32Array(pos.count * 3);
    const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
    for (let t = 0; t + 2 < n; t += 3) {
        const i = idx ? [idx.getX(t), idx.getX(t + 1), idx.getX(t + 2)] : [t, t + 1, t + 2];
        a.fromBufferAttribute(pos, i[0]); b.fromBufferAttribute(pos, i[1]); c.fromBufferAttribute(pos, i[2]);
        c.sub(b); b.sub(a); b.cross(c); // (b - a) x (c - b): the winding's normal, area-weighted
        for (const v of i) { acc[3 * v] += b.x; acc[3 * v + 1] += b.y; acc[3 * v + 2] += b.z; }
    }
    let turned = 0;
    for (let v = 0; v < pos.count; ++v) {
        const d = nrm.getX(v) * acc[3 * v] + nrm.getY(v) * acc[3 * v + 1] + nrm.getZ(v) * acc[3 * v + 2];
        if (d < 0) { nrm.setXYZ(v, -nrm.getX(v), -nrm.getY(v), -nrm.getZ(v)); ++turned; }
    }
    if (turned) nrm.needsUpdate = true;
    return turned;
}

// One peer's pass, at its defaults but for the radius. SAOPass's kernel radius is in pixels: R
// projected at the distance from the eye to the camera's target.
function makePass(name, opts) {
    Math.random = seededRandom(0x55a0);
    const p = makePeerPass(name, opts);
    if (p.normalMaterial) p.normalMaterial = viewFacingNormals();
    return p;
}

// The passes' normal pre-pass, as ssaolab's G-buffer writes normals: both sides drawn, the
// interpolated normal turned towards the viewer, packed (n + 1) / 2 as MeshNormalMaterial
// packs it. MeshNormalMaterial's own double-sided flip keys on gl_FrontFacing, which reads
// inverted through ANGLE into three.js's render targets here (every wall read as facing away:
// GTAOPass returned 0 on flat walls), so it is not used.
function viewFacingNormals() {
    return new THREE.ShaderMaterial({
        side: THREE.DoubleSide,
        blending: THREE.NoBlending,
        vertexShader: `
            varying vec3 vNormalView;
            varying vec3 vPosView;
            void main() {
                vec4 pv = modelViewMatrix * vec4(position, 1.0);
                vPosView = pv.xyz;
                vNormalView = normalMatrix * normal;
                gl_Position = projectionMatrix * pv;
            }`,
        fragmentShader: `
            varying vec3 vNormalView;
            varying vec3 vPosView;
            void main() {
                vec3 n = normalize(vNormalView);
                if (dot(n, -vPosView) < 0.0) n = -n;
                gl_FragColor = vec4(n * 0.5 + 0.5, 1.0);
            }`,
    });
}

function makePeerPass(name, opts) {
    const w = cfg.width, h = cfg.height, R = cfg.radius;
    if (name === 'ssao') {
        const p = new SSAOPass(scene, camera, w, h, opts.kernelSize); // its one constructor-only setting
        p.kernelRadius = R;
        const c = cfg.camera, far = c.far === 'inf' ? 1e7 : c.far;
        p.maxDistance = R / (far - c.near); // in linear depth over the clip range
        // Its self-occlusion bias, as a fraction of maxDistance: the defaults' ratio is 0.05
        // (0.005 : 0.1), which darkens flat walls (CornellBox: RMSE 0.39, bias -0.30); .ci/peers.sh
        // tries several ('ssao:min=0.5') and keeps the best.
        p.minDistance = (opts.min ?? 0.05) * p.maxDistance;
        p.output = SSAOPass.OUTPUT.Blur;
        return p;
    }
    if (name === 'sao') {
        const p = new SAOPass(scene, camera, new THREE.Vector2(w, h));
        const dist = new THREE.Vector3().fromArray(cfg.camera.eye).distanceTo(new THREE.Vector3().fromArray(cfg.camera.target));
        p.params.saoKernelRadius = R / (2 * dist * Math.tan(THREE.MathUtils.degToRad(cfg.camera.fov_y_deg) / 2)) * h;
        // SAO's falloff is 1 / (1 + (saoScale x distance / far)^2): half at R with saoScale = far / R.
        const far = cfg.camera.far === 'inf' ? 1e7 : cfg.camera.far;
        p.params.saoScale = far / R;
        p.params.output = SAOPass.OUTPUT.SAO;
        return p;
    }
    if (name === 'gtao') {
        const p = new GTAOPass(scene, camera, w, h);
        p.updateGtaoMaterial({ radius: R, thickness: 4 * R });
        p.output = GTAOPass.OUTPUT.Denoise;
        // Normals from depth (GTAOPass's own fallback): with its normal pre-pass it returned AO 0
        // on walls facing the camera, on llvmpipe and SwiftShader alike, with MeshNormalMaterial
        // or viewFacingNormals(); from depth the same walls read 0.99.
        for (const m of [p.gtaoMaterial, p.pdMaterial]) { m.defines.NORMAL_VECTOR_TYPE = 0; m.needsUpdate = true; }
        return p;
    }
    if (name === 'pp-ssao') return makePpSsao(opts.normalBuffer);
    if (name === 'n8ao') {
        const p = new N8AOPass(scene, camera, w, h);
        p.configuration.aoRadius = R;
        p.configuration.renderMode = 1;         // AO only: 1 - (1 - ao) x black = ao
        p.configuration.gammaCorrection = false; // linear AO, as ssaolab scores it
        return p;
    }
    throw new Error(`unknown peer '${name}'`);
}

// postprocessing's SSAOEffect, at its defaults but for its reach. Its radius is a fraction of the
// height, scaled with linear depth t by (1 - smoothstep(0, cutoff, t)) x (1 - minRadiusScale) +
// minRadiusScale: R projected at the camera's target distance, over that scale there. A sample
// counts while its depth differs by less than proximityThreshold + proximityFalloff (fractions of
// far - near): R, split 4:1 as the manual's demo (0.4 : 0.1). The world* setters are not used: they
// convert a depth difference as a distance from the camera, so a length below near sets 0.
function makePpSsao(normalBuffer) {
    const e = new pp.SSAOEffect(camera, normalBuffer), m = e.ssaoMaterial;
    const c = cfg.camera, far = c.far === 'inf' ? 1e7 : c.far, R = cfg.radius;
    m.proximityThreshold = 0.8 * R / (far - c.near);
    m.proximityFalloff = 0.2 * R / (far - c.near);
    const dist = new THREE.Vector3().fromArray(c.eye).distanceTo(new THREE.Vector3().fromArray(c.target));
    const t = THREE.MathUtils.smoothstep((dist - c.near) / (far - c.near), 0, m.distanceThreshold + m.distanceFalloff);
    const scale = (1 - t) * (1 - m.minRadiusScale) + m.minRadiusScale;
    m.radius = R / (2 * dist * Math.tan(THREE.MathUtils.degToRad(c.fov_y_deg) / 2)) / scale;
    e.luminanceInfluence = 0;                     // the AO alone, whatever the frame's colour
    e.blendMode.blendFunction = pp.BlendFunction.SRC; // 1 - occlusion, not multiplied onto the frame
    return e;
}

// postprocessing's composer: RenderPass, NormalPass (its normals drawn as viewFacingNormals()),
// EffectPass with the effect, writing linear AO to the canvas (its encodeOutput would convert to
// sRGB). The composer turns the renderer's autoClear off, which three.js's passes rely on: each
// call keeps the renderer's setting as it found it.
function ppComposer(passes) {
    const autoClear = renderer.autoClear;
    const c = new pp.EffectComposer(renderer);
    for (const p of passes) c.addPass(p);
    renderer.autoClear = autoClear;
    return {
        render() {
            const a = renderer.autoClear;
            renderer.autoClear = false;
            c.render();
            renderer.autoClear = a;
        },
        dispose() { c.dispose(); },
    };
}

function makePpPipeline(name, opts) {
    if (!pp) throw new Error(`${name}: the npm package postprocessing is not installed (make engine-modules)`);
    const normalPass = new pp.NormalPass(scene, camera);
    normalPass.renderPass.overrideMaterial = viewFacingNormals();
    const pass = makePass(name, { ...opts, normalBuffer: normalPass.texture });
    const effectPass = new pp.EffectPass(camera, pass);
    effectPass.fullscreenMaterial.encodeOutput = false;
    return { pass, composer: ppComposer([new pp.RenderPass(scene, camera), normalPass, effectPass]) };
}

const isPp = (name) => name.startsWith('pp-');

// The composer without the peer, for its time: the peer's own kind of composer and RenderPass.
function plainComposer(name) {
    if (isPp(name)) return ppComposer([new pp.RenderPass(scene, camera)]);
    const plain = newComposer();
    plain.addPass(new RenderPass(scene, camera));
    return plain;
}

const frameTimes = (draw, frames) => harnessFrameTimes(renderer.getContext(), draw, frames);

function timeFrames(draw, frames) {
    return median(frameTimes(draw, frames));
}

// Returns the median frame times (with the peer, and the RenderPass alone) and the AO read back
// from the canvas: one byte per pixel, rows bottom-up as GL reads them, base64.
window.runPeer = (name, opts, frames) => {
    if (isPp(name)) return runPpPeer(name, opts, frames);
    const plain = newComposer();
    plain.addPass(new RenderPass(scene, camera));
    const composer = newComposer();
    composer.addPass(new RenderPass(scene, camera));
    composer.addPass(makePass(name, opts));
    return timeAndRead(name, plain, composer, frames);
};

function runPpPeer(name, opts, frames) {
    const plain = plainComposer(name), { composer } = makePpPipeline(name, opts);
    return timeAndRead(name, plain, composer, frames);
}

// The frame with the pass minus the frame without, then the AO the last frame left on the canvas.
function timeAndRead(name, plain, composer, frames) {
    const plainMs = timeFrames(() => plain.render(), frames);
    const peerMs = timeFrames(() => composer.render(), frames);
    const ao = readAo();
    plain.dispose();
    composer.dispose();
    return { name, frame_ms: peerMs, plain_ms: plainMs, ao_ms: peerMs - plainMs, width: cfg.width, height: cfg.height, ao };
}

function newComposer() {
    const c = new EffectComposer(renderer);
    c.setPixelRatio(1);
    c.setSize(cfg.width, cfg.height);
    return c;
}

// ssaolab tune --engine (run_engine.mjs): one engine at many parameter sets over several views in
// one session. `params` are rows of the engine's table (tools/peers/engines/*.json): each is
// written as the table says (a property path, an update call, or a constructor argument) over the
// make-peers settings above, which stand for every row a job leaves out; the pass and its
// composer are kept per view and constructor values, so a value set costs no shader rebuild
// unless the engine's own setter rebuilds.
let engineView = -1;
const enginePlainMs = new Map(); // the composer's kind ('three', 'pp') -> its frame without a peer
const engines = new Map(); // JSON of the constructor values -> { composer, pass, base }

// The view every later job renders: ssaolab's metrics.json camera and R (scene units).
window.setEngineView = (index, cam, radius) => {
    if (index === engineView) return;
    for (const e of engines.values()) e.composer.dispose();
    engines.clear();
    enginePlainMs.clear();
    cfg.camera = cam;
    cfg.radius = radius;
    makeCamera();
    engineView = index;
};

// job: { peer, params, values: { name: value }, scale: { name: factor }, frames }. scale: the
// make-peers value times the factor (a tuned setting relative to the view's R). frames 0: two
// frames drawn (the first compiles), no timing; else the median frame times as runPeer measures
// them, and the fastest and slowest frame's AO ms (bench --engines).
window.runEngine = (job) => {
    const ctor = {};
    for (const p of job.params)
        if (p.write.constructor_arg !== undefined && job.values[p.name] !== undefined) ctor[p.name] = job.values[p.name];
    const key = JSON.stringify([job.peer, ctor]); // one session may run several engines (bench --engines)
    let e = engines.get(key);
    if (!e) {
        let pass, composer;
        if (isPp(job.peer)) {
            ({ pass, composer } = makePpPipeline(job.peer, ctor));
        } else {
            pass = makePass(job.peer, ctor);
            composer = newComposer();
            composer.addPass(new RenderPass(scene, camera));
            composer.addPass(pass);
        }
        e = { composer, pass, base: readParams(pass, job.params) };
        engines.set(key, e);
    }
    for (const p of job.params) {
        if (p.write.constructor_arg !== undefined) continue;
        const scale = job.scale?.[p.name];
        const v = job.values[p.name] ?? (scale !== undefined ? e.base[p.name] * scale : e.base[p.name]);
        if (p.write.call) e.pass[p.write.call]({ [p.write.key]: v });
        else writePath(e.pass, p.write.path, v);
    }
    const out = { values: readParams(e.pass, job.params) };
    if (job.frames > 0) {
        const kind = isPp(job.peer) ? 'pp' : 'three';
        if (!enginePlainMs.has(kind)) {
            const plain = plainComposer(job.peer);
            enginePlainMs.set(kind, timeFrames(() => plain.render(), job.frames));
            plain.dispose();
        }
        const plainMs = enginePlainMs.get(kind);
        Object.assign(out, timedJob(frameTimes(() => e.composer.render(), job.frames), plainMs));
    } else {
        e.composer.render();
        e.composer.render();
    }
    out.ao = readAo();
    return out;
};

window.peersReady = true;
