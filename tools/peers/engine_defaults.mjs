// Each engine's own defaults, from the installed package itself: the pass is constructed in Node
// (constructing needs no GL context; Babylon.js's through its NullEngine, PlayCanvas's its
// NullGraphicsDevice; Filament's options are the defaults its JavaScript binding fills in, read from
// its wasm module without an engine) as its table's "class" says, and every parameter is read
// where its table's "read" path says. Prints {engine: {version, defaults: {name: value}}} as JSON;
// tests/cli/test_cli_engines.cpp compares it with the tables.
//
// node engine_defaults.mjs --modules DIR --tables a.json,b.json
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import vm from 'node:vm';
import { pathToFileURL } from 'node:url';
import { parseArgs } from './session.mjs';

const args = parseArgs(process.argv, ['modules', 'tables'], 'engine_defaults');
const modules = path.resolve(args.modules);
const load = (rel) => import(pathToFileURL(path.join(modules, rel)).href);
const THREE = await load('three/build/three.module.js');
async function threePass(table) {
    const Pass = (await load(table.class.module))[table.class.export];
    const given = { scene: new THREE.Scene(), camera: new THREE.PerspectiveCamera(), width: 64, height: 64,
                    resolution: new THREE.Vector2(64, 64) };
    return new Pass(...table.class.constructor.map((a) => given[a]));
}

// Babylon.js's pipelines need a scene and a camera: its NullEngine (no GL) builds them in Node, and
// the constructor's ratio is the documented examples' (SSAO2's blurRatio, SSAO's combineRatio; the rows read from constructor arguments,
// which a pipeline does not keep, are read from `ssaolabCtor` as the page records them).
function babylonPipeline(table) {
    const BABYLON = createRequire(import.meta.url)(path.join(modules, 'babylonjs'));
    BABYLON.Logger.LogLevels = BABYLON.Logger.NoneLogLevel; // its log goes to stdout, which carries the JSON
    const engine = new BABYLON.NullEngine();
    const scene = new BABYLON.Scene(engine);
    const camera = new BABYLON.TargetCamera('c', new BABYLON.Vector3(0, 0, -5), scene);
    const ratio = { ssaoRatio: 0.5, blurRatio: 1, combineRatio: 1 };
    const given = { name: 'ssao', scene, ratio, cameras: [camera] };
    const pass = new BABYLON[table.class.export](...table.class.constructor.map((a) => given[a]));
    pass.ssaolabCtor = { ssaoRatio: ratio.ssaoRatio };
    return pass;
}

// PlayCanvas's CameraFrame needs an application and a camera component: its NullGraphicsDevice
// (no GL) builds them in Node.
async function playcanvasFrame(table) {
    const pc = await load('playcanvas/build/playcanvas.mjs');
    const opts = new pc.AppOptions();
    opts.graphicsDevice = new pc.NullGraphicsDevice({});
    opts.componentSystems = [pc.CameraComponentSystem];
    const app = new pc.AppBase({});
    app.init(opts);
    const camera = new pc.Entity('c');
    camera.addComponent('camera');
    app.root.addChild(camera);
    const given = { app, camera: camera.camera };
    return new pc[table.class.export](...table.class.constructor.map((a) => given[a]));
}

// Filament's web build is an Emscripten module that replaces its global on init: it runs in a
// context of its own, where that global is visible once ready. Enum members read as their numbers.
async function filamentOptions() {
    const file = path.join(modules, 'filament', 'filament.js');
    const ctx = { require: createRequire(file), __dirname: path.dirname(file), __filename: file, process, console,
                  WebAssembly, TextDecoder, setTimeout, clearTimeout, performance, URL, module: { exports: {} } };
    ctx.exports = ctx.module.exports;
    vm.createContext(ctx);
    vm.runInContext(fs.readFileSync(file, 'utf8'), ctx, { filename: file });
    await new Promise((resolve) => ctx.Filament.init([], resolve));
    const o = ctx.Filament.View.prototype.setAmbientOcclusionOptionsDefaults({});
    return Object.fromEntries(Object.entries(o).map(([k, v]) => [k, typeof v?.value === 'number' ? v.value : v]));
}

const out = {};
for (const file of args.tables.split(',')) {
    const table = JSON.parse(fs.readFileSync(file, 'utf8'));
    const pass = table.class.module === 'babylonjs' ? babylonPipeline(table)
               : table.class.module === 'playcanvas' ? await playcanvasFrame(table)
               : table.class.module === 'filament' ? await filamentOptions() : await threePass(table);
    const defaults = {};
    for (const p of table.parameters) {
        let v = pass;
        for (const k of p.read.split('.')) v = v?.[k];
        defaults[p.name] = p.type === 'boolean' ? Boolean(v) : v === undefined ? null : Number(v);
    }
    const pkg = JSON.parse(fs.readFileSync(path.join(modules, table.package, 'package.json'), 'utf8'));
    out[table.engine] = { version: pkg.version, defaults };
}
console.log(JSON.stringify(out));
process.exit(0);
